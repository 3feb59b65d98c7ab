{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the cube, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.Cube (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (cube)
-- | The compiled step of 'cube'.
compiled :: CompiledStep
compiled = $(compiledStep cube)
