{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the rectangle, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.Rectangle (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (rectangle)
-- | The compiled step of 'rectangle'.
compiled :: CompiledStep
compiled = $(compiledStep rectangle)
