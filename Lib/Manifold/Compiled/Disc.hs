{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the disc, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.Disc (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (disc)
-- | The compiled step of 'disc'.
compiled :: CompiledStep
compiled = $(compiledStep disc)
