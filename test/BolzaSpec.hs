-- | The Bolza surface's group (Manifold.Bolza): the octagon's area 4π
-- (Gauss–Bonnet for genus 2) integrated from the Poincaré map's Jacobian;
-- the side pairings as Lorentz matrices carrying each side onto its partner;
-- eight octagons at every corner (the surface is smooth there); the 48
-- touching images; the wrap back into the octagon. Then the catalogue's
-- @bolza@ space (its compiled step): curvature −1, a free body's speed and
-- its place in the octagon over 10,000 steps, a crossing against the closed
-- form of the geodesic mapped by the side pairing, and a collision across
-- a side.
module BolzaSpec (spec) where

import Control.Monad (forM, forM_, replicateM_, (>=>))
import Data.IORef
import Data.List (isPrefixOf)
import Linear.V3 (V3 (..))
import Linear.Vector ((*^))
import Test.Hspec

import Manifold
import Manifold.Bolza
import Manifold.Disc
import Manifold.Engine
import Manifold.World (layout)
import LorentzUtil

-- | The Lorentz defect relative to the matrix's size (its yy entry, cosh of how far it moves the vertex, squared).
relativeDefect :: [Double] -> Double
relativeDefect m = lorentzDefect m / (m !! 4) ^ (2 :: Int)

sameMatrix :: [Double] -> [Double] -> Bool
sameMatrix a b = maximum (zipWith (\x y -> abs (x - y)) a b) < 1e-9 * maximum (map abs a)

samePoint :: V3 Double -> V3 Double -> Bool
samePoint (V3 a b c) (V3 d e f) = abs (a - d) + abs (b - e) + abs (c - f) < 1e-9 * abs b

outside :: V3 Double -> Double
outside p = maximum [ sideExcess k p | k <- [0 .. 7] ]

-- | Gauss–Legendre nodes and weights on [−1, 1] (Newton on the Legendre polynomial).
gauss :: Int -> [(Double, Double)]
gauss n = [ node i | i <- [1 .. n] ]
  where
    node i =
      let x0 = cos (pi * (fromIntegral i - 0.25) / (fromIntegral n + 0.5))
          x = iterate newton x0 !! 30
          (_, dp) = legendre x
      in (x, 2 / ((1 - x * x) * dp * dp))
    newton x = let (p, dp) = legendre x in x - p / dp
    -- P_n(x) and its derivative, by the three-term recurrence
    legendre x =
      let go k p0 p1
            | k == n = (p1, p0)
            | otherwise = go (k + 1) p1 ((fromIntegral (2 * k + 1) * x * p1 - fromIntegral k * p0) / fromIntegral (k + 1))
          (pn, pn1) = go (1 :: Int) 1 x
      in (pn, fromIntegral n * (x * pn - pn1) / (x * x - 1))

-- | ∫ f over [a, b] by Gauss–Legendre.
integrate :: [(Double, Double)] -> Double -> Double -> (Double -> Double) -> Double
integrate rule a b f = 0.5 * (b - a) * sum [ w * f (0.5 * (a + b) + 0.5 * (b - a) * x) | (x, w) <- rule ]

