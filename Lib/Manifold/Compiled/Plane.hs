{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the plane, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.Plane (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (plane)
-- | The compiled step of 'plane'.
compiled :: CompiledStep
compiled = $(compiledStep plane)
