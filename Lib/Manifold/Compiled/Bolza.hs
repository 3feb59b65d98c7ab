{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the Bolza surface, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.Bolza (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (bolza)
-- | The compiled step of 'bolza'.
compiled :: CompiledStep
compiled = $(compiledStep bolza)
