-- | Bodies: mass and inertia against closed forms, centroids, and the
-- geodesic polygons.
module BodySpec (spec) where

import Control.Exception (evaluate)
import Control.Monad (forM_)
import Data.List (nub)
import Linear.Metric (dot, norm)
import Linear.V2 (V2 (..))
import Linear.V3 (V3 (..), cross)
import Linear.Vector ((*^), (^+^))
import Test.Hspec
import Test.QuickCheck
import Text.Printf (printf)

import Manifold
import TestUtil

spec :: Spec
spec = do
  massSpec
  centroidSpec
  polygonCountSpec
  polygonGeometrySpec

-- Mass ------------------------------------------------------------------------------

-- | Area and moment of inertia (per unit density) of a regular n-gon of
-- circumradius R: A = (n/2) R² sin(2π/n), I = (m R²/6)(1 + 2cos²(π/n)).
ngonClosedForm :: Int -> Double -> Double -> (Double, Double)
ngonClosedForm n bigR density =
  let a = fromIntegral n / 2 * bigR * bigR * sin (2 * pi / fromIntegral n)
      m = density * a
  in (m, m * bigR * bigR / 6 * (1 + 2 * cos (pi / fromIntegral n) ^ (2 :: Int)))

massCases :: [(String, Shape, Double, Double, (Double, Double))]
massCases =
  [ ("circle (m = ρπR², I = mR²/2)", circle, 0.7, 2.5
    , let m = 2.5 * pi * 0.7 * 0.7 in (m, m * 0.7 * 0.7 / 2))
  , ("circle, R = 0.2, ρ = 1", circle, 0.2, 1
    , let m = pi * 0.04 in (m, m * 0.04 / 2))
  , ("square (side R√2: m = 2ρR², I = mR²/3)", square, 0.6, 1.5
    , let m = 1.5 * 2 * 0.36 in (m, m * 0.36 / 3))
  , ("regular hexagon (m = ρ(3√3/2)R², I = (5/12) mR²)", regularPolygon 6, 0.5, 2
    , let m = 2 * 3 * sqrt 3 / 2 * 0.25 in (m, 5 / 12 * m * 0.25))
  , ("triangle (n-gon formula)", regularPolygon 3, 0.8, 1, ngonClosedForm 3 0.8 1)
  , ("pentagon (n-gon formula)", regularPolygon 5, 0.3, 3, ngonClosedForm 5 0.3 3)
  , ("octagon (n-gon formula)", regularPolygon 8, 1.2, 0.5, ngonClosedForm 8 1.2 0.5)
  ]

