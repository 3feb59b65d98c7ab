{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the flat Klein bottle, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.FlatKlein (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (flatKlein)
-- | The compiled step of 'flatKlein'.
compiled :: CompiledStep
compiled = $(compiledStep flatKlein)
