{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The functions of the compiled step that do not depend on the space (the
-- pair narrow phase, the solver's sweeps, waking and sleeping), spliced
-- once from the plane's step: every space's compiled step whose function
-- is the same staged tree calls this one ("Manifold.Compile").
module Manifold.Compiled.Shared where

import Manifold.Compile (sharedFunctions)

$(sharedFunctions)
