-- | The hyperbolic plane's flat pictures (Manifold.Disc): the Poincaré and
-- Klein discs' maps against each other and their defining properties (the
-- Poincaré disc conformal with factor 2/(1 − r²), the Klein disc's straight
-- lines geodesics), the translations as Lorentz boosts, a walk there and
-- back, the geodesic grid's lines, and the page's generated copies of all of
-- it (web/gen/spaces.js under node) against the native functions.
module DiscSpec (spec) where

import Control.Monad (forM_)
import qualified Data.Aeson as A
import qualified Data.ByteString.Lazy.Char8 as BL
import Data.List (foldl')
import Linear.V3 (V3 (..))
import Test.Hspec

import Manifold.Disc
import Manifold.Spaces (catalogue)
import Manifold.Stage.Kernels (spaceIndexScript)
import LorentzUtil
import NodeJS

-- | Points of the open unit disc: rings out to radius 0.95, at angles no
-- ring shares.
discPoints :: [(Double, Double)]
discPoints = [ (r * cos a, r * sin a) | k <- [1 .. 19 :: Int], let r = 0.05 * fromIntegral k, j <- [0 .. 6 :: Int], let a = 0.9 * fromIntegral j + 0.37 * fromIntegral k ]

sheet :: V3 Double -> Double
sheet p = minkowski p p + 1

v3 :: V3 a -> [a]
v3 (V3 a b c) = [a, b, c]

spec :: Spec
spec = describe "Manifold.Disc" $ do
  it "the Poincaré and the Klein disc's maps are inverse to their pictures, onto the sheet (1e-12)" $
    forM_ discPoints $ \(u, w) -> do
      let p = fromPoincare u w
          (u', w') = toPoincare p
          q = fromKlein u w
          (u'', w'') = toKlein q
          scale = minkowski p p
      abs (sheet p) / abs scale `shouldSatisfy` (< 1e-12)
      abs (sheet q) / abs (minkowski q q) `shouldSatisfy` (< 1e-12)
      max (abs (u' - u)) (abs (w' - w)) `shouldSatisfy` (< 1e-12)
      max (abs (u'' - u)) (abs (w'' - w)) `shouldSatisfy` (< 1e-12)

  it "the Poincaré disc is conformal: its metric is (2/(1 − r²))² times the disc's (1e-6)" $
    forM_ discPoints $ \(u, w) -> do
      let h = 1e-6
          du = (fromPoincare (u + h) w `minus` fromPoincare (u - h) w) `times` (1 / (2 * h))
          dw = (fromPoincare u (w + h) `minus` fromPoincare u (w - h)) `times` (1 / (2 * h))
          factor = (2 / (1 - u * u - w * w)) ^ (2 :: Int)
      abs (minkowski du du / factor - 1) `shouldSatisfy` (< 1e-6)
      abs (minkowski dw dw / factor - 1) `shouldSatisfy` (< 1e-6)
      abs (minkowski du dw / factor) `shouldSatisfy` (< 1e-6)

  it "the Klein disc's straight lines are geodesics: three points of a chord lie on one plane through the origin" $
    forM_ (zip discPoints (drop 7 discPoints)) $ \((a, b), (c, d)) -> do
      let p = fromKlein a b
          q = fromKlein c d
          r = fromKlein (0.3 * a + 0.7 * c) (0.3 * b + 0.7 * d)
          det (V3 x1 y1 z1) (V3 x2 y2 z2) (V3 x3 y3 z3) = x1 * (y2 * z3 - z2 * y3) - y1 * (x2 * z3 - z2 * x3) + z1 * (x2 * y3 - y2 * x3)
          size = product (map (sqrt . sum . map (^ (2 :: Int)) . v3) [p, q, r])
      abs (det p q r) / size `shouldSatisfy` (< 1e-12)

  it "translationTo p is a Lorentz matrix carrying the vertex to p, and the translation to the opposite point undoes it" $
    forM_ discPoints $ \(u, w) -> do
      let p = fromPoincare u w
          m = translationTo p
          V3 x y z = p
          back = translationTo (V3 (-x) y (-z))
          size = y * y
      lorentzDefect m / size `shouldSatisfy` (< 1e-12)
      maxDiff (v3 (applyBoost m (V3 0 1 0))) (v3 p) / y `shouldSatisfy` (< 1e-14)
      maxDiff (composeBoosts back m) identity / size `shouldSatisfy` (< 1e-12)
      maxDiff (composeBoosts (inverseBoost m) m) identity / size `shouldSatisfy` (< 1e-12)

  it "a walk of 2000 drags, renormalised at each, stays a Lorentz matrix, and the drags back return to the identity (1e-9)" $ do
    -- the pointer's path: a wobbling spiral in the disc, each drag from one of its points to the next
    let at k = let a = 0.05 * fromIntegral (k :: Int); r = 0.5 + 0.4 * sin (0.013 * fromIntegral k) in fromPoincare (r * cos a) (r * sin a)
        drags = [ (at k, at (k + 1)) | k <- [0 .. 1999] ]
        step m (a, b) = renormaliseBoost (composeBoosts (composeBoosts (translationTo b) (inverseBoost (translationTo a))) m)
        there = foldl' step identity drags
        andBack = foldl' step there (reverse [ (b, a) | (a, b) <- drags ])
    lorentzDefect there `shouldSatisfy` (< 1e-12)
    maxDiff andBack identity `shouldSatisfy` (< 1e-9)
    maxDiff there identity `shouldSatisfy` (> 0.1)

  it "a line of the geodesic grid is a geodesic: the geodesic perpendicular to the x axis at distance d has grid coordinate d all along" $
    forM_ [-1.5, -0.25, 0.5, 2 :: Double] $ \d ->
      forM_ [-2, -0.7, 0, 0.4, 1.9 :: Double] $ \s -> do
        -- the point at distance s along the perpendicular through (sinh d, cosh d, 0)
        let p = V3 (sinh d * cosh s) (cosh d * cosh s) (sinh s)
            (g, _) = geodesicGrid p
        abs (g - d) `shouldSatisfy` (< 1e-12)

  it "the page's generated maps (web/gen/spaces.js under node) compute the native values (1e-14 relative)" $ do
    let points = take 40 discPoints
        m = translationTo (fromPoincare 0.31 (-0.52))
        n = translationTo (fromKlein (-0.2) 0.45)
        call f args = "H." ++ f ++ "(" ++ concatMap (\a -> jsDouble a ++ ",") args ++ ")"
        calls = concat
          [ [ call "fromPoincare" [u, w], call "fromKlein" [u, w], call "toPoincare" (v3 (fromPoincare u w))
            , call "toKlein" (v3 (fromKlein u w)), call "translationTo" (v3 (fromPoincare u w)), call "grid" (v3 (fromPoincare u w)) ]
          | (u, w) <- points ]
          ++ [ call "compose" (m ++ n), call "inverse" m, call "renormalise" m, call "apply" (m ++ [0.2, 1.3, -0.4]) ]
        native = concat
          [ [ v3 (fromPoincare u w), v3 (fromKlein u w), pair (toPoincare (fromPoincare u w))
            , pair (toKlein (fromKlein u w)), translationTo (fromPoincare u w), pair (geodesicGrid (fromPoincare u w)) ]
          | (u, w) <- points ]
          ++ [ composeBoosts m n, inverseBoost m, renormaliseBoost m, v3 (applyBoost m (V3 0.2 1.3 (-0.4))) ]
        pair (a, b) = [a, b]
        script = "require('vm').runInThisContext(" ++ BL.unpack (A.encode (spaceIndexScript catalogue)) ++ ");\n"
          ++ "const H = globalThis.Manifold.hyperbolic;\n__emit([" ++ concatMap (++ ",") calls ++ "]);\n"
    out <- runNodeJSON script :: IO [[Bits]]
    length out `shouldBe` length native
    forM_ (zip out native) $ \(js, hs) ->
      maximum (zipWith (\(Bits a) b -> abs (a - b) / max 1 (abs b)) js hs) `shouldSatisfy` (< 1e-14)
  where
    minus (V3 a b c) (V3 d e f) = V3 (a - d) (b - e) (c - f)
    times (V3 a b c) k = V3 (k * a) (k * b) (k * c)
