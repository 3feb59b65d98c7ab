-- | The Minkowski metric's geometry (Manifold.Metric), on the hyperboloid
-- y = √(1 + x² + z²), the hyperbolic plane of curvature −1: geodesics and
-- geodesic circles against their closed forms, the tangent frames, the
-- broad phase's grid coordinates, and a free body moved by the generic step.
-- (Every Euclidean space computing exactly what it did before metrics
-- existed is the golden runs' test.)
module MetricSpec (spec) where

import Control.Monad (forM_, replicateM_, when, (>=>))
import Linear.Metric (dot)
import Linear.V3 (V3 (..))
import Linear.Vector ((*^), (^+^), (^-^))
import Test.Hspec

import Manifold
import Manifold.Engine
import Manifold.World (layout)

-- | The upper sheet of y² − x² − z² = 1 in Minkowski space, no gravity.
hyperboloid :: Space
hyperboloid = (space "hyperboloid" "the hyperbolic plane as a hyperboloid" (scalarFn (\(V3 x y z) -> sqrt (1 + x * x + z * z) - y)))
  { spaceMetric = Minkowski, spaceBounds = 6 }

vertex :: V3 Double
vertex = V3 0 1 0

-- | The hyperboloid's point at distance @r@ from the vertex in direction
-- angle @a@ (the closed form of the exponential map there).
polar :: Double -> Double -> V3 Double
polar r a = V3 (sinh r * cos a) (cosh r) (sinh r * sin a)

distanceTo :: V3 Double -> V3 Double -> Double
distanceTo p q = sqrt (sum (fmap (^ (2 :: Int)) (p ^-^ q)))

spec :: Spec
spec = describe "Manifold.Metric: the hyperboloid in Minkowski space" $ do
  let f = spaceField hyperboloid
      m = Minkowski

  it "has a unit time-like normal and orthonormal tangent frames, far from the vertex too" $
    forM_ [(0.3, 0.2), (2.0, 1.1), (3.5, -2.4)] $ \(r, a) -> do
      let p = polar r a
          n = unitNormal m f p
          u = referenceAxis m n
          (_, w) = tangentFrame m n u
      inner m n n `shouldSatisfy` (\x -> abs (x + 1) < 1e-12)
      forM_ [inner m n u, inner m n w, inner m u w] (`shouldSatisfy` ((< 1e-12) . abs))
      forM_ [inner m u u, inner m w w] (`shouldSatisfy` (\x -> abs (x - 1) < 1e-12))

  it "has Gaussian curvature −1 everywhere under the metric (1e-9), where R³'s formula gives another number" $
    forM_ [(0, 0), (0.8, 1.0), (2.2, -0.5), (3.5, 2.9)] $ \(r, a) -> do
      let p = polar r a
      abs (gaussianCurvatureIn m f p + 1) `shouldSatisfy` (< 1e-9)
      when (r > 0) $ abs (gaussianCurvature f p + 1) `shouldSatisfy` (> 1e-3)

  it "walks geodesics from the vertex to cosh L · (0, 1, 0) + sinh L · d (within 1e-6 of cosh L), with the direction sinh L · (0, 1, 0) + cosh L · d" $
    forM_ [(1.5, 0.3), (2.5, 2.0), (0.7, -1.0)] $ \(len, a) -> do
      let d = V3 (cos a) 0 (sin a)
          (end, dir) = expMap m f 4000 vertex d len
      (distanceTo end (polar len a) / cosh len) `shouldSatisfy` (< 1e-6)
      (distanceTo dir (sinh len *^ V3 0 1 0 ^+^ cosh len *^ d) / cosh len) `shouldSatisfy` (< 1e-6)
      abs (evalFn f end) `shouldSatisfy` (< 1e-9)

  it "has geodesic circles of circumference 2π sinh ρ (1e-4), where a flat plane's would be 2πρ" $
    forM_ [0.5, 1.0, 2.0] $ \rho -> do
      let k = 720 :: Int
          points = [fst (expMap m f 400 vertex (V3 (cos a) 0 (sin a)) rho) | i <- [0 .. k - 1], let a = 2 * pi * fromIntegral i / fromIntegral k]
          around = sum (zipWith (\p q -> normIn m (q ^-^ p)) points (drop 1 points ++ take 1 points))
      abs (around / (2 * pi * sinh rho) - 1) `shouldSatisfy` (< 1e-4)

  it "files points for the broad phase so that no axis is apart by more than the chord (2000 seeded pairs)" $ do
    -- a seeded linear congruential sequence on [−1, 1)
    let numbers = map (\k -> fromIntegral k / 2 ^ (31 :: Int) - 1) (tail (iterate (\k -> (1103515245 * k + 12345) `mod` (2 ^ (32 :: Int))) (31 :: Integer))) :: [Double]
        pairs = take 2000 (go numbers)
        go (r1 : a1 : r2 : a2 : rest) = (polar (3 * abs r1) (pi * a1), polar (3 * abs r2) (pi * a2)) : go rest
        go _ = []
    forM_ pairs $ \(p, q) -> do
      let V3 dx dy dz = gridPoint m p ^-^ gridPoint m q
          chord = normIn m (p ^-^ q)
      maximum (map abs [dx, dy, dz]) `shouldSatisfy` (<= chord * (1 + 1e-12))

  it "moves a free body along the geodesic at constant speed, on the surface (generic step, 600 steps)" $ do
    w <- genericStep <$> newWorldUsing [] hyperboloid (layout 16)
    let speed = 0.5
        a = 0.4
    _ <- addBody w (BodyInit circle 0.1 1 False vertex (speed *^ V3 (cos a) 0 (sin a)) 0 0.3 sceneMaterial) >>= either fail pure
    let steps = 600 :: Int
    replicateM_ steps (stepNative w)
    b <- readBody w 0
    let t = fromIntegral steps * pDt defaultParams
    abs (normIn m (bsVel b) / speed - 1) `shouldSatisfy` (< 1e-9)
    abs (evalFn f (bsPos b)) `shouldSatisfy` (< 1e-9)
    inner m (bsVel b) (unitNormal m f (bsPos b)) `shouldSatisfy` ((< 1e-9) . abs)
    distanceTo (bsPos b) (polar (speed * t) a) `shouldSatisfy` (< 1e-3)
    -- it went far: a Euclidean walk would be nowhere near
    (bsPos b `dot` V3 0 1 0) `shouldSatisfy` (> 2)

  describe "the catalogue's hyperbolic-plane (compiled step)" $ do
    let sp = hyperbolicPlane
        g = spaceField sp
        worldWith gravityOn bodies = do
          w <- newWorld sp (layout (length bodies))
          setParams w defaultParams { pGravity = gravityOn }
          forM_ bodies (addBody w >=> either fail (const (pure ())))
          pure w
        free p v = BodyInit circle 0.1 1 False p v 0 0 sceneMaterial

    it "has the Minkowski metric, and curvature −1 (1e-9) on its surface" $ do
      spaceMetric sp `shouldBe` Minkowski
      forM_ [(0, 0), (0.7, 0.3), (1.9, 2.2), (3.0, -1.4)] $ \(r, a) ->
        abs (gaussianCurvatureIn m g (polar r a) + 1) `shouldSatisfy` (< 1e-9)

    -- (after one step of 1/100 s the velocity has been carried to where
    -- the body moved: the closed form holds to O(dt²))
    it "pulls a body at rest toward the vertex with G tanh r (1e-4 after one step)" $
      forM_ [0.5, 1.0, 2.0] $ \r -> do
        w <- worldWith True [free (polar r 0) (V3 0 0 0)]
        stepNative w
        b <- readBody w 0
        let expected = hyperbolicGravity * tanh r * pDt defaultParams
            -- the unit tangent at polar r 0 pointing away from the vertex
            outward = V3 (cosh r) (sinh r) 0
        abs (normIn m (bsVel b) / expected - 1) `shouldSatisfy` (< 1e-4)
        (inner m (bsVel b) outward / expected) `shouldSatisfy` (\c -> abs (c + 1) < 1e-4)

    it "keeps a free body's speed (1e-12) on the surface (1e-9), along the geodesic's closed form, for 1000 steps" $ do
      -- (to r = 3 from the vertex: farther out the hyperboloid's coordinates
      -- grow as cosh r and every rounding with them)
      let speed = 0.3
          a = 1.1
      w <- worldWith False [free vertex (speed *^ V3 (cos a) 0 (sin a))]
      replicateM_ 1000 (stepNative w)
      b <- readBody w 0
      abs (normIn m (bsVel b) / speed - 1) `shouldSatisfy` (< 1e-12)
      abs (evalFn g (bsPos b)) `shouldSatisfy` (< 1e-9)
      (distanceTo (bsPos b) (polar (speed * 10) a) / cosh (speed * 10)) `shouldSatisfy` (< 1e-3)

    it "keeps a thrown body's angular momentum about the y axis under gravity (Clairaut, 1e-9 over 2000 steps)" $ do
      let p0 = polar 0.8 0.4
          v0 = 0.9 *^ V3 (negate (sin 0.4)) 0 (cos 0.4)
          momentum b = let V3 x _ z = bsPos b; V3 vx _ vz = bsVel b in x * vz - z * vx
      w <- worldWith True [free p0 v0]
      l0 <- momentum <$> readBody w 0
      replicateM_ 2000 (stepNative w)
      l1 <- momentum <$> readBody w 0
      abs (l1 / l0 - 1) `shouldSatisfy` (< 1e-9)
