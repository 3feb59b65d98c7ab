-- | The test suite: an explicit main over the specs (no hspec-discover).
module Main (main) where

import System.IO (BufferMode (..), hSetBuffering, stdout)
import Test.Hspec

import qualified ADSpec
import qualified AnchorSpec
import qualified ElementarySpec
import qualified BodySpec
import qualified CliSpec
import qualified ContactManifoldSpec
import qualified DiscSpec
import qualified BolzaSpec
import qualified EngineSpec
import qualified FlatSpec
import qualified GeodesicPathSpec
import qualified GoldenSpec
import qualified HullSpec
import qualified ImpSpec
import qualified MeasuresSpec
import qualified MetricSpec
import qualified PhysicsSpec
import qualified PresetSpec
import qualified ReadmeExampleSpec
import qualified SolverSpec
import qualified JointSpec
import qualified SleepSpec
import qualified StageSpec
import qualified SurfaceSpec

main :: IO ()
main = do
  hSetBuffering stdout LineBuffering
  hspec $
    -- (parallel: the examples are independent, each its own world, node
    -- process or temporary directory; most wait on one core, so two run
    -- at once on the machine's two; hspec reports them in this order. The
    -- longest (the golden runs, the page's allocation guard) come first, so
    -- that the short ones fill the second core beside them rather than
    -- leave it idle at the end.)
    parallel $ do
      GoldenSpec.spec
      -- the allocation guards (alone: cabal test --test-options='-m performance')
      describe "performance" EngineSpec.performanceSpec
      describe "Manifold.AD" ADSpec.spec
      describe "Manifold.Elementary" ElementarySpec.spec
      describe "Manifold.Surface" SurfaceSpec.spec
      MetricSpec.spec
      DiscSpec.spec
      BolzaSpec.spec
      describe "Manifold.GeodesicPath" GeodesicPathSpec.spec
      PresetSpec.spec
      MeasuresSpec.spec
      describe "Manifold.Body" BodySpec.spec
      describe "manifold (command line)" CliSpec.spec
      describe "Manifold.World" EngineSpec.spec
      describe "Manifold.Stage" StageSpec.spec
      describe "Manifold.Stage.Imp" ImpSpec.spec
      ContactManifoldSpec.spec
      HullSpec.spec
      describe "Physics" PhysicsSpec.spec
      describe "Solver" SolverSpec.spec
      AnchorSpec.spec
      describe "Joint" JointSpec.spec
      describe "Sleep" SleepSpec.spec
      FlatSpec.spec
      ReadmeExampleSpec.spec
