{-# LANGUAGE FlexibleContexts #-}
-- | One step of the world (paper §2.4–2.6): gravity, contacts, impulses,
-- motion, polygons. Written once; run natively and printed as JavaScript.
module Manifold.Step
  ( step
  , stepPhases
  ) where

import Manifold.Collide
import Manifold.Solver
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.World

step :: Imp m => Space -> Layout -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE step :: Space -> Layout -> WorldArrays NativeArray -> Native () #-}
step sp l w = mapM_ (\(_, phase) -> phase sp l w) stepPhases

-- | The step's phases in order, named, so that a benchmark can time each.
stepPhases :: Imp m => [(String, Space -> Layout -> WorldArrays (Array m) -> m ())]
{-# SPECIALIZE stepPhases :: [(String, Space -> Layout -> WorldArrays NativeArray -> Native ())] #-}
stepPhases =
  [ ("gravity", \sp _ w -> applyGravity sp w)
  , ("collide", collide)
  , ("solve", solve)
  , ("integrate", \sp _ w -> integrate sp w)
  , ("polygonise", polygoniseAll)
  ]
