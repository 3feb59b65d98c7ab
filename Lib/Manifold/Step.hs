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
import Manifold.Field (Field (..))
import Manifold.Joint (prepareJoints)
import Manifold.Sleep (markTouched, sleepIslands, wakeMarked, wakePhase)
import Manifold.Solver
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.World (Layout, Meta (..), WorldArrays, polygoniseAll, readMeta, writeMeta)

step :: Imp m => Space -> Layout -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE step :: Space -> Layout -> WorldArrays NativeArray -> Native () #-}
step sp l w = mapM_ (\(_, phase) -> phase sp l w) stepPhases

-- | The step's phases in order, named, so that a benchmark can time each.
stepPhases :: Imp m => [(String, Space -> Layout -> WorldArrays (Array m) -> m ())]
{-# SPECIALIZE stepPhases :: [(String, Space -> Layout -> WorldArrays NativeArray -> Native ())] #-}
stepPhases =
  [ ("wake", \_ _ w -> wakePhase w)
  , ("collide", collideWaking)
  , ("prepare", \sp _ w -> prepareContacts (spaceMetric sp) w >> prepareJoints sp w)
  , ("substeps", substeps)
  , ("finish", \sp _ w -> finishStep sp w)
  , ("polygonise", polygoniseAll)
    -- after the polygons: a body that falls asleep keeps the outline of
    -- where it came to rest
  , ("sleep", \sp _ w -> sleepIslands (spaceMetric sp) w)
  ]

-- | The contacts ('collide'); where they touch a sleeping island, the
-- island wakes and the contacts are found again, its bodies' own among
-- them, so that the solve moves it with the body that struck it
-- ('markTouched'). A loop of two passes, the second only in a step that
-- woke something: the collision phase's code is printed once.
collideWaking :: Imp m => Space -> Layout -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE collideWaking :: Space -> Layout -> WorldArrays NativeArray -> Native () #-}
collideWaking sp l w = do
  -- the rows dropped for want of room are counted once, by the last pass
  dropped <- readMeta w DroppedContacts >>= newRef
  forEach (toIndex 2) $ \pass -> do
    -- the wake phase left no request; the first pass's touches make one
    requested <- readMeta w WakeRequest
    whenPositive (maxF (0.5 - toScalar pass) requested) $ do
      wakeMarked w
      readRef dropped >>= writeMeta w DroppedContacts
      collide sp l w
      subroutine "markTouched" [] $ \_ -> markTouched w
