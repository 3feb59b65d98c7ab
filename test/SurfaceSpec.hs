-- | Projection onto the surface, transport of tangent vectors, geodesics and
-- the exponential map.
module SurfaceSpec (spec) where

import Control.Monad (forM, forM_)
import Linear.Metric (dot, norm, quadrance)
import Linear.V3 (V3 (..), cross)
import Linear.Vector ((*^), (^+^), (^-^))
import Test.Hspec
import Test.QuickCheck
import Test.QuickCheck.Gen (unGen)
import Test.QuickCheck.Random (mkQCGen)
import Text.Printf (printf)

import Manifold
import TestUtil

spec :: Spec
spec = do
  projectionSpec
  transportSpec
  geodesicSpec
  expMapSpec

-- Projection ---------------------------------------------------------------------

projectionSpec :: Spec
projectionSpec = describe "projectToSurface" $ do
  describe "lands on the surface (|f| < 1e-9) from up to 0.1 away in a random direction" $
    forM_ catalogue $ \s ->
      it (spaceName s ++ " (surface points: " ++ samplerDomain (surfaceSampler s) ++ ")") $
        property $ withMaxSuccess 200 $
          forAll (genSurfacePoint s) $ \analytic ->
          forAll genUnitV3 $ \e -> forAll (choose (0, 0.2)) $ \a ->
          forAll genUnitV3 $ \u ->
          forAll (choose (0, 0.1)) $ \t ->
            let f = spaceField s
                -- A surface point obtained by projecting a random point
                -- (within 0.2 of an analytic surface point).
                start = analytic ^+^ a *^ e
                p0 = projectToSurface f start
                q = p0 ^+^ t *^ u
                p1 = projectToSurface f q
                fv0 = fieldAt s p0
                fv = fieldAt s p1
            in norm (gradAt s p0) > 0.1 && abs fv0 < 1e-9 ==>
                 counterexample ("p0 = " ++ showV3 p0 ++ ", offset point " ++ showV3 q ++ " -> " ++ showV3 p1
                                 ++ ", f = " ++ show fv) $
                   abs fv < 1e-9 .&&. vecDist p1 q <= 0.2
  it "sanity: the samplers give points on the surface of every space" $
    property $ withMaxSuccess 200 $ forAllShow (elements catalogue) spaceName $ \s ->
      forAll (genSurfacePoint s) $ \p ->
        counterexample (spaceName s ++ " " ++ showV3 p) (abs (fieldAt s p) < 1e-12)
  it "sphere: a point off the sphere goes to p / |p| (one Newton step is exact)" $
    property $ withMaxSuccess 200 $ forAll genUnitV3 $ \u -> forAll (choose (0.5, 2)) $ \rho ->
      vecDist u (projectToSurface (spaceField sphere) (rho *^ u)) <= 1e-12
  it "leaves a point whose gradient vanishes where it is (the centre of |p|² − 1 = 0)" $ do
    let f = scalarFn (\p -> quadrance p - 1)
    fieldGradient f (V3 0 0 0) `shouldBe` (V3 0 0 0 :: V3 Double)
    projectToSurface f (V3 0 0 0) `shouldBe` (V3 0 0 0 :: V3 Double)
  it "leaves points on the surface where they are" $
    property $ withMaxSuccess 200 $ forAllShow (elements catalogue) spaceName $ \s ->
      forAll (genSurfacePoint s) $ \p ->
        vecDist p (projectToSurface (spaceField s) p) <= 1e-12

-- Transport ------------------------------------------------------------------------

transportSpec :: Spec
transportSpec = describe "transport" $
  forM_ catalogue $ \s ->
    it (spaceName s ++ ": keeps the length (relative 1e-12) and makes the vector tangent") $
      property $ withMaxSuccess 200 $
        forAll (genNearSurfacePoint 0.1 s) $ \p ->
        forAll (genV3In 3) $ \v ->
          let f = spaceField s
              n = unitNormal Euclidean f p
              w = v ^-^ (n `dot` v) *^ n
              t = transport Euclidean f p v
          in (norm (gradAt s p) > 0.1 && norm w > 1e-3 * norm v) ==>
               counterexample ("p = " ++ showV3 p ++ ", v = " ++ showV3 v ++ " -> " ++ showV3 t) $
                 (abs (norm t - norm v) <= 1e-12 * norm v)
                   .&&. (abs (n `dot` t) <= 1e-12 * norm v)
                   .&&. (t `dot` w > 0)

-- Geodesics --------------------------------------------------------------------------