massSpec :: Spec
massSpec = describe "massProperties against closed forms (within 1 %)" $ do
  forM_ massCases $ \(name, shape, size, density, (m, i)) -> do
    let MassProperties m' i' = massProperties shape size density
        em = relErr m m'
        ei = relErr i i'
    runIO $ printf "mass rel error %-50s mass %.3e, inertia %.3e\n" name em ei
    it (printf "%s, size %.2f, density %.2f (mass error %.1e, inertia error %.1e)" name size density em ei) $ do
      (m', em) `shouldSatisfy` ((< 0.01) . snd)
      (i', ei) `shouldSatisfy` ((< 0.01) . snd)
  it "the closed forms of the n-gon reduce to the square's for n = 4" $ do
    let (m, i) = ngonClosedForm 4 0.6 1.5
    m `shouldSatisfy` closeRel 1e-12 (1.5 * 2 * 0.36)
    i `shouldSatisfy` closeRel 1e-12 (m * 0.36 / 3)
  it "areaOf of a custom outline s = 1 + 0.5 cos θ is ½∫s² = 1.125π" $
    areaOf offCentre 1 `shouldSatisfy` closeRel 1e-6 (1.125 * pi)
  it "shapeFromKind gives the shapes of the kinds" $ do
    shapeKind (shapeFromKind CircleShape) `shouldBe` Just CircleShape
    shapeKind (shapeFromKind SquareShape) `shouldBe` Just SquareShape
    shapeKind (shapeFromKind (PolygonShape 7)) `shouldBe` Just (PolygonShape 7)
    areaOf (shapeFromKind SquareShape) 1 `shouldSatisfy` closeRel 1e-3 2
    areaOf (shapeFromKind (PolygonShape 6)) 1 `shouldSatisfy` closeRel 1e-3 (3 * sqrt 3 / 2)

-- Centroids -----------------------------------------------------------------------------

-- | An off-centre outline: its centroid is at (17/36, 0) for size 1, and
-- ∫ s² e^{iθ} dθ = (π, 0).
offCentre :: Shape
offCentre = customShape "off-centre" (\t -> 1 + 0.5 * cos t)

v2Norm :: V2 Double -> Double
v2Norm (V2 x y) = sqrt (x * x + y * y)

centroidSpec :: Spec
centroidSpec = describe "centroidOffset and paperMomentIntegral" $ do
  forM_ [("square", square), ("circle", circle), ("hexagon", regularPolygon 6)] $ \(name, s) ->
    it ("vanish (1e-9) for the " ++ name) $ do
      v2Norm (centroidOffset s 0.7) `shouldSatisfy` (< 1e-9)
      v2Norm (paperMomentIntegral s 0.7) `shouldSatisfy` (< 1e-9)
  -- The triangle has no central symmetry and 4096 midpoint samples do not
  -- divide into 3 sectors, so its integrals vanish only to quadrature
  -- accuracy (≈ 2e-7), not to rounding.
  it "vanish to quadrature accuracy (1e-6) for the triangle" $ do
    v2Norm (centroidOffset (regularPolygon 3) 0.7) `shouldSatisfy` (< 1e-6)
    v2Norm (paperMomentIntegral (regularPolygon 3) 0.7) `shouldSatisfy` (< 1e-6)
  it "are non-zero for the off-centre outline s(θ) = 1 + 0.5 cos θ: centroid (17/36)·size, moment π·size²" $
    forM_ [1, 0.5] $ \size -> do
      let V2 cx cy = centroidOffset offCentre size
          V2 mx my = paperMomentIntegral offCentre size
      cx `shouldSatisfy` closeRel 1e-6 (17 / 36 * size)
      cy `shouldSatisfy` closeAbs 1e-9 0
      mx `shouldSatisfy` closeRel 1e-6 (pi * size * size)
      my `shouldSatisfy` closeAbs 1e-9 0
  it "rotate with the outline (s(θ) = 1 + 0.5 sin θ has its centroid on the y axis)" $ do
    let V2 cx cy = centroidOffset (customShape "up" (\t -> 1 + 0.5 * sin t)) 1
    cx `shouldSatisfy` closeAbs 1e-9 0
    cy `shouldSatisfy` closeRel 1e-6 (17 / 36)

-- Polygons ---------------------------------------------------------------------------------

paramCases :: [PolygonParams]
paramCases = [PolygonParams 3 1, PolygonParams 4 2, defaultPolygonParams, PolygonParams 7 3, PolygonParams 12 5, PolygonParams 36 1]

-- | A unit tangent axis at a point with unit normal n.
axisAt :: V3 Double -> V3 Double
axisAt n =
  let pick = if abs (n `dot` V3 1 0 0) < 0.9 then V3 1 0 0 else V3 0 0 1
  in safeNormalize (tangentProjection Euclidean n pick)

polygonCountSpec :: Spec
polygonCountSpec = describe "polygonise: counts" $
  forM_ paramCases $ \pp@(PolygonParams d st) ->
    it (printf "match the parameters for %d directions × %d steps" d st) $ do
      let f = spaceField sphere
          p = V3 0 1 0
          poly = polygonise Euclidean f pp square 0.3 p (V3 1 0 0) (0.2 :: Double)
          nv = 1 + d * st
          nt = d * (2 * st - 1)
      vertexCount pp `shouldBe` nv
      triangleCount pp `shouldBe` nt
      length (polyVertices poly) `shouldBe` nv
      length (polyLocal poly) `shouldBe` nv
      length (polyTriangles poly) `shouldBe` nt
      length (polyOutline poly) `shouldBe` d
      -- Indices are in range, triangles are not degenerate nor repeated,
      -- and every vertex is used.
      let idx = concat [[a, b, c] | (a, b, c) <- polyTriangles poly]
      idx `shouldSatisfy` all (\i -> i >= 0 && i < nv)
      polyTriangles poly `shouldSatisfy` all (\(a, b, c) -> a /= b && b /= c && a /= c)
      length (nub (polyTriangles poly)) `shouldBe` nt
      length (nub idx) `shouldBe` nv
      -- The outline is the last step of every direction.
      polyOutline poly `shouldBe` [polyVertices poly !! (1 + k * st + st - 1) | k <- [0 .. d - 1]]
      head (polyVertices poly) `shouldBe` p

polygonGeometrySpec :: Spec
polygonGeometrySpec = describe "polygonise: geometry" $ do
  describe "vertices are on the surface (|f| < 1e-9) for the first body of every scene" $
    forM_ catalogue $ \s ->
      it (spaceName s) $
        forM_ (take 2 (spaceScene s)) $ \pl -> do
          let f = spaceField s
              c = projectToSurface f (placeAt pl)
              n = unitNormal Euclidean f c
              poly = polygonise Euclidean f defaultPolygonParams (shapeFromKind (placeShape pl)) (placeSize pl) c (axisAt n) (0.4 :: Double)
          maximum (map (abs . evalField s) (polyOutline poly)) `shouldSatisfy` (< 1e-9)
          maximum (map (abs . evalField s) (polyVertices poly)) `shouldSatisfy` (< 1e-9)
  it "on the plane, a circle's outline is at distance size from the centre (1e-9), vertex j of s at j·size/s" $
    property $ withMaxSuccess 100 $
      forAll ((\x z -> V3 x 0 z) <$> choose (-1, 1) <*> choose (-1, 1)) $ \c ->
      forAll (choose (0.05, 1)) $ \size ->
      forAll (choose (0, 2 * pi)) $ \t -> forAll (choose (-3, 3)) $ \angle ->
        let pp = defaultPolygonParams
            poly = polygonise Euclidean (spaceField plane) pp circle size c (V3 (cos t) 0 (sin t)) angle
            st = polySteps pp
            ringDist j = [vecDist c (polyVertices poly !! (1 + k * st + j - 1)) | k <- [0 .. polyDirections pp - 1]]
        in conjoin [ counterexample ("step " ++ show j) (all (closeAbs 1e-9 (size * fromIntegral j / fromIntegral st)) (ringDist j))
                   | j <- [1 .. st] ]
             .&&. all (closeAbs 1e-9 size . vecDist c) (polyOutline poly)
  it "on the plane, a square's outline point in direction θ is c + s(θ)(cos(angle+θ) u + sin(angle+θ) n×u)" $
    property $ withMaxSuccess 100 $
      forAll ((\x z -> V3 x 0 z) <$> choose (-1, 1) <*> choose (-1, 1)) $ \c ->
      forAll (choose (0.05, 1)) $ \size ->
      forAll (choose (0, 2 * pi)) $ \t -> forAll (choose (-3, 3)) $ \angle ->
        let pp = PolygonParams 16 3
            u = V3 (cos t) 0 (sin t)
            w = V3 0 1 0 `cross` u
            poly = polygonise Euclidean (spaceField plane) pp square size c u angle
            expected k =
              let theta = 2 * pi * fromIntegral k / 16
                  -- circumradius size, a side facing θ = 0: the square
                  -- max(|x|, |y|) = apothem = size cos(π/4)
                  r = size * cos (pi / 4) / max (abs (cos theta)) (abs (sin theta))
                  phi = angle + theta
              in c ^+^ r *^ (cos phi *^ u ^+^ sin phi *^ w)
        in conjoin [ counterexample (show k ++ ": " ++ showV3 o ++ " expected " ++ showV3 (expected k)) (vecDist o (expected k) <= 1e-9)
                   | (k, o) <- zip [0 :: Int ..] (polyOutline poly) ]
  describe "directionSector counts the boundaries a direction has passed: the floor of its angle over 2π/nd" $ do
    forM_ [2, 3, 4, 5, 7, 8, 12, 24, 25] $ \nd ->
      it (show nd ++ " directions") $
        property $ withMaxSuccess 2000 $
          forAll (choose (0, 2 * pi)) $ \phi -> forAll (choose (1e-3, 1e3)) $ \r ->
            let sigma = 2 * pi / fromIntegral nd
                x = r * cos phi
                y = r * sin phi
                -- the angle as atan2 gives it, in [0, 2π)
                angle = let a = atan2 y x in if a < 0 then a + 2 * pi else a
                nearBoundary = let f = angle / sigma in abs (f - fromIntegral (round f :: Int)) < 1e-9
                expected = fromIntegral (min (nd - 1) (floor (angle / sigma)) :: Int) :: Double
            in not nearBoundary ==> directionSector (sectors nd) x y === expected
    it "puts the origin, NaN and directions along the x axis in whole sectors" $ do
      directionSector (sectors 24) 0 (0 :: Double) `shouldBe` 0
      directionSector (sectors 24) 1 (0 :: Double) `shouldBe` 0
      directionSector (sectors 24) (-1) (0 :: Double) `shouldSatisfy` (`elem` [11, 12])
      directionSector (sectors 5) (-1) (0 :: Double) `shouldSatisfy` (`elem` [2, 3])
      directionSector (sectors 24) (0 / 0) (1 :: Double) `shouldSatisfy` (\k -> k >= 0 && k <= 23)
    it "refuses sectors of no direction in words" $
      evaluate (directionSector (sectors 0) 1 (1 :: Double)) `shouldThrow` errorCall "sectors: at least one direction, got 0"
  it "polyLocal gives each vertex's (r, θ)" $ do
    let pp = PolygonParams 8 2
        poly = polygonise Euclidean (spaceField plane) pp circle 0.5 (V3 0 0 0) (V3 1 0 0) (0 :: Double)
    polyLocal poly `shouldSatisfy` \ls ->
      and [ closeAbs 1e-12 r (0.5 * fromIntegral j / 2) && closeAbs 1e-12 th (2 * pi * fromIntegral k / 8)
          | (idx, (r, th)) <- zip [0 :: Int ..] ls, idx > 0
          , let k = (idx - 1) `div` 2, let j = (idx - 1) `mod` 2 + 1 ]
  describe "on the unit sphere, a circle of geodesic radius ρ has its outline at great-circle distance ρ (1e-3)" $
    forM_ [(0.1, defaultPolygonParams), (0.2, defaultPolygonParams), (0.3, defaultPolygonParams), (1.0, PolygonParams 36 32), (2.0, PolygonParams 24 64)] $ \(rho, pp) ->
      it (printf "ρ = %.1f, %d directions × %d steps" rho (polyDirections pp) (polySteps pp)) $
        property $ withMaxSuccess 20 $ forAll genUnitV3 $ \c -> forAll (genTangentUnit c) $ \u -> forAll (choose (-3, 3)) $ \angle ->
          let poly = polygonise Euclidean (spaceField sphere) pp circle rho c u angle
              dists = [acos (max (-1) (min 1 (o `dot` c))) | o <- polyOutline poly]
          in counterexample ("distances " ++ show dists) $
               all (closeAbs 1e-3 rho) dists .&&. all ((< 1e-9) . abs . subtract 1 . norm) (polyOutline poly)
