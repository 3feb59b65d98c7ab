-- | The documentation's worked example (docs/spaces.md, "Adding a space")
-- compiles and works: the bowl of "Bowl" and its compiled step of
-- "BowlStep" stand in docs/spaces.md as they are in those modules, each as
-- one block of consecutive lines.
module ReadmeExampleSpec (spec) where

import Control.Monad (forM_, replicateM_)
import Data.Char (isSpace)
import Data.List (isInfixOf)
import qualified Data.Vector.Unboxed as V
import Linear.V3 (V3 (..))
import Test.Hspec

import Bowl (bowl)
import BowlStep (bowlStep)
import Manifold
import Manifold.Engine
import Manifold.World

-- | The lines of a file between its markers ("-- README: from here" …).
readmeBlock :: FilePath -> IO [String]
readmeBlock path = do
  source <- readFile path
  pure (takeWhile (/= "-- README: to here") (drop 1 (dropWhile (/= "-- README: from here") (lines source))))

trimEnd :: String -> String
trimEnd = reverse . dropWhile isSpace . reverse

spec :: Spec
spec = describe "the worked example of adding a space (docs/spaces.md)" $ do
  it "is the code of test/Bowl.hs and test/BowlStep.hs, each block's lines one after another" $ do
    readme <- map trimEnd . lines <$> readFile "docs/spaces.md"
    forM_ ["test/Bowl.hs", "test/BowlStep.hs"] $ \path -> do
      block <- map trimEnd <$> readmeBlock path
      length block `shouldSatisfy` (> 3)
      (path, block `isInfixOf` readme) `shouldBe` (path, True)

  it "makes a working space: projection, curvature 4 at the vertex, boundary" $ do
    let f = spaceField bowl
        p = projectToSurface f (V3 0.3 0.5 0 :: V3 Double)
    abs (evalField bowl p) `shouldSatisfy` (< 1e-12)
    abs (gaussianCurvature f (V3 0 0 0 :: V3 Double) - 4) `shouldSatisfy` (< 1e-12)
    evalBoundary bowl (V3 0 2 0 :: V3 Double) `shouldSatisfy` (< 0)

  it "gets its compiled step from the one splice, which moves its bodies as the generic step does (200 steps)" $ do
    let world = do
          w <- newWorldUsing [bowlStep] bowl (layout 16)
          forM_ (zip [0 :: Int ..] [V3 0.3 0.1 0, V3 (-0.2) 0.05 0.1, V3 0 0.02 (-0.3)]) $ \(k, p) ->
            addBody w (BodyInit (if even k then square else circle) 0.1 1 False p (V3 0.2 0 0.1) 0 1 sceneMaterial) >>= either fail (const (pure ()))
          pure w
    compiled <- world
    generic <- genericStep <$> world
    (usesCompiledStep compiled, usesCompiledStep generic) `shouldBe` (True, False)
    -- not for another space, though its name were the bowl's
    other <- newWorldUsing [bowlStep] (bowl { spaceGravity = uniformGravity (V3 0 (-1) 0) }) (layout 16)
    usesCompiledStep other `shouldBe` False
    replicateM_ 200 (stepNative compiled >> stepNative generic)
    let positions :: NativeWorld -> IO (V.Vector Double)
        positions w = V.freeze (wPos (nwArrays w))
    a <- positions compiled
    b <- positions generic
    start <- world >>= positions
    V.maximum (V.zipWith (\x y -> abs (x - y)) a b) `shouldSatisfy` (< 1e-9)
    -- and they moved
    V.maximum (V.zipWith (\x y -> abs (x - y)) a start) `shouldSatisfy` (> 1e-2)
