{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the sphere, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.Sphere (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (sphere)
-- | The compiled step of 'sphere'.
compiled :: CompiledStep
compiled = $(compiledStep sphere)
