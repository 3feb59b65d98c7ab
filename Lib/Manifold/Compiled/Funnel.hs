{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the funnel, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.Funnel (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (funnel)
-- | The compiled step of 'funnel'.
compiled :: CompiledStep
compiled = $(compiledStep funnel)
