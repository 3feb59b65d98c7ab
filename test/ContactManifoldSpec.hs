{-# LANGUAGE FlexibleContexts #-}
-- | Contact manifolds in the plane ("Manifold.ContactManifold"): each pair
-- of shape kinds against cases worked by hand (points, normal, separation,
-- keys), the manifold of a pair against the manifold of the pair swapped,
-- and the native run against the staged JavaScript under node, bit for bit.
module ContactManifoldSpec (spec) where

import Control.Monad (unless, zipWithM_)
import Data.List (sortOn)
import qualified Data.Vector.Unboxed as V
import GHC.Float (castDoubleToWord64)
import Linear.V2 (V2 (..))
import Test.Hspec
import Test.QuickCheck (Gen, choose, vectorOf)
import Test.QuickCheck.Gen (unGen)
import Test.QuickCheck.Random (mkQCGen)

import Manifold.ContactManifold
import Manifold.Field (constant)
import Manifold.Stage.Imp

import NodeJS

-- Shapes as corner lists -----------------------------------------------------

-- | A shape in the plane: corners (counter-clockwise) and a radius.
data Shape2 = Shape2 [V2 Double] Double deriving Show

-- | Each edge's outward unit normal (edge k from corner k to the next).
normals :: [V2 Double] -> [V2 Double]
normals cs = zipWith outward cs (drop 1 (cycle cs))
  where
    outward (V2 ax ay) (V2 bx by) =
      let dx = bx - ax
          dy = by - ay
          l = sqrt (dx * dx + dy * dy)
      in V2 (dy / l) (negate dx / l)

circleAt :: V2 Double -> Double -> Shape2
circleAt c r = Shape2 [c] r

-- | An axis-aligned box of half-extents @(hx, hy)@ centred at @c@.
boxAt :: V2 Double -> Double -> Double -> Shape2
boxAt (V2 x y) hx hy = Shape2 [V2 (x - hx) (y - hy), V2 (x + hx) (y - hy), V2 (x + hx) (y + hy), V2 (x - hx) (y + hy)] 0

-- | A box of half-extents @(hx, hy)@ centred at @c@, turned by @t@
-- counter-clockwise (its corners from the lower left before turning).
turnedBoxAt :: V2 Double -> Double -> Double -> Double -> Shape2
turnedBoxAt (V2 x y) hx hy t =
  Shape2 [V2 (x + u * cos t - v * sin t) (y + u * sin t + v * cos t) | (u, v) <- [(-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)]] 0

capsule :: V2 Double -> V2 Double -> Double -> Shape2
capsule a b r = Shape2 [a, b] r

-- | A native hull of a shape.
hull :: Shape2 -> Hull Native
hull (Shape2 cs r) =
  let vs = V.fromList [ x | V2 x _ <- cs ]
      ws = V.fromList [ y | V2 _ y <- cs ]
      ns = normals cs
      nx = V.fromList [ x | V2 x _ <- ns ]
      ny = V.fromList [ y | V2 _ y <- ns ]
  in Hull (fromIntegral (length cs)) (\i -> pure (V2 (vs V.! i) (ws V.! i))) (\i -> pure (V2 (nx V.! i) (ny V.! i))) r

-- | The manifold natively, with the margin and tolerance given.
manifoldOf :: Double -> Shape2 -> Shape2 -> IO (ContactManifold Double)
manifoldOf margin a b = runNative (collideHulls margin tolerance (hull a) (hull b))

tolerance :: Double
tolerance = 5e-4

-- | The manifold's points: where, the separation, the key.
pointsOf :: ContactManifold Double -> [(V2 Double, Double, Double)]
pointsOf m = take (round (cmCount m)) [ (mpPoint p, mpSeparation p, mpKey p) | p <- [cmFirst m, cmSecond m] ]

near :: V2 Double -> V2 Double -> Bool
near = nearTo 1e-12

nearTo :: Double -> V2 Double -> V2 Double -> Bool
nearTo e (V2 a b) (V2 c d) = abs (a - c) < e && abs (b - d) < e

-- | Two polygons (or capsules) whose edges find them about equally far
-- apart, each along its own best edge: the separating axis test's tie.
nearTie :: Shape2 -> Shape2 -> Bool
nearTie a@(Shape2 ca _) b@(Shape2 cb _) = length ca > 1 && length cb > 1 && abs (edgeSeparation a b - edgeSeparation b a) < 4 * tolerance
  where
    edgeSeparation (Shape2 cs _) (Shape2 ds _) =
      maximum [ minimum [ dotV n (d - c) | d <- ds ] | (c, n) <- zip cs (normals cs) ]
    dotV (V2 x y) (V2 u v) = x * u + y * v

close :: Double -> Double -> Bool
close a b = abs (a - b) < 1e-12

-- | The manifold has these points (in any order) and normal.
shouldHave :: ContactManifold Double -> (V2 Double, [(V2 Double, Double)]) -> Expectation
shouldHave m (normal, expected) = do
  let got = sortOn (\(V2 x y, _, _) -> (x, y)) (pointsOf m)
      want = sortOn (\(V2 x y, _) -> (x, y)) expected
  unless (length got == length want && near (cmNormal m) normal
          && and (zipWith (\(p, s, _) (q, t) -> near p q && close s t) got want)) $
    expectationFailure ("expected normal " ++ show normal ++ ", points " ++ show expected ++ "; got " ++ show m)

spec :: Spec
spec = describe "Manifold.ContactManifold" $ do
  describe "circles" $ do
    it "two overlapping circles: one point midway between their surfaces, along the line of centres" $ do
      m <- manifoldOf 0.1 (circleAt (V2 0 0) 1) (circleAt (V2 1.5 0) 1)
      m `shouldHave` (V2 1 0, [(V2 0.75 0, -0.5)])
    it "within the margin they touch speculatively, beyond it not at all" $ do
      m <- manifoldOf 0.1 (circleAt (V2 0 0) 1) (circleAt (V2 0 2.05) 1)
      m `shouldHave` (V2 0 1, [(V2 0 1.025, 0.05)])
      far <- manifoldOf 0.1 (circleAt (V2 0 0) 1) (circleAt (V2 0 2.2) 1)
      cmCount far `shouldBe` 0

  describe "a circle and a polygon" $ do
    it "a circle on a box's face: the face's normal, the point between the face and the circle (either order)" $ do
      m <- manifoldOf 0.1 (boxAt (V2 0 0) 1 1) (circleAt (V2 0.3 1.4) 0.5)
      m `shouldHave` (V2 0 1, [(V2 0.3 0.95, -0.1)])
      m' <- manifoldOf 0.1 (circleAt (V2 0.3 1.4) 0.5) (boxAt (V2 0 0) 1 1)
      m' `shouldHave` (V2 0 (-1), [(V2 0.3 0.95, -0.1)])
    it "a circle beyond a box's corner: along the line from the corner to the centre" $ do
      m <- manifoldOf 0.1 (boxAt (V2 0 0) 1 1) (circleAt (V2 1.3 1.4) 0.45)
      m `shouldHave` (V2 0.6 0.8, [(V2 (1 + 0.6 * 0.025) (1 + 0.8 * 0.025), 0.05)])
    it "a circle whose centre is inside a box: pushed out through the nearest face" $ do
      m <- manifoldOf 0.1 (boxAt (V2 0 0) 1 1) (circleAt (V2 0.2 0.9) 0.3)
      m `shouldHave` (V2 0 1, [(V2 0.2 0.8, -0.4)])
    it "a circle on a capsule's side, and at its end" $ do
      side <- manifoldOf 0.1 (capsule (V2 (-1) 0) (V2 1 0) 0.25) (circleAt (V2 0.5 0.7) 0.5)
      side `shouldHave` (V2 0 1, [(V2 0.5 0.225, -0.05)])
      end <- manifoldOf 0.1 (capsule (V2 (-1) 0) (V2 1 0) 0.25) (circleAt (V2 1.6 0.8) 0.75)
      end `shouldHave` (V2 0.6 0.8, [(V2 (1 + 0.6 * 0.25) (0.8 * 0.25), 0)])

  describe "polygons and capsules" $ do
    it "a box resting on a box has two points, at the upper box's corners, along the lower box's face normal" $ do
      m <- manifoldOf 0.1 (boxAt (V2 0 0) 1 1) (boxAt (V2 0.2 1.4) 0.5 0.5)
      m `shouldHave` (V2 0 1, [(V2 (-0.3) 0.95, -0.1), (V2 0.7 0.95, -0.1)])
      length (filter (\(_, _, k) -> k >= 0 && k < fromIntegral keysPerManifold) (pointsOf m)) `shouldBe` 2
    it "a box overhanging the corner of the one below: clipped where the lower box ends" $ do
      m <- manifoldOf 0.1 (boxAt (V2 0 0) 1 1) (boxAt (V2 1.2 1.45) 0.5 0.5)
      m `shouldHave` (V2 0 1, [(V2 0.7 0.975, -0.05), (V2 1 0.975, -0.05)])
    it "the same pair the other way round: the same points, the normal reversed" $ do
      m <- manifoldOf 0.1 (boxAt (V2 1.2 1.45) 0.5 0.5) (boxAt (V2 0 0) 1 1)
      m `shouldHave` (V2 0 (-1), [(V2 0.7 0.975, -0.05), (V2 1 0.975, -0.05)])
    it "two boxes apart corner to corner: one point between the corners, along the line joining them" $ do
      m <- manifoldOf 0.2 (boxAt (V2 0 0) 1 1) (boxAt (V2 1.6 1.6) 0.5 0.5)
      let s = sqrt 0.02
      m `shouldHave` (V2 (1 / sqrt 2) (1 / sqrt 2), [(V2 1.05 1.05, s)])
    it "a capsule lying on a capsule: two points, clipped to the lower one's segment" $ do
      m <- manifoldOf 0.1 (capsule (V2 (-1) 0) (V2 1 0) 0.25) (capsule (V2 0 0.45) (V2 2 0.45) 0.25)
      m `shouldHave` (V2 0 1, [(V2 0 0.225, -0.05), (V2 1 0.225, -0.05)])
    it "two capsules end to end at an angle: one point between their nearest ends" $ do
      m <- manifoldOf 0.5 (capsule (V2 0 0) (V2 1 0) 0.1) (capsule (V2 1.3 0.4) (V2 2 1) 0.1)
      m `shouldHave` (V2 0.6 0.8, [(V2 1.15 0.2, 0.3)])
    it "a capsule standing on a box: one point under its lower end (its upper end is beyond the margin)" $ do
      m <- manifoldOf 0.1 (boxAt (V2 0 0) 1 1) (capsule (V2 0 1.2) (V2 0 2) 0.25)
      m `shouldHave` (V2 0 1, [(V2 0 0.975, -0.05)])
    it "a thin card (0.001 by 0.2) lying on a box: two points at its ends" $ do
      m <- manifoldOf 1e-4 (boxAt (V2 0 0) 1 1) (boxAt (V2 0 1.0004) 0.1 0.0005)
      m `shouldHave` (V2 0 1, [(V2 (-0.1) 0.99995, -1e-4), (V2 0.1 0.99995, -1e-4)])
    it "keys follow the features: moved a little, a box on a box keeps its points' keys" $ do
      a <- manifoldOf 0.1 (boxAt (V2 0 0) 1 1) (boxAt (V2 0.2 1.4) 0.5 0.5)
      b <- manifoldOf 0.1 (boxAt (V2 0 0) 1 1) (boxAt (V2 0.25 1.41) 0.5 0.5)
      map (\(_, _, k) -> k) (pointsOf a) `shouldBe` map (\(_, _, k) -> k) (pointsOf b)
    it "keys name the corner a point is at, whichever hull gives the reference edge: a box level on a slab and tilted a little (the slab's face the reference) keeps its points' keys" $ do
      let keys m = sortOn id [k | (_, _, k) <- pointsOf m]
      level <- manifoldOf 0.1 (turnedBoxAt (V2 0.2 1.49) 0.5 0.5 0) (boxAt (V2 0 0) 1 1)
      tilted <- manifoldOf 0.1 (turnedBoxAt (V2 0.2 1.5) 0.5 0.5 0.02) (boxAt (V2 0 0) 1 1)
      keys level `shouldBe` [0, 1]
      -- (the slab's face gives the normal: its reference edge)
      cmNormal tilted `shouldSatisfy` near (V2 0 (-1))
      keys tilted `shouldBe` [0, 1]
      -- the slab first: the box's corners are the second shape's
      swapped <- manifoldOf 0.1 (boxAt (V2 0 0) 1 1) (turnedBoxAt (V2 0.2 1.5) 0.5 0.5 0.02)
      keys swapped `shouldBe` [fromIntegral maxHullCorners, fromIntegral maxHullCorners + 1]
      -- a circle: its centre, the one corner
      circle <- manifoldOf 0.1 (boxAt (V2 0 0) 1 1) (circleAt (V2 0.3 1.4) 0.5)
      keys circle `shouldBe` [fromIntegral maxHullCorners]

  it "a pair and the pair swapped give the same separations, the normals opposite, but where the two hulls' edges find them equally far apart (300 seeded pairs of every kind)" $ do
    let cases = unGen (vectorOf 300 genPair) (mkQCGen 11) 30
    compared <- concat <$> mapM (\(a, b) -> do
      m <- manifoldOf 0.05 a b
      m' <- manifoldOf 0.05 b a
      let seps = sortOn id . map (\(_, s, _) -> s) . pointsOf
          agree = cmCount m == cmCount m' && (cmCount m == 0 || (nearTo 1e-9 (cmNormal m) (negate <$> cmNormal m')
                    && and (zipWith (\x y -> abs (x - y) < 1e-9) (seps m) (seps m'))))
      -- (a near tie: either hull's edge is a fair reference, and the two
      -- give different points)
      if agree then pure [True] else if nearTie a b then pure [] else expectationFailure
        ("swapped differ: " ++ show (a, b) ++ "\n" ++ show m ++ "\n" ++ show m') >> pure []) cases
    length compared `shouldSatisfy` (> 280)

  it "runs natively and as the staged JavaScript bit for bit (300 seeded pairs)" $ do
    let pairs = unGen (vectorOf 300 genPair) (mkQCGen 12) 30
        flat (Shape2 cs r) = let ns = normals cs; pad xs = take maxHullCorners (xs ++ repeat (V2 0 0))
                             in [fromIntegral (length cs), r] ++ concat [[x, y] | V2 x y <- pad cs] ++ concat [[x, y] | V2 x y <- pad ns]
        stride = 2 + 4 * maxHullCorners
        input = concat [ flat a ++ flat b | (a, b) <- pairs ]
        outStride = 11
        program :: Imp m => Array m -> Array m -> Array m -> m ()
        program meta hulls out = do
          n <- toIndex <$> readArray meta 0
          forEach n $ \k -> do
            let at side = toIndex (toScalar k * fromIntegral (2 * stride)) + side * fromIntegral stride
                shape side = do
                  count <- readArray hulls (at side)
                  radius <- readArray hulls (at side + 1)
                  let corner i = V2 <$> readArray hulls (at side + 2 + 2 * i) <*> readArray hulls (at side + 3 + 2 * i)
                      normal i = V2 <$> readArray hulls (at side + 2 + 2 * fromIntegral maxHullCorners + 2 * i)
                                    <*> readArray hulls (at side + 3 + 2 * fromIntegral maxHullCorners + 2 * i)
                  pure (Hull count corner normal radius)
            a <- shape 0
            b <- shape 1
            m <- collideHulls 0.05 (constant tolerance) a b
            let V2 nx ny = cmNormal m
                point p = let V2 x y = mpPoint p in [x, y, mpSeparation p, mpKey p]
            zipWithM_ (\o v -> writeArray out (toIndex (toScalar k * fromIntegral outStride) + fromIntegral o) v) [0 :: Int ..]
              ([cmCount m, nx, ny] ++ point (cmFirst m) ++ point (cmSecond m))
        js = stageProcedure (Procedure "manifolds" ["meta", "hulls", "out"] []) (\as _ -> case as of
               [m, h, o] -> program m h o
               _ -> error "arity")
        inst = [[fromIntegral (length pairs)], input, replicate (outStride * length pairs) 0]
    arrays <- mapM (V.thaw . V.fromList) inst
    runNative (case arrays of [m, h, o] -> program m h o; _ -> error "arity")
    native <- V.toList <$> V.freeze (arrays !! 2)
    out <- runNodeJSON (js ++ "const a = [" ++ concatMap (\v -> jsDoubles v ++ ",") inst ++ "].map(v => Float64Array.from(v));\n"
                        ++ "manifolds(...a);\n__emit(a[2]);\n") :: IO [Bits]
    let differing = [ (k, x, unBits y) | (k, x, y) <- zip3 [0 :: Int ..] native out, castDoubleToWord64 x /= castDoubleToWord64 (unBits y) ]
    take 5 differing `shouldBe` []
    -- (most pairs touch: the test exercises every branch)
    length [ () | k <- [0 .. length pairs - 1], native !! (k * outStride) > 0 ] `shouldSatisfy` (> 100)

-- | Two shapes of any kinds (circle, capsule, box, a convex polygon of 3 to
-- 8 corners, some rounded) near each other.
genPair :: Gen (Shape2, Shape2)
genPair = (,) <$> genShape (V2 0 0) <*> (choose (0, 1.6) >>= \d -> choose (0, 2 * pi) >>= \t -> genShape (V2 (d * cos t) (d * sin t)))

genShape :: V2 Double -> Gen Shape2
genShape (V2 x y) = do
  kind <- choose (0 :: Int, 3)
  turn <- choose (0, 2 * pi)
  size <- choose (0.2, 0.8)
  let at (u, v) = V2 (x + u * cos turn - v * sin turn) (y + u * sin turn + v * cos turn)
  case kind of
    0 -> pure (Shape2 [V2 x y] size)
    1 -> do
      r <- choose (0.05, 0.3)
      pure (Shape2 [at (negate size, 0), at (size, 0)] r)
    2 -> do
      aspect <- choose (0.1, 1)
      r <- choose (0, 0.05)
      pure (Shape2 (map at [(negate size, negate (aspect * size)), (size, negate (aspect * size)), (size, aspect * size), (negate size, aspect * size)]) r)
    _ -> do
      n <- choose (3, maxHullCorners)
      -- corners at increasing angles, each at its own distance: convex when
      -- the distances are close enough; a regular polygon's, jittered
      jitter <- vectorOf n (choose (-0.1, 0.1))
      let corners = [ at (size * cos a, size * sin a) | (k, j) <- zip [0 .. n - 1] jitter, let a = 2 * pi * (fromIntegral k + 0.3 * j) / fromIntegral n ]
      pure (Shape2 corners 0)
