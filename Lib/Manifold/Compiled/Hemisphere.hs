{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the hemisphere, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.Hemisphere (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (hemisphere)
-- | The compiled step of 'hemisphere'.
compiled :: CompiledStep
compiled = $(compiledStep hemisphere)
