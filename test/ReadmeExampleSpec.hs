-- | The README's worked example ("Adding a space") compiles and works: the
-- definition below is checked to stand, line for line, in README.md.
module ReadmeExampleSpec (spec) where

import Data.Char (isSpace)
import Data.List (isInfixOf)
import Linear.V3 (V3 (..))
import Test.Hspec

import Manifold

-- README: from here
bowl :: Space
bowl = (space "bowl" "the paraboloid y = x² + z², up to y = 1" (scalarFn bowlField))
  { spaceBoundary = Just (scalarFn (\(V3 _ y _) -> 1 - y))
  , spaceGravity  = uniformGravity (V3 0 (-4) 0)
  , spaceScene    = [Placement (V3 0.3 0.1 0) SquareShape 0.15 False]
  }
  where
    -- a field, not a distance: the engine only needs f/|∇f| near the surface
    bowlField (V3 x y z) = (x * x + z * z - y) / sqrt (1 + 4 * (x * x + z * z))
-- README: to here

spec :: Spec
spec = describe "the README's worked example" $ do
  it "is the code above, line for line" $ do
    readme <- readFile "README.md"
    source <- readFile "test/ReadmeExampleSpec.hs"
    let block = takeWhile (/= "-- README: to here") (drop 1 (dropWhile (/= "-- README: from here") (lines source)))
        trimEnd = reverse . dropWhile isSpace . reverse
    length block `shouldSatisfy` (> 5)
    mapM_ (\l -> (trimEnd l, trimEnd l `isInfixOf` readme) `shouldBe` (trimEnd l, True)) block

  it "makes a working space: projection, curvature 4 at the vertex, boundary" $ do
    let f = spaceField bowl
        p = projectToSurface f (V3 0.3 0.5 0 :: V3 Double)
    abs (evalField bowl p) `shouldSatisfy` (< 1e-12)
    abs (gaussianCurvature f (V3 0 0 0 :: V3 Double) - 4) `shouldSatisfy` (< 1e-12)
    evalBoundary bowl (V3 0 2 0 :: V3 Double) `shouldSatisfy` (< 0)
