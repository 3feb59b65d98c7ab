{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the flat torus, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.FlatTorus (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (flatTorus)
-- | The compiled step of 'flatTorus'.
compiled :: CompiledStep
compiled = $(compiledStep flatTorus)
