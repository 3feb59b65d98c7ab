{-# LANGUAGE TemplateHaskell #-}
{-# OPTIONS_GHC -O2 -fllvm #-}
-- | The compiled step of the projective plane, spliced from the staged step ("Manifold.Compile").
module Manifold.Compiled.ProjectivePlane (compiled) where
import Manifold.Compile (CompiledStep, compiledStep)
import Manifold.Compiled.Shared ()
import Manifold.Spaces (projectivePlane)
-- | The compiled step of 'projectivePlane'.
compiled :: CompiledStep
compiled = $(compiledStep projectivePlane)