-- | A random start on the unit sphere with a unit tangent direction.
genSphereStart :: Gen (V3 Double, V3 Double)
genSphereStart = do
  p <- genUnitV3
  d <- genTangentUnit p
  pure (p, d)

greatCircleSteps :: Int
greatCircleSteps = round (2 * pi / 0.01 :: Double) -- 628, step ≈ 0.01

-- | Walk a full great circle; returns (closure error |end − start|, error of
-- the half-way point against the antipode, largest distance from the plane
-- of the circle, largest |f|, largest | |v| − 1 |).
greatCircle :: (V3 Double, V3 Double) -> (Double, Double, Double, Double, Double)
greatCircle (p0, d) =
  let sf = spaceField sphere
      path = geodesicPath Euclidean sf greatCircleSteps p0 d (2 * pi)
      (end, _) = last path
      (half, _) = path !! (greatCircleSteps `div` 2)
      nrm = p0 `cross` d
  in ( vecDist end p0
     , vecDist half (negate p0)
     , maximum [abs (p `dot` nrm) | (p, _) <- path]
     , maximum [abs (evalField sphere p) | (p, _) <- path]
     , maximum [abs (norm v - 1) | (_, v) <- path] )

-- | Angular momentum about the torus's symmetry axis, @(p × v) · ŷ@.
angularMomentum :: V3 Double -> V3 Double -> Double
angularMomentum p v = let V3 _ l _ = p `cross` v in l

-- | A start on the torus with a unit tangent direction whose angular momentum
-- is not small (so that a relative drift is meaningful).
genTorusStart :: Gen (V3 Double, V3 Double)
genTorusStart = (do
  (phi, psi) <- genTorusAngles
  let p = torusPoint phi psi
  d <- genTangentUnit (unitNormal Euclidean (spaceField torus) p)
  pure (p, d)) `suchThat` (\(p, d) -> abs (angularMomentum p d) >= 0.2)

-- | Walk a torus geodesic of length 20 with the given step; returns (maximum
-- relative drift of the angular momentum, polyline length, largest |f|).
clairaut :: Double -> (V3 Double, V3 Double) -> (Double, Double, Double)
clairaut h (p0, d) =
  let tf = spaceField torus
      n = round (20 / h)
      path = geodesicPath Euclidean tf n p0 d 20
      l0 = angularMomentum p0 d
      drift = maximum [abs (angularMomentum p v - l0) / abs l0 | (p, v) <- path]
      pts = map fst path
      len = sum (zipWith vecDist pts (tail pts))
  in (drift, len, maximum [abs (evalField torus p) | p <- pts])

geodesicSpec :: Spec
geodesicSpec = describe "geodesicPath / expMap" $ do
  it "returns n + 1 points, starting at the start with the normalised tangent direction" $
    property $ withMaxSuccess 100 $ forAll genSphereStart $ \(p, d) -> forAll (choose (1, 50)) $ \n ->
      let path = geodesicPath Euclidean (spaceField sphere) n p (3 *^ d ^+^ 2 *^ p) 1
      in length path == n + 1 .&&. vecDist (fst (head path)) p == 0 .&&. vecDist (snd (head path)) d <= 1e-12
  it "on the plane walks a straight line of the given length" $
    property $ withMaxSuccess 100 $
      forAll ((\x z -> V3 x 0 z) <$> choose (-1, 1) <*> choose (-1, 1)) $ \p ->
      forAll (choose (0, 2 * pi)) $ \t -> forAll (choose (0.1, 3)) $ \len ->
        let d = V3 (cos t) 0 (sin t)
            (end, endDir) = expMap Euclidean (spaceField plane) 37 p d len
        in vecDist end (p ^+^ len *^ d) <= 1e-9 .&&. vecDist endDir d <= 1e-12

  -- Measured once, printed, then checked.
  let circles = unGen (vectorOf 8 genSphereStart) (mkQCGen 2026) 30
  let gcs = map greatCircle circles
      gcClose = maximum [c | (c, _, _, _, _) <- gcs]
      gcHalf = maximum [a | (_, a, _, _, _) <- gcs]
  runIO $ printf "great-circle closure error (8 random great circles, step 0.01, length 2π): max |end − start| = %.3e, max |mid − antipode| = %.3e\n" gcClose gcHalf
  it "closes a great circle of the unit sphere after length 2π (end within 1e-3 of the start; 8 seeded circles)" $
    forM_ (zip circles gcs) $ \((p, d), (close, half, offPlane, offSurface, speed)) -> do
      let ctx = "start " ++ showV3 p ++ " dir " ++ showV3 d
      (ctx, close) `shouldSatisfy` ((< 1e-3) . snd)
      (ctx ++ ": half-way point vs antipode", half) `shouldSatisfy` ((< 1e-3) . snd)
      (ctx ++ ": distance from the circle's plane", offPlane) `shouldSatisfy` ((< 1e-9) . snd)
      (ctx ++ ": |f|", offSurface) `shouldSatisfy` ((< 1e-9) . snd)
      (ctx ++ ": | |v| - 1 |", speed) `shouldSatisfy` ((< 1e-12) . snd)
  it "expMap is the last point of geodesicPath" $
    property $ withMaxSuccess 50 $ forAll genSphereStart $ \(p, d) ->
      let sf = spaceField sphere
      in expMap Euclidean sf 100 p d 1.3 == last (geodesicPath Euclidean sf 100 p d 1.3)

  let starts = unGen (vectorOf 8 genTorusStart) (mkQCGen 2027) 30
  let cl01 = map (clairaut 0.01) starts
      cl005 = map (clairaut 0.005) starts
      maxDrift rs = maximum [d | (d, _, _) <- rs]
  runIO $ printf "clairaut drift (torus, 8 random starts, length 20): max relative = %.3e at step 0.01, %.3e at step 0.005\n"
            (maxDrift cl01) (maxDrift cl005)
  it "on the torus conserves the angular momentum about the axis (Clairaut) to 1e-3 relative over length 20 (step 0.01; 8 seeded starts)" $
    clairautChecks starts cl01
  it "... and at step 0.005" $
    clairautChecks starts cl005
  it "the Clairaut oracle itself: drift shrinks as the step shrinks (first start, 0.01 vs 0.0025)" $ do
    let s0 = head starts
        (d1, _, _) = clairaut 0.01 s0
        (d2, _, _) = clairaut 0.0025 s0
    (d1, d2) `shouldSatisfy` (\(a, b) -> b < a / 2 || a < 1e-6)

