{-# LANGUAGE TemplateHaskell #-}
-- | The worked example's bowl given its compiled step with one splice, in a
-- module of its own (Template Haskell's stage restriction: the space is
-- defined in another module); the lines between the markers stand in
-- docs/spaces.md.
module BowlStep (bowlStep) where

-- README: from here
import Manifold.Compile (CompiledStep, compiledStep)
import Bowl (bowl)

bowlStep :: CompiledStep
bowlStep = $(compiledStep bowl)
-- README: to here
