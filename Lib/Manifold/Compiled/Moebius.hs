{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the Möbius strip, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.Moebius (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (moebius)
-- | The compiled step of 'moebius'.
compiled :: CompiledStep
compiled = $(compiledStep moebius)
