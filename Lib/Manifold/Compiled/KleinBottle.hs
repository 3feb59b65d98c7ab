{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the Klein bottle, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.KleinBottle (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (kleinBottle)
-- | The compiled step of 'kleinBottle'.
compiled :: CompiledStep
compiled = $(compiledStep kleinBottle)
