-- | Forward AD against hand-written derivatives and finite differences, the
-- nested-dual Hessian, and the curvatures built on it.
module ADSpec (spec) where

import Linear.Matrix (M33, (!*))
import Data.List (isInfixOf)
import Control.Monad (forM_)
import Linear.Metric (dot, norm, quadrance)
import Linear.V3 (V3 (..))
import Linear.Vector ((*^))
import Test.Hspec
import Test.QuickCheck

import Manifold
import TestUtil

spec :: Spec
spec = do
  elementarySpec
  spaceGradientSpec
  hessianSpec
  curvatureSpec

-- Elementary functions ----------------------------------------------------------

-- | A unary function with its first and second derivatives written by hand,
-- and a domain where both are finite and well conditioned.
data Unary = Unary
  { uName :: String
  , uFn :: forall a. Field a => a -> a
  , uD1 :: Double -> Double
  , uD2 :: Double -> Double
  , uDom :: (Double, Double)
  }

sech2 :: Double -> Double
sech2 u = 1 / (cosh u * cosh u)

unaries :: [Unary]
unaries =
  [ Unary "sqrt" sqrt (\u -> 0.5 / sqrt u) (\u -> -0.25 / (u * sqrt u)) (0.05, 4)
  , Unary "exp" exp exp exp (-3, 3)
  , Unary "log" log recip (\u -> -1 / (u * u)) (0.05, 5)
  , Unary "sin" sin cos (negate . sin) (-6, 6)
  , Unary "cos" cos (negate . sin) (negate . cos) (-6, 6)
  , Unary "tan" tan (\u -> 1 + tan u ^ (2 :: Int)) (\u -> 2 * tan u * (1 + tan u ^ (2 :: Int))) (-1.4, 1.4)
  , Unary "asin" asin (\u -> 1 / sqrt (1 - u * u)) (\u -> u / (1 - u * u) ** 1.5) (-0.95, 0.95)
  , Unary "acos" acos (\u -> -1 / sqrt (1 - u * u)) (\u -> -u / (1 - u * u) ** 1.5) (-0.95, 0.95)
  , Unary "atan" atan (\u -> 1 / (1 + u * u)) (\u -> -2 * u / (1 + u * u) ^ (2 :: Int)) (-5, 5)
  , Unary "sinh" sinh cosh sinh (-3, 3)
  , Unary "cosh" cosh sinh cosh (-3, 3)
  , Unary "tanh" tanh sech2 (\u -> -2 * tanh u * sech2 u) (-3, 3)
  , Unary "abs (positive side)" abs (const 1) (const 0) (0.01, 3)
  , Unary "abs (negative side)" abs (const (-1)) (const 0) (-3, -0.01)
  , Unary "recip" recip (\u -> -1 / (u * u)) (\u -> 2 / (u * u * u)) (0.2, 4)
  , Unary "x ** 3 (constant exponent)" (** 3) (\u -> 3 * u * u) (6 *) (0.1, 3)
  , Unary "asinh" asinh (\u -> 1 / sqrt (u * u + 1)) (\u -> -u / (u * u + 1) ** 1.5) (-3, 3)
  , Unary "acosh" acosh (\u -> 1 / sqrt (u * u - 1)) (\u -> -u / (u * u - 1) ** 1.5) (1.1, 4)
  , Unary "atanh" atanh (\u -> 1 / (1 - u * u)) (\u -> 2 * u / (1 - u * u) ^ (2 :: Int)) (-0.9, 0.9)
  ]

-- | A binary function with its two partial derivatives written by hand and
-- the domains of its two arguments.
data Binary = Binary
  { bName :: String
  , bFn :: forall a. Field a => a -> a -> a
  , bD :: Double -> Double -> (Double, Double)
  , bDomU :: (Double, Double)
  , bDomV :: (Double, Double)
  }