clairautChecks :: [(V3 Double, V3 Double)] -> [(Double, Double, Double)] -> Expectation
clairautChecks starts results =
  forM_ (zip starts results) $ \((p, d), (drift, len, offSurface)) -> do
    let ctx = "start " ++ showV3 p ++ " dir " ++ showV3 d ++ " L0 = " ++ show (angularMomentum p d)
    (ctx, drift) `shouldSatisfy` ((< 1e-3) . snd)
    -- The geodesic really moves: its polyline is 20 long.
    (ctx ++ ": polyline length", len) `shouldSatisfy` ((< 0.01) . relErr 20 . snd)
    (ctx ++ ": |f|", offSurface) `shouldSatisfy` ((< 1e-9) . snd)

-- Exponential map ------------------------------------------------------------------------

-- | The circumference of the geodesic circle of radius ρ about the north pole
-- of the unit sphere, as the sum of the chords between the ends of 720
-- geodesics (step ≤ 0.01).
geodesicCircumference :: Double -> Double
geodesicCircumference rho =
  let sf = spaceField sphere
      pole = V3 0 1 0
      k = 720 :: Int
      n = ceiling (rho / 0.01)
      ends = [ fst (expMap Euclidean sf n pole (V3 (cos t) 0 (sin t)) rho)
             | i <- [0 .. k - 1], let t = 2 * pi * fromIntegral i / fromIntegral k ]
  in sum (zipWith vecDist ends (tail ends ++ take 1 ends))

expMapSpec :: Spec
expMapSpec = describe "expMap" $ do
  let radii = [0.3, 1.0, 1.6, 2.4, 3.0] :: [Double]
  results <- runIO $ forM radii $ \rho -> do
    let c = geodesicCircumference rho
        e = relErr (2 * pi * sin rho) c
    printf "circumference rel error (unit sphere, ρ = %.1f): measured %.6f, expected 2π sin ρ = %.6f, rel error %.3e\n"
      rho c (2 * pi * sin rho) e
    pure (rho, c, e)
  forM_ results $ \(rho, c, e) ->
    it (printf "a geodesic circle of radius %.1f on the unit sphere has circumference 2π sin ρ within 1%%" rho) $
      (c, e) `shouldSatisfy` ((< 0.01) . snd)
  it "reaches the point at great-circle distance ρ (walked from random points)" $
    property $ withMaxSuccess 50 $ forAll genSphereStart $ \(p, d) -> forAll (choose (0.1, 3)) $ \rho ->
      let (end, _) = expMap Euclidean (spaceField sphere) (ceiling (rho / 0.01)) p d rho
          expected = cos rho *^ p ^+^ sin rho *^ d
      in counterexample ("end " ++ showV3 end ++ " expected " ++ showV3 expected) (vecDist end expected <= 1e-3)
