-- | What the compiled native step is made of (the code that
-- "Manifold.Compile" splices, from the staged step, into the modules
-- "Manifold.Compiled.*" and into a user's own), and how a world knows that
-- a compiled step is the one for its space.
--
-- The native engine is the polymorphic step run at 'Double'; it calls the
-- space's field through a record, so GHC cannot simplify the geometry
-- around it. The page's JavaScript is the same step staged for one space,
-- with the field's gradient worked out and simplified symbolically; the
-- compiled step is that same staged program spliced as Haskell, so the
-- native engine gets the simplifications V8 gets.
module Manifold.Compiled.Runtime
  ( Arr
  , primitiveArray
  , loopI
  , chkI
  , rdU
  , wrU
  , newLocals
  , floorF
  , CompiledStep (..)
  , spaceFingerprint
  ) where

import qualified Data.Vector.Primitive.Mutable as PV
import qualified Data.Vector.Unboxed.Mutable as MV
import Data.Vector.Unboxed.Base (MVector (MV_Double))
import Linear.V3 (V3 (..))

import Manifold.Field
import Manifold.Space
import Manifold.Stage.Expr (E, sym)
import Manifold.Stage.Imp (localSlots)
import Manifold.Stage.Print
import Manifold.World (Layout (..), WorldArrays)

-- | The compiled step's arrays are the world's, seen as primitive vectors
-- (a plain data type). An unboxed vector of 'Double' is a data family
-- instance, and GHC evaluates a data family value through its generic apply
-- code, spilling every live number around it, wherever the compiled step
-- touches an array; a primitive vector is evaluated once, where the
-- function's strict parameter receives it.
type Arr = PV.IOVector Double

-- | The world's array as the compiled step takes it (the same memory).
primitiveArray :: MV.IOVector Double -> Arr
primitiveArray (MV_Double v) = v
{-# INLINE primitiveArray #-}

-- | @loopI lo hi body@: the staged @for@ loop. The counter is an 'Int'
-- from @lo@ (a whole number) while it is below @hi@ (compared as numbers,
-- so a NaN bound runs nothing, as in JavaScript).
loopI :: Double -> Double -> (Int -> IO ()) -> IO ()
loopI lo hi body = go (truncate lo)
  where go !i | fromIntegral i < hi = body i >> go (i + 1)
              | otherwise = pure ()
{-# INLINE loopI #-}

-- | @chkI a base lo hi@: the compiled step's check that @a@ holds indices
-- @base + lo@ to @base + hi@, before it reads or writes them with 'rdU' and
-- 'wrU' (see @arrayAccess@ in "Manifold.Stage.Imp": one check per row of an
-- array instead of one per access).
chkI :: Arr -> Int -> Int -> Int -> IO ()
chkI a base lo hi
  | base + lo >= 0 && base + hi < PV.length a = pure ()
  | otherwise = outOfBounds a base lo hi
{-# INLINE chkI #-}

outOfBounds :: Arr -> Int -> Int -> Int -> IO ()
outOfBounds a base lo hi = ioError $ userError $
  "Manifold.Compiled: indices " ++ show (base + lo) ++ " to " ++ show (base + hi)
  ++ " outside an array of " ++ show (PV.length a)
{-# NOINLINE outOfBounds #-}

-- | An element of an array, unchecked: a 'chkI' before it covered the
-- index.
rdU :: Arr -> Int -> IO Double
rdU = PV.unsafeRead
{-# INLINE rdU #-}

-- | Set an element of an array, unchecked (see 'rdU'); the number is
-- evaluated first.
wrU :: Arr -> Int -> Double -> IO ()
wrU a i !x = PV.unsafeWrite a i x
{-# INLINE wrU #-}

-- | The compiled step's mutable locals, one array a phase call (see
-- 'Manifold.Stage.Imp.localSlots').
newLocals :: IO Arr
newLocals = PV.replicate localSlots 0

-- | A space's step, compiled: the phases in the order of
-- 'Manifold.Step.stepPhases', for the space and polygon the fingerprint
-- describes (made by "Manifold.Compile"'s splice).
data CompiledStep = CompiledStep
  { compiledSpace :: String
  , compiledFingerprint :: String
  , compiledPhases :: [(String, WorldArrays (MV.IOVector Double) -> IO ())]
  }

-- | Everything about a space and a layout that the staged step depends on:
-- the field, boundary and gravity as printed expressions, the quotient, the
-- bounds and the polygon. A compiled step serves a world only if the
-- fingerprints agree, so a space of one's own that reuses a catalogue name
-- runs the generic step, not another space's.
spaceFingerprint :: Space -> Layout -> String
spaceFingerprint sp l = unlines
  [ "field " ++ printed [evalFn (spaceField sp) xyz]
  , "boundary " ++ maybe "none" (\b -> printed [evalFn b xyz]) (spaceBoundary sp)
  , "gravity " ++ let VectorFn g = spaceGravity sp; V3 a b c = g xyz in printed [a, b, c]
  , "quotient " ++ show (spaceQuotient sp)
  , "bounds " ++ show (spaceBounds sp)
  , "polygon " ++ show (polygon l)
  ]
  where
    xyz = V3 (sym "x") (sym "y") (sym "z") :: V3 E
    printed = printFunction JavaScript "f" (FnType ["x", "y", "z"] False)

