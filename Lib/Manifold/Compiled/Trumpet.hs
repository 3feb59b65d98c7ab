{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the trumpet, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.Trumpet (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (trumpet)
-- | The compiled step of 'trumpet'.
compiled :: CompiledStep
compiled = $(compiledStep trumpet)