binaries :: [Binary]
binaries =
  [ Binary "+" (+) (\_ _ -> (1, 1)) (-3, 3) (-3, 3)
  , Binary "-" (-) (\_ _ -> (1, -1)) (-3, 3) (-3, 3)
  , Binary "*" (*) (\u v -> (v, u)) (-3, 3) (-3, 3)
  , Binary "/ (positive denominator)" (/) (\u v -> (1 / v, -u / (v * v))) (-3, 3) (0.3, 3)
  , Binary "/ (negative denominator)" (/) (\u v -> (1 / v, -u / (v * v))) (-3, 3) (-3, -0.3)
  , Binary "**" (**) (\u v -> (v * u ** (v - 1), u ** v * log u)) (0.2, 3) (-2, 2)
  , Binary "minF" minF (\u v -> if u < v then (1, 0) else (0, 1)) (-3, 3) (-3, 3)
  , Binary "maxF" maxF (\u v -> if u > v then (1, 0) else (0, 1)) (-3, 3) (-3, 3)
  , Binary "logBase" logBase (\u v -> (-log v / (u * log u ^ (2 :: Int)), 1 / (v * log u))) (1.5, 4) (0.2, 4)
  ]

-- | @u(p) = a·p + c@ as a function of any scalar.
linearAt :: Field b => V3 Double -> Double -> V3 b -> b
linearAt a c q = dot (fmap constant a) q + constant c

scaleM :: Double -> M33 Double -> M33 Double
scaleM k = fmap (fmap (* k))

outer :: V3 Double -> V3 Double -> M33 Double
outer a b = fmap (*^ b) a

-- | A point, a coefficient vector and an offset such that the linear function
-- takes a value of the given interval at the point.
genLinear :: (Double, Double) -> V3 Double -> Gen (V3 Double, Double, Double)
genLinear dom p = do
  a <- genV3In 1.5
  u0 <- choose dom
  pure (a, u0 - dot a p, u0)

vecClose :: Double -> V3 Double -> V3 Double -> Bool
vecClose tol expected got = vecDist expected got <= tol * max 1 (norm expected)

matClose :: Double -> M33 Double -> M33 Double -> Bool
matClose tol expected got = matDist expected got <= tol * max 1 (maximum (fmap maxAbsV expected))

