-- | The geodesic the page's tool draws ("Manifold.GeodesicPath"): the
-- generated JavaScript walks what the native program walks, bit for bit;
-- it is the surface's geodesic (closed forms on the sphere and the flat
-- spaces), winds through a quotient's fundamental domain, breaking where it
-- wraps, and stops at a boundary.
module GeodesicPathSpec (spec) where

import Control.Monad (forM)
import qualified Data.Vector.Unboxed as V
import qualified Data.Vector.Unboxed.Mutable as MV
import Linear.Metric (dot, norm)
import Linear.V3 (V3 (..), cross)
import Test.Hspec

import Manifold
import Manifold.GeodesicPath
import Manifold.Stage.Imp (runNative)
import NodeJS
import TestUtil (firstPlacement, scriptOf, vecDist)

-- | A walked path: its points and, for each, whether the curve breaks
-- before it.
walk :: Space -> V3 Double -> V3 Double -> Double -> Int -> IO [(V3 Double, Bool)]
walk sp p d len n = points <$> walkRaw sp p d len n

walkRaw :: Space -> V3 Double -> V3 Double -> Double -> Int -> IO [Double]
walkRaw sp p d len n = do
  path <- MV.replicate (pathLength n) 0
  runNative (walkGeodesic sp path p d len n)
  V.toList <$> V.freeze path

points :: [Double] -> [(V3 Double, Bool)]
points (count : rest) = take (round count) (go rest)
  where
    go (x : y : z : b : more) = (V3 x y z, b > 0) : go more
    go _ = []
points [] = []

-- | A start on each space: its default scene's first place, on the surface.
start :: Space -> V3 Double
start sp = projectToSurface (spaceField sp) (firstPlacement sp)

-- | A direction at the start that is not along the normal.
direction :: Space -> V3 Double
direction sp = let n = unitNormal Euclidean (spaceField sp) (start sp) in cross n (V3 0.3 0.5 0.8)

spec :: Spec
spec = describe "the page's geodesic tool (walkGeodesic)" $ do
  it "walks in the generated JavaScript exactly what it walks natively, on every space" $ do
    let len = 1.7
        n = 96
    native <- forM catalogue $ \sp -> walkRaw sp (start sp) (direction sp) len n
    let call sp = "(() => { const e = Manifold.spaces[" ++ show (spaceName sp) ++ "].engine;"
          ++ " const path = new Float64Array(" ++ show (pathLength n) ++ ");"
          ++ " e.geodesic(path, " ++ concatMap ((++ ", ") . jsDouble) (v3list (start sp) ++ v3list (direction sp))
          ++ jsDouble len ++ ", " ++ show n ++ "); return path; })()"
        script = concatMap scriptOf catalogue ++ "__emit([" ++ concatMap ((++ ",") . call) catalogue ++ "]);\n"
    js <- runNodeJSON script :: IO [[Bits]]
    [ spaceName sp | (sp, a, b) <- zip3 catalogue native js, map doubleBits a /= map (doubleBits . unBits) b ] `shouldBe` []
    -- and the walks are not trivial: every space walked some of its length
    [ spaceName sp | (sp, a) <- zip catalogue native, length (points a) < 10 ] `shouldBe` []

  it "is the geodesic 'geodesicPath' walks, where the space has no quotient and no boundary (within 1e-9)" $ do
    let spaces = [ sp | sp <- catalogue, spaceQuotient sp == NoQuotient, not (hasBoundary sp) ]
    errs <- forM spaces $ \sp -> do
      walked <- walk sp (start sp) (direction sp) 1.2 64
      let reference = map fst (geodesicPath (spaceMetric sp) (spaceField sp) 64 (start sp) (direction sp) 1.2)
      pure (spaceName sp, length walked, maximum (zipWith vecDist (map fst walked) reference))
    [ e | e@(_, count, err) <- errs, count /= 65 || err > 1e-9 ] `shouldBe` []
    length spaces `shouldSatisfy` (>= 4)

  it "closes on the sphere after 2π, on its great circle, and is on the surface all the way" $ do
    let p = normalize3 (V3 0.3 0.2 0.9)
        d = cross p (V3 0 1 0)
        plane = normalize3 (cross p d)
    walked <- walk sphere p d (2 * pi) 512
    length walked `shouldBe` 513
    -- the step is second order: the walk closes to 1.6e-4 in 512 steps, and
    -- to a quarter of that in twice as many
    let closure = vecDist (fst (last walked)) p
    closure `shouldSatisfy` (< 2e-4)
    finer <- walk sphere p d (2 * pi) 1024
    (closure / vecDist (fst (last finer)) p) `shouldSatisfy` (\r -> r > 3.8 && r < 4.2)
    maximum [ abs (norm q - 1) | (q, _) <- walked ] `shouldSatisfy` (< 1e-9)
    maximum [ abs (dot q plane) | (q, _) <- walked ] `shouldSatisfy` (< 1e-9)
    -- half way round it is at the antipode: the projective plane's walk is
    -- back at its start (p ~ −p) after π
    vecDist (fst (walked !! 256)) (negate <$> p) `shouldSatisfy` (< 1e-4)
    [ () | (_, True) <- walked ] `shouldBe` []

  it "winds through the flat torus's square, breaking at each wrap, as a straight line of the plane" $ do
    let p = V3 0.1 0 (-0.2)
        d = V3 1 0 2
        len = 9
        n = 900
    walked <- walk flatTorus p d len n
    length walked `shouldBe` n + 1
    -- each point is where the straight line is, brought back into [−1, 1)²
    let u = normalize3 d
        expected k = let V3 x y z = p + (len * fromIntegral k / fromIntegral n) `scale` u in V3 (wrapTo x) y (wrapTo z)
        wrapTo x = x - 2 * fromIntegral (floor ((x + 1) / 2) :: Int)
    maximum (zipWith (\k (q, _) -> vecDist q (expected k)) [0 :: Int ..] walked) `shouldSatisfy` (< 1e-9)
    -- the line crosses x = ±1 and z = ±1 about len·(1 + 2)/(2·√5) times
    let breaks = length [ () | (_, True) <- walked ]
    breaks `shouldSatisfy` (\b -> b >= 5 && b <= 7)

  it "goes on mirrored through the flat Klein bottle's flipped edge" $ do
    walked <- walk flatKlein (V3 0.5 0 0.3) (V3 1 0 0.5) 1.5 150
    let crossing = length (takeWhile (not . snd) walked)
        (V3 xb _ zb, _) = walked !! crossing
        (V3 xa _ za, _) = walked !! (crossing - 1)
    crossing `shouldSatisfy` (< 150)
    (xa > 0.9, xb < -0.9) `shouldBe` (True, True)
    -- before the edge z grows with x; after it, mirrored, it falls
    let (V3 _ _ zc, _) = walked !! (crossing + 20)
    (za > 0.5, zc < zb) `shouldBe` (True, True)

  it "stops at the disc's wall, its last point inside" $ do
    walked <- walk disc (V3 0 0 0) (V3 1 0 0) 3 300
    let (V3 x _ _, _) = last walked
    length walked `shouldSatisfy` (\c -> c > 90 && c < 102)
    x `shouldSatisfy` (\v -> v <= 1 && v > 0.98)
  where
    v3list (V3 x y z) = [x, y, z]
    normalize3 v = (1 / norm v) `scale` v
    scale k (V3 x y z) = V3 (k * x) (k * y) (k * z)
