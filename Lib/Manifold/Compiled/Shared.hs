{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The subroutines of the compiled step that do not depend on the space
-- (the pair narrow phase, the solver's preparation and sweep), spliced
-- once: every space's compiled step whose subroutine is the same staged
-- tree calls this one ("Manifold.Compile").
module Manifold.Compiled.Shared where

import Manifold.Compile (sharedSubroutines)

$(sharedSubroutines)