elementarySpec :: Spec
elementarySpec = describe "grad and hessian of elementary functions (against hand-written derivatives)" $ do
  mapM_ unaryCase unaries
  mapM_ binaryCase binaries

  it "abs has derivative 0 at 0 (signum 0 = 0)" $ do
    grad (\(V3 x _ _) -> abs x) (V3 0 0.3 (-2 :: Double)) `shouldBe` V3 0 0 0
    grad (\(V3 x y _) -> abs (x - y)) (V3 0.7 0.7 (1 :: Double)) `shouldBe` V3 0 0 0
  it "abs away from 0 has derivative ±1" $ do
    grad (\(V3 x _ _) -> abs x) (V3 (-0.5) 0 (0 :: Double)) `shouldBe` V3 (-1) 0 0
    grad (\(V3 x _ _) -> abs x) (V3 0.5 0 (0 :: Double)) `shouldBe` V3 1 0 0
  it "minF and maxF at a tie take the second argument's derivative (select chooses e when c = 0)" $ do
    grad (\(V3 x y _) -> minF x y) (V3 0.4 0.4 (0 :: Double)) `shouldBe` V3 0 1 0
    grad (\(V3 x y _) -> maxF x y) (V3 0.4 0.4 (0 :: Double)) `shouldBe` V3 0 1 0
  it "minF and maxF take the chosen branch's derivative" $ do
    grad (\(V3 x y _) -> minF (2 * x) (3 * y)) (V3 0.1 0.5 (0 :: Double)) `shouldBe` V3 2 0 0
    grad (\(V3 x y _) -> minF (2 * x) (3 * y)) (V3 0.9 0.1 (0 :: Double)) `shouldBe` V3 0 3 0
    grad (\(V3 x y _) -> maxF (2 * x) (3 * y)) (V3 0.1 0.5 (0 :: Double)) `shouldBe` V3 0 3 0
    grad (\(V3 x y _) -> maxF (2 * x) (3 * y)) (V3 0.9 0.1 (0 :: Double)) `shouldBe` V3 2 0 0
  it "valueAndGrad and secondOrder agree with grad and hessian" $
    property $ withMaxSuccess 100 $ forAll (genV3In 2) $ \p ->
      let f :: Field b => V3 b -> b
          f (V3 x y z) = sin (x * y) + exp z * cos x - x * y * z
          (v, g) = valueAndGrad f p
          (g2, h2) = secondOrder (scalarFn f) p
      in v == f p && g == grad f p && g2 == g && h2 == hessian f p
  where
    unaryCase u = it ("d/dx " ++ uName u) $
      property $ withMaxSuccess 200 $
        forAll (genV3In 2) $ \p -> forAll (genLinear (uDom u) p) $ \(a, c, _) ->
          let fn :: Field b => V3 b -> b
              fn q = uFn u (linearAt a c q)
              up = linearAt a c p
              g = grad fn p
              h = hessian fn p
              g' = uD1 u up *^ a
              h' = scaleM (uD2 u up) (outer a a)
          in counterexample ("u(p) = " ++ show up ++ ", grad " ++ showV3 g ++ " expected " ++ showV3 g'
                             ++ "\nhessian " ++ show h ++ " expected " ++ show h') $
               vecClose 1e-10 g' g .&&. matClose 1e-9 h' h .&&. fn p == uFn u up
    binaryCase b = it ("partial derivatives of " ++ bName b) $
      property $ withMaxSuccess 200 $
        forAll (genV3In 2) $ \p ->
        forAll (genLinear (bDomU b) p) $ \(a, c, _) ->
        forAll (genLinear (bDomV b) p) $ \(a2, c2, _) ->
          let fn :: Field x => V3 x -> x
              fn q = bFn b (linearAt a c q) (linearAt a2 c2 q)
              up = linearAt a c p
              vp = linearAt a2 c2 p
              (du, dv) = bD b up vp
              g = grad fn p
              g' = du *^ a + dv *^ a2
          in abs (up - vp) > 1e-6 ==>
               counterexample ("u = " ++ show up ++ ", v = " ++ show vp ++ ", grad " ++ showV3 g
                               ++ " expected " ++ showV3 g') $
                 vecClose 1e-10 g' g

-- Fields of the catalogue --------------------------------------------------------

-- | Hand-written gradients of four fields.
analyticGradients :: [(Space, String, V3 Double -> Bool, V3 Double -> V3 Double)]
analyticGradients =
  [ (plane, "(0, 1, 0)", const True, const (V3 0 1 0))
  , (sphere, "p / |p|", \p -> norm p > 0.05, \p -> (1 / norm p) *^ p)
  , (torus, "((q/d) x/ρ, y/d, (q/d) z/ρ), ρ = √(x²+z²), q = ρ − R, d = √(q²+y²)"
    , \(V3 x y z) -> let rho = sqrt (x * x + z * z); q = rho - torusMajor in rho > 0.05 && sqrt (q * q + y * y) > 0.05
    , \(V3 x y z) ->
        let rho = sqrt (x * x + z * z)
            q = rho - torusMajor
            d = sqrt (q * q + y * y)
        in V3 (q / d * x / rho) (y / d) (q / d * z / rho))
  , (trumpet, "(x/ρ, −e^y, z/ρ)", \(V3 x _ z) -> sqrt (x * x + z * z) > 0.05
    , \(V3 x y z) -> let rho = sqrt (x * x + z * z) in V3 (x / rho) (negate (exp y)) (z / rho))
  ]

-- | Tolerances of the finite-difference comparisons.
fdH1, fdH2 :: Double
fdH1 = 1e-4
fdH2 = 1e-5

spaceGradientSpec :: Spec
spaceGradientSpec = describe "grad of the fields of the catalogue" $ do
  describe "against hand-written gradients" $
    mapM_ (\(s, formula, ok, g) -> it (spaceName s ++ ": ∇f = " ++ formula) $
      property $ withMaxSuccess 200 $ forAll (genV3In 2) $ \p ->
        ok p ==>
          let ad = gradAt s p
          in counterexample ("AD " ++ showV3 ad ++ " analytic " ++ showV3 (g p)) (vecClose 1e-12 (g p) ad))
      analyticGradients
  describe "against central finite differences within 0.2 of the surface" $
    mapM_ (\s -> it (spaceName s ++ " (surface points: " ++ samplerDomain (surfaceSampler s) ++ ")") $
      property $ withMaxSuccess 200 $ forAll (genNearSurfacePoint 0.2 s) $ \p ->
        let f = fieldAt s
            fd1 = fdGrad fdH1 f p
            fd2 = fdGrad fdH2 f p
            ad = gradAt s p
            stable = and (fdStable 1e-6 <$> fd1 <*> fd2)
        in (stable && norm fd2 > 1e-3) ==>
             counterexample ("p = " ++ showV3 p ++ ": AD " ++ showV3 ad ++ ", FD " ++ showV3 fd2) $
               vecDist ad fd2 <= 1e-5 * norm fd2)
      catalogue

-- Hessian --------------------------------------------------------------------------

hessianSpec :: Spec
hessianSpec = describe "hessian" $ do
  describe "against finite differences of grad within 0.2 of the surface" $
    mapM_ (\s -> it (spaceName s) $
      property $ withMaxSuccess 200 $ forAll (genNearSurfacePoint 0.2 s) $ \p ->
        let h = hessian (fieldFn s) p
            fd1 = fdHessianOfGrad fdH1 (gradAt s) p
            fd2 = fdHessianOfGrad fdH2 (gradAt s) p
            scale = max 1 (maximum (fmap maxAbsV fd2))
            stable = matDist fd1 fd2 <= 1e-6 * scale
        in stable ==>
             counterexample ("p = " ++ showV3 p ++ "\nAD " ++ show h ++ "\nFD " ++ show fd2) $
               matDist h fd2 <= 1e-5 * scale)
      catalogue
  it "of an elementary mixture, against finite differences of grad" $
    property $ withMaxSuccess 200 $ forAll (genV3In 1.5) $ \p ->
      let f :: Field b => V3 b -> b
          f (V3 x y z) = sin (x * y) * exp (0.5 * z) + sqrt (1 + x * x + y * y) / (2 + cos z) + atan (x - z) ^ (2 :: Int)
          h = hessian f p
          fd = fdHessianOfGrad fdH2 (grad f) p
      in counterexample ("AD " ++ show h ++ "\nFD " ++ show fd) (matDist h fd <= 1e-6)
  it "of the sphere field is (I − n nᵀ)/|p|" $
    property $ withMaxSuccess 200 $ forAll (genV3In 2) $ \p ->
      norm p > 0.1 ==>
        let n = (1 / norm p) *^ p
            expected = scaleM (1 / norm p) (identity3 - outer n n)
        in matClose 1e-12 expected (hessian (fieldFn sphere) p)
  it "of the trumpet field is [[z²/ρ³, 0, −xz/ρ³], [0, −e^y, 0], [−xz/ρ³, 0, x²/ρ³]]" $
    property $ withMaxSuccess 200 $ forAll (genV3In 2) $ \p@(V3 x y z) ->
      let rho = sqrt (x * x + z * z)
          r3 = rho ^ (3 :: Int)
          expected = V3 (V3 (z * z / r3) 0 (-x * z / r3)) (V3 0 (-exp y) 0) (V3 (-x * z / r3) 0 (x * x / r3))
      in rho > 0.1 ==> matClose 1e-11 expected (hessian (fieldFn trumpet) p)
  where identity3 = V3 (V3 1 0 0) (V3 0 1 0) (V3 0 0 1)

-- Curvature ---------------------------------------------------------------------------

curvatureSpec :: Spec
curvatureSpec = describe "curvature from the Hessian" $ do
  let sf = spaceField sphere
      tf = spaceField torus
      pf = spaceField plane
      bigR = torusMajor
      r = torusMinor
  it "unit sphere: K = 1 and H = 1 on the surface" $
    property $ withMaxSuccess 200 $ forAll genUnitV3 $ \p ->
      let k = gaussianCurvature sf p
          h = meanCurvature sf p
      in counterexample ("K = " ++ show k ++ ", H = " ++ show h) $
           closeAbs 1e-9 1 k .&&. closeAbs 1e-9 1 h
  it "sphere field off the surface: the level set |p| = ρ has K = 1/ρ², H = 1/ρ" $
    property $ withMaxSuccess 200 $ forAll genUnitV3 $ \u -> forAll (choose (0.3, 3)) $ \rho ->
      let p = rho *^ u
      in closeRel 1e-9 (1 / (rho * rho)) (gaussianCurvature sf p)
           .&&. closeRel 1e-9 (1 / rho) (meanCurvature sf p)
  it "torus (R = 0.8, r = 0.5): K = cos φ / (r (R + r cos φ))" $
    property $ withMaxSuccess 200 $ forAll genTorusAngles $ \(phi, psi) ->
      let p = torusPoint phi psi
          expected = cos phi / (r * (bigR + r * cos phi))
          k = gaussianCurvature tf p
      in counterexample ("φ = " ++ show phi ++ ": K = " ++ show k ++ ", expected " ++ show expected) $
           abs (k - expected) <= 1e-9 * max 1 (abs expected)
  it "torus: H = (R + 2r cos φ) / (2r (R + r cos φ))" $
    property $ withMaxSuccess 200 $ forAll genTorusAngles $ \(phi, psi) ->
      let p = torusPoint phi psi
          expected = (bigR + 2 * r * cos phi) / (2 * r * (bigR + r * cos phi))
          h = meanCurvature tf p
      in counterexample ("φ = " ++ show phi ++ ": H = " ++ show h ++ ", expected " ++ show expected) $
           abs (h - expected) <= 1e-9 * max 1 (abs expected)
  it "torus: K is positive outside (φ = 0) and negative inside (φ = π)" $ do
    gaussianCurvature tf (torusPoint 0 0.3) `shouldSatisfy` (> 0)
    gaussianCurvature tf (torusPoint pi 0.3) `shouldSatisfy` (< 0)
  it "the torus's field vanishes on the torus of radii R = torusMajor, r = torusMinor about the y axis (the parametrisation the formulas above use), the radii its description gives" $ do
    spaceDescription torus `shouldSatisfy` isInfixOf ("R = " ++ show torusMajor ++ ", r = " ++ show torusMinor)
    forM_ [(0, 0), (1, 2), (2.5, 4), (4, 1)] $ \(phi, psi) -> do
      abs (evalField torus (torusPoint phi psi)) `shouldSatisfy` (< 1e-12)
      -- and not on a torus of other radii
      let rho = bigR + 1.1 * r * cos phi
      abs (evalField torus (V3 (rho * cos psi) (1.1 * r * sin phi) (rho * sin psi))) `shouldSatisfy` (> 1e-3)
  it "a field without unit gradient, |p|² − 1: K = 1 and H = 1 on the unit sphere" $
    property $ withMaxSuccess 200 $ forAll genUnitV3 $ \p ->
      let f = scalarFn (\q -> 3 * (quadrance q - 1))
      in closeAbs 1e-9 1 (gaussianCurvature f p) .&&. closeAbs 1e-9 1 (meanCurvature f p)
  it "trumpet ρ = e^y: K = −1/(1 + e^{2y})², H = ½(1/(e^y √(1+e^{2y})) − e^y/(1+e^{2y})^{3/2})" $
    property $ withMaxSuccess 200 $ forAll (choose (-1.5, 1.5)) $ \y -> forAll (choose (0, 2 * pi)) $ \t ->
      let r0 = exp y
          p = V3 (r0 * cos t) y (r0 * sin t)
          e2 = exp (2 * y)
          kExp = -1 / (1 + e2) ^ (2 :: Int)
          hExp = 0.5 * (1 / (r0 * sqrt (1 + e2)) - r0 / (1 + e2) ** 1.5)
          k = gaussianCurvature (spaceField trumpet) p
          h = meanCurvature (spaceField trumpet) p
      in counterexample ("y = " ++ show y ++ ": K = " ++ show k ++ " (expected " ++ show kExp ++ "), H = "
                         ++ show h ++ " (expected " ++ show hExp ++ ")") $
           closeAbs 1e-9 kExp k .&&. closeAbs 1e-9 hExp h
  it "plane: K = 0 and H = 0" $
    property $ withMaxSuccess 200 $ forAll (genV3In 3) $ \p ->
      gaussianCurvature pf p == 0 .&&. meanCurvature pf p == 0
  it "adjugate satisfies A · adj A = det A · I" $
    property $ withMaxSuccess 200 $ forAll (V3 <$> genV3In 2 <*> genV3In 2 <*> genV3In 2) $ \m ->
      let V3 r0 r1 r2 = m
          det = r0 `dot` crossV r1 r2
          prod = fmap (\row -> adjugate m `transposeMul` row) m
      in matDist prod (fmap (fmap (* det)) (V3 (V3 1 0 0) (V3 0 1 0) (V3 0 0 1))) <= 1e-10
  where
    crossV (V3 a b c) (V3 d e f) = V3 (b * f - c * e) (c * d - a * f) (a * e - b * d)
    -- (row of A) · adj A, as a row: (adj Aᵀ) !* row
    transposeMul adj row = transposeM adj !* row
    transposeM (V3 (V3 a b c) (V3 d e f) (V3 g h i)) = V3 (V3 a d g) (V3 b e h) (V3 c f i)
