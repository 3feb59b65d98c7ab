{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the hyperbolic plane, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.HyperbolicPlane (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (hyperbolicPlane)
-- | The compiled step of 'hyperbolicPlane'.
compiled :: CompiledStep
compiled = $(compiledStep hyperbolicPlane)
