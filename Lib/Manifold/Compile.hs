{-# LANGUAGE TemplateHaskellQuotes #-}
-- | The compiled native step: a space's staged step ("Manifold.Program"),
-- made for the 'Haskell' target and spliced with Template Haskell while
-- the library (or a user's module) compiles, so it can never differ from
-- the engine it is built from. One line compiles a space's step:
--
-- > bowlStep :: CompiledStep
-- > bowlStep = $(compiledStep bowl)
--
-- (with @TemplateHaskell@ on and the space defined in another module, as
-- Template Haskell's stage restriction asks). "Manifold.Compiled.Runtime"
-- says why the compiled step is faster than the generic one, and holds
-- what the spliced code calls.
module Manifold.Compile
  ( CompiledStep
  , compiledStep
  , sharedFunctions
  , compiledLayout
  , dumpStep
  ) where

import Data.List (partition)
import Data.Maybe (fromMaybe)
import Data.Foldable (toList)
import Language.Haskell.TH
import Language.Haskell.TH.Syntax (mkNameG_v)

import Manifold.Compiled.Runtime (CompiledStep (..), newLocals, primitiveArray, spaceFingerprint)
import Manifold.Program (phaseFunction, stagedPhases, stepProcedures, worldParams)
import Manifold.Space
import Manifold.Spaces (plane)
import Manifold.Stage.Code (Check, Function (..), calledNames)
import Manifold.Stage.Imp (localsArray, stageFunctions)
import Manifold.Stage.Print (Target (..), printProcedure)
import Manifold.Stage.Splice (functionDecs)
import Manifold.World (Layout (..), WalkLoops (..), layout)

-- | The polygon the compiled step is made for (the engine's), walked with
-- each Newton iteration of a geodesic step as a loop of its own across the
-- directions: compiled natively, the walk otherwise waits on each
-- iteration's chain (see 'WalkLoops').
compiledLayout :: Layout
compiledLayout = (layout 0) { walkLoops = LoopPerNewtonIteration }

-- | A space's step staged for Haskell: the phases, then the subroutines
-- they call.
stepFunctions :: Space -> [Function Check]
stepFunctions sp = stageFunctions Haskell (stepProcedures sp compiledLayout)

-- | The plane's step: its phases and subroutines. Most of a step's
-- subroutines (the pair narrow phase, the solver's sweeps) and several of
-- its phases (waking, sleeping; on spaces without anchors to walk, the
-- rows' preparation too) do not touch the space, so they are spliced once,
-- in "Manifold.Compiled.Shared", and every space whose function is the same
-- tree calls that one: 14 copies of the subroutines took a third more
-- compile time.
referenceFunctions :: [Function Check]
referenceFunctions = stepFunctions plane

-- | The declarations of "Manifold.Compiled.Shared".
sharedFunctions :: Q [Dec]
sharedFunctions = pure (concatMap (functionDecs mkName) referenceFunctions)

-- | A subroutine of "Manifold.Compiled.Shared", by its global name (so a
-- splice anywhere calls it without importing the module).
sharedName :: String -> Name
sharedName = mkNameG_v package "Manifold.Compiled.Shared"
  where package = fromMaybe (error "compiledStep: no package for Manifold.Compiled.Runtime") (namePackage 'newLocals)

-- | Of a space's functions that are the same trees as the plane's, those
-- that can be the plane's: a phase printed alike calls its subroutines by
-- name, so where one of those is the space's own, the phase must be its
-- own too (and so must whatever calls it).
sharedWith :: [Function Check] -> [String]
sharedWith same
  | length kept == length same = map fnName same
  | otherwise = sharedWith kept
  where kept = [ f | f <- same, all (`elem` map fnName same) (calledNames f) ]

-- | A space's compiled step, as an expression of type 'CompiledStep'.
compiledStep :: Space -> Q Exp
compiledStep sp = do
  let (shared, own) = partition ((`elem` sharedNames) . fnName) functions
      functions = stepFunctions sp
      sharedNames = sharedWith [ f | f <- functions, f `elem` referenceFunctions ]
      callee n | n `elem` map fnName shared = sharedName n
               | otherwise = mkName n
  applyTo <- newName "applyTo"
  f <- newName "f"
  w <- newName "w"
  let arrays = map mkName worldParams
      -- the world's arrays as primitive vectors, and a locals array of
      -- the call's own, passed to a phase
      applyDec = FunD applyTo [Clause [VarP f, VarP w] (NormalB (CaseE
        (AppE (AppE (VarE 'map) (VarE 'primitiveArray)) (AppE (VarE 'toList) (VarE w)))
        [ Match (ListP (map VarP arrays))
            (NormalB (InfixE (Just (VarE 'newLocals)) (VarE '(>>=)) (Just (foldl AppE (VarE f) (map VarE arrays))))) []
        , Match WildP (NormalB (AppE (VarE 'error) (LitE (StringL
            ("the compiled step of " ++ spaceName sp ++ ": the world's arrays are not the ones it was made for"))))) []
        ])) []]
      phases = ListE [ TupE [Just (LitE (StringL name)), Just (AppE (VarE applyTo) (VarE (callee (phaseFunction name))))]
                     | (name, _) <- stagedPhases ]
  pure $ LetE (applyDec : concatMap (functionDecs callee) own) $
    foldl AppE (ConE 'CompiledStep)
      [LitE (StringL (spaceName sp)), LitE (StringL (spaceFingerprint sp compiledLayout)), phases]

-- | A space's compiled step as Haskell text, for reading
-- (@manifold dump-step SPACE@): every function the splice defines or calls,
-- over the definitions of "Manifold.Compiled.Runtime"; each function
-- takes the world's arrays and, last, the array of its locals
-- (@'localsArray'@).
dumpStep :: Space -> String
dumpStep sp = unlines (header : map (printProcedure Haskell) (stepFunctions sp))
  where header = "-- the compiled step of " ++ show (spaceName sp) ++ " (arrays: " ++ unwords (worldParams ++ [localsArray]) ++ ")"
