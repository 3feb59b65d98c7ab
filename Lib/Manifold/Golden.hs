-- | The golden runs: the catalogue's scenes, each run for a number of steps
-- and fingerprinted by the hash of its final state ("Manifold.StateHash").
-- The test suite keeps their hashes (@test/golden/hashes@, which
-- @manifold hashes@ prints and @scripts/regolden@ rewrites) and checks
-- that the compiled native step, the generic one and the page's engine
-- all end on them: a change to the physics changes a hash, and never
-- passes unnoticed.
module Manifold.Golden
  ( GoldenRun (..)
  , goldenRuns
  , defaultScene
  , runHash
  , goldenLine
  ) where

import Control.Monad (replicateM_)
import Data.Word (Word64)
import Linear.V3 (V3 (..))

import Manifold.Bench (benchScene, benchSpaces)
import Manifold.Engine
import Manifold.Scene
import Manifold.Space
import Manifold.Spaces (catalogue)
import Manifold.StateHash (showHash)

-- | A scene, its name (a file name: @SPACE-default@, @SPACE-N@) and how
-- many steps it runs.
data GoldenRun = GoldenRun
  { grName :: String
  , grScene :: Scene
  , grSteps :: Int
  }

-- | Every catalogue space's default scene (what the page starts with: its
-- bodies at rest, falling), 1000 steps; the benchmark piles of 300 bodies
-- on the benchmark spaces, 600 steps (as they fall and pile up, contacts
-- at every step), and of 1000 bodies, 200 steps.
goldenRuns :: [GoldenRun]
goldenRuns =
  [GoldenRun (spaceName sp ++ "-default") (defaultScene sp) 1000 | sp <- catalogue]
    ++ [ GoldenRun (spaceName sp ++ "-" ++ show n) (benchScene sp n) steps
       | (n, steps) <- [(300, 600), (1000, 200)], sp <- benchSpaces ]

-- | A space's default scene ('spaceScene') with the default parameters.
defaultScene :: Space -> Scene
defaultScene sp =
  Scene sp defaultParams
    [ BodySpec (placeShape pl) (placeSize pl) 1 (placeStatic pl) (placeAt pl) (V3 0 0 0) 0 0 Nothing []
    | pl <- spaceScene sp ]

-- | The hash after @steps@ steps of the scene natively: by the generic step
-- when asked (else by the space's compiled one, where it has one).
runHash :: Bool -> Int -> Scene -> IO (Either String Word64)
runHash generic steps scene = do
  loaded <- loadScene 0 scene
  case loaded of
    Left e -> pure (Left e)
    Right w0 -> do
      let w = if generic then genericStep w0 else w0
      replicateM_ steps (stepNative w)
      Right <$> stateHash w

-- | A line of the golden file: the run's name, its steps and the hash.
goldenLine :: GoldenRun -> Word64 -> String
goldenLine run h = unwords [grName run, show (grSteps run), showHash h]
