-- | The Bolza surface's group (Manifold.Bolza): the octagon's area 4π
-- (Gauss–Bonnet for genus 2) integrated from the Poincaré map's Jacobian;
-- the side pairings as Lorentz matrices carrying each side onto its partner;
-- eight octagons at every corner (the surface is smooth there); the 48
-- touching images; the wrap back into the octagon.
module BolzaSpec (spec) where

import Control.Monad (forM_)
import Linear.V3 (V3 (..))
import Test.Hspec

import Manifold.Bolza
import Manifold.Disc
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