spec :: Spec
spec = describe "Manifold.Bolza" $ do
  it "the octagon's area, integrated from the Poincaré map's Jacobian, is 4π (Gauss–Bonnet for genus 2; 1e-6)" $ do
    let rule = gauss 24
        h = 1e-5
        minus (V3 a b c) (V3 d e f) = V3 (a - d) (b - e) (c - f)
        -- the area element of the disc's map at (u, w): √det of the metric it pulls back
        element u w =
          let du = fromPoincare (u + h) w `minus` fromPoincare (u - h) w
              dw = fromPoincare u (w + h) `minus` fromPoincare u (w - h)
              g11 = minkowski du du / (4 * h * h)
              g22 = minkowski dw dw / (4 * h * h)
              g12 = minkowski du dw / (4 * h * h)
          in sqrt (g11 * g22 - g12 * g12)
        -- the octagon's edge at angle φ in the disc: a straight line in the Klein disc at tanh r from the centre
        edge phi =
          let k = floor ((phi + pi / 8) / (pi / 4)) :: Int
              kappa = tanh inradius / cos (phi - sideAngle k)
          in kappa / (1 + sqrt (1 - kappa * kappa))
        -- sixteen pieces between a side's middle and a corner, where the edge is smooth
        pieces = [ (fromIntegral j * pi / 8 - pi / 8, fromIntegral j * pi / 8) | j <- [0 .. 15 :: Int] ]
        area = sum [ integrate rule a b (\phi -> integrate rule 0 (edge phi) (\rho -> rho * element (rho * cos phi) (rho * sin phi))) | (a, b) <- pieces ]
    abs (area - 4 * pi) `shouldSatisfy` (< 1e-6)

  it "each side pairing is a Lorentz matrix carrying the opposite side onto its side; pairing k + 4 undoes pairing k" $
    forM_ [0 .. 7] $ \k -> do
      let m = pairing k
          back = pairing ((k + 4) `mod` 8)
          -- points along side k + 4: from its middle towards both corners
          opposite = [ applyBoost (translationTo (along (sideAngle (k + 4)) inradius)) (along (sideAngle (k + 4) + pi / 2) t) | t <- [-1.2, -0.5, 0, 0.7, 1.3] ]
          along a d = V3 (sinh d * cos a) (cosh d) (sinh d * sin a)
      relativeDefect m `shouldSatisfy` (< 1e-12)
      sameMatrix (composeBoosts back m) identity `shouldBe` True
      forM_ opposite $ \q -> do
        abs (sideExcess ((k + 4) `mod` 8) q) / minkowski q q `shouldSatisfy` (\e -> abs e < 1e-12)
        abs (sideExcess k (applyBoost m q)) `shouldSatisfy` (< 1e-9)

  it "eight octagons meet at every corner (the angles sum to 2π): seven of the touching images hold it" $
    forM_ corners $ \v -> do
      let holding = [ g | g <- touchingImages, any (samePoint (applyBoost (inverseBoost g) v)) corners ]
      length holding `shouldBe` 7

  it "the 48 touching images are distinct group elements, closed under inverses, the eight pairings among them" $ do
    length touchingImages `shouldBe` 48
    forM_ touchingImages $ \g -> do
      relativeDefect g `shouldSatisfy` (< 1e-9)
      length (filter (sameMatrix g) touchingImages) `shouldBe` 1
      any (sameMatrix (inverseBoost g)) touchingImages `shouldBe` True
    forM_ pairings $ \m -> any (sameMatrix m) touchingImages `shouldBe` True

  it "the wrap brings every point within 3.2 of the centre into the octagon, by a group element, and leaves inside points alone" $ do
    let points = [ V3 (sinh d * cos a) (cosh d) (sinh d * sin a) | d <- [0, 0.1 .. 3.2], a <- [0, 0.0137 .. 2 * pi] ]
    forM_ points $ \p -> do
      let (q, m) = wrapIntoOctagon p
      outside q `shouldSatisfy` (< 1e-9)
      samePoint (applyBoost m p) q `shouldBe` True
      relativeDefect m `shouldSatisfy` (< 1e-9)
      if outside p < 0 then m `shouldBe` identity else pure ()

  describe "the catalogue's bolza (compiled step)" $ do
    let sp = bolza
        polar r a = V3 (sinh r * cos a) (cosh r) (sinh r * sin a)
        -- the unit tangent at polar r a pointing away from the vertex
        outward r a = V3 (cosh r * cos a) (sinh r) (cosh r * sin a)
        worldOn = worldOnWith defaultParams
        worldOnWith params space' bodies = do
          w <- newWorld space' (layout (length bodies))
          setParams w params { pGravity = False }
          forM_ bodies (addBody w >=> either fail (const (pure ())))
          pure w
        worldWith = worldOn sp
        -- the same bodies on the hyperbolic plane (no gravity), of which the
        -- Bolza surface is the quotient
        onPlane = worldOn hyperbolicPlane
        free p v = BodyInit circle 0.1 1 False p v 0 0 sceneMaterial
        dt = pDt defaultParams

    it "has curvature −1 (1e-9) on its surface, the octagon's 48 touching images, no gravity, and refuses joints" $ do
      spaceMetric sp `shouldBe` Minkowski
      forM_ [(0, 0), (0.7, 0.3), (1.5, 2.2), (2.4, -1.4 :: Double)] $ \(r, a) ->
        abs (gaussianCurvatureIn Minkowski (spaceField sp) (polar r a) + 1) `shouldSatisfy` (< 1e-9)
      length (quotientImages (spaceQuotient sp)) `shouldBe` 48
      evalGravity sp (polar 1 0.5 :: V3 Double) `shouldBe` V3 0 0 0
      jointsRefused sp `shouldSatisfy` maybe False ("joints are not supported on bolza" `isPrefixOf`)
      jointsRefused hyperbolicPlane `shouldBe` Nothing

    it "keeps a free body's speed (1e-12) on the surface (1e-9) and in the octagon (1e-9) for 10,000 steps, through 40 and more crossings" $ do
      let speed = 0.8
      w <- worldWith [free (V3 0 1 0) (speed *^ V3 (cos 0.37) 0 (sin 0.37))]
      crossings <- newIORef (0 :: Int)
      worst <- newIORef (0 :: Double, 0 :: Double, -1 :: Double)
      previous <- newIORef (V3 0 1 0)
      replicateM_ 10000 $ do
        stepNative w
        b <- readBody w 0
        p0 <- readIORef previous
        writeIORef previous (bsPos b)
        -- a wrap moves the body by about the octagon's width (2 × 1.53)
        if normIn Minkowski (bsPos b - p0) > 1 then modifyIORef' crossings (+ 1) else pure ()
        modifyIORef' worst $ \(s, f, o) ->
          ( max s (abs (normIn Minkowski (bsVel b) / speed - 1))
          , max f (abs (evalFn (spaceField sp) (bsPos b)))
          , max o (outside (bsPos b)) )
      (s, f, o) <- readIORef worst
      n <- readIORef crossings
      n `shouldSatisfy` (>= 40)
      s `shouldSatisfy` (< 1e-12)
      f `shouldSatisfy` (< 1e-9)
      o `shouldSatisfy` (< 1e-9)

    it "brings a body across side 0 back through side 4 where the pairing puts it on the plane (1e-9) and the geodesic's closed form (1e-5), its velocity carried" $ do
      -- from the vertex at angle 0.3 the geodesic crosses side 0 (whose
      -- angles are within π/8 of 0) at distance r with tanh r cos 0.3 = tanh of the inradius
      let speed = 0.5
          a = 0.3
          start = [free (V3 0 1 0) (speed *^ V3 (cos a) 0 (sin a))]
      w <- worldWith start
      wPlane <- onPlane start
      states <- forM [1 .. 600 :: Int] $ \k -> do
        stepNative w
        stepNative wPlane
        (,,) k <$> readBody w 0 <*> readBody wPlane 0
      let crossed = [ s' | s'@(_, _, bp) <- states, sideExcess 0 (bsPos bp) > 0 ]
          back = pairing 4
          gap u v = normIn Euclidean (u - v)
      case crossed of
        [] -> expectationFailure "the body never reached side 0 in 600 steps"
        (k, b, bp) : _ -> do
          let r = speed * fromIntegral k * dt
          sideExcess 4 (bsPos b) `shouldSatisfy` (\e -> e < 0 && e > -0.05) -- just inside side 4
          gap (bsPos b) (applyBoost back (bsPos bp)) `shouldSatisfy` (< 1e-9)
          gap (bsVel b) (applyBoost back (bsVel bp)) `shouldSatisfy` (< 1e-9)
          gap (bsPos b) (applyBoost back (polar r a)) `shouldSatisfy` (< 1e-5)
          gap (bsVel b) (applyBoost back (speed *^ outward r a)) `shouldSatisfy` (< 1e-5)

    it "collides two bodies across a side as the plane collides them about its vertex (1e-9): head on, the momentum along the axis kept (1e-5) and passed on" $ do
      -- body 0 just inside side 0 moving out, body 1 at rest just inside
      -- side 4, whose image under pairing 0 is 0.3 beyond body 0; on the
      -- plane the same pair about the vertex (the translation along x by
      -- the inradius carries one pair onto the other)
      let r = inradius - 0.15
      -- (a pair through an image is found anew each step, where a pair in
      -- place keeps its rows while it hardly moves: here neither does)
      let fresh = defaultParams { pKeepContacts = False }
      w <- worldOnWith fresh sp [free (polar r 0) (outward r 0), free (polar r pi) (V3 0 0 0)]
      wPlane <- worldOnWith fresh hyperbolicPlane [free (polar 0.15 pi) (outward (-0.15) 0), free (polar 0.15 0) (V3 0 0 0)]
      -- the velocity along +x (the unit tangent at (x, y, 0) on the x
      -- axis is (y, x, 0)); pairings 0 and 4 keep the axis and the sense
      let along b = let V3 x y _ = bsPos b in inner Minkowski (bsVel b) (V3 y x 0)
      replicateM_ 100 (stepNative w >> stepNative wPlane)
      [b0, b1] <- mapM (readBody w) [0, 1]
      [p0, p1] <- mapM (readBody wPlane) [0, 1]
      abs (along b0 - along p0) `shouldSatisfy` (< 1e-9)
      abs (along b1 - along p1) `shouldSatisfy` (< 1e-9)
      along b0 + along b1 `shouldSatisfy` (\m -> abs (m - 1) < 1e-5)
      along b1 `shouldSatisfy` (> 0.4)
      along b0 `shouldSatisfy` (< 0.6)

    it "collides two bodies across a corner, where eight octagons meet, as the plane collides them (1e-9)" $ do
      -- body 0 at rest inside, 0.4 from corner 0 along the ray through it;
      -- body 1 0.4 beyond the corner on that ray (in the octagon across
      -- the corner, wrapped into this one after the first step), thrown at
      -- body 0 through the corner; on the plane, the same two bodies
      let c = circumradius
          a = pi / 8
          fresh = defaultParams { pKeepContacts = False }
          bodies = [free (polar (c - 0.4) a) (V3 0 0 0), free (polar (c + 0.4) a) (negate (outward (c + 0.4) a))]
      w <- worldOnWith fresh sp bodies
      wPlane <- worldOnWith fresh hyperbolicPlane bodies
      replicateM_ 100 (stepNative w >> stepNative wPlane)
      b0 <- readBody w 0
      p0 <- readBody wPlane 0
      let gap u v = normIn Euclidean (u - v)
      gap (bsPos b0) (bsPos p0) `shouldSatisfy` (< 1e-9)
      gap (bsVel b0) (bsVel p0) `shouldSatisfy` (< 1e-9)
      -- it was struck: about half the thrower's speed, away from the
      -- corner towards the octagon's centre
      inner Minkowski (bsVel b0) (outward (c - 0.4) a) `shouldSatisfy` (< -0.3)

