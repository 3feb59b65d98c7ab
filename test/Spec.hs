-- | The test suite: an explicit main over the specs (no hspec-discover).
module Main (main) where

import System.IO (BufferMode (..), hSetBuffering, stdout)
import Test.Hspec

import qualified ADSpec
import qualified BodySpec
import qualified CliSpec
import qualified SurfaceSpec

main :: IO ()
main = do
  hSetBuffering stdout LineBuffering
  hspec $ do
    describe "Manifold.AD" ADSpec.spec
    describe "Manifold.Surface" SurfaceSpec.spec
    describe "Manifold.Body" BodySpec.spec
    describe "manifold (command line)" CliSpec.spec
