{-# LANGUAGE FlexibleContexts #-}
-- | One step of the world (paper §2.4–2.6): the islands that wake, the
-- contacts, then the solver's sub-steps (gravity, impulses, motion), then
-- the polygons, then the islands that have come to rest fall asleep. Written once;
-- run natively and printed as JavaScript.
module Manifold.Step
  ( step
  , stepPhases
  ) where

import Manifold.Collide
import Manifold.Joint (prepareJoints)
import Manifold.Sleep (sleepIslands, wakePhase)
import Manifold.Solver
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.World (Layout, WorldArrays, polygoniseAll)

step :: Imp m => Space -> Layout -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE step :: Space -> Layout -> WorldArrays NativeArray -> Native () #-}
step sp l w = mapM_ (\(_, phase) -> phase sp l w) stepPhases

-- | The step's phases in order, named, so that a benchmark can time each.
stepPhases :: Imp m => [(String, Space -> Layout -> WorldArrays (Array m) -> m ())]
{-# SPECIALIZE stepPhases :: [(String, Space -> Layout -> WorldArrays NativeArray -> Native ())] #-}
stepPhases =
  [ ("wake", \_ _ w -> wakePhase w)
  , ("collide", collide)
  , ("prepare", \sp _ w -> prepareContacts (spaceMetric sp) w >> prepareJoints sp w)
  , ("substeps", substeps)
  , ("finish", \sp _ w -> finishStep sp w)
  , ("polygonise", polygoniseAll)
    -- after the polygons: a body that falls asleep keeps the outline of
    -- where it came to rest
  , ("sleep", \sp _ w -> sleepIslands (spaceMetric sp) w)
  ]
