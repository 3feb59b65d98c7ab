{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the torus, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.Torus (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (torus)
-- | The compiled step of 'torus'.
compiled :: CompiledStep
compiled = $(compiledStep torus)
