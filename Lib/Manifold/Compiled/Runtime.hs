-- | What the compiled native step is made of (the Haskell that
-- 'Manifold.Stage.Imp.stageProceduresFor' prints, in the generated modules
-- "Manifold.Compiled.*"), and how a world knows that a compiled step is
-- the one for its space.
--
-- The native engine is the polymorphic step run at 'Double'; it calls the
-- space's field through a record, so GHC cannot simplify the geometry
-- around it. The page's JavaScript is the same step staged for one space,
-- with the field's gradient worked out and simplified symbolically; the
-- compiled step is that same staged program printed as Haskell, so the
-- native engine gets the simplifications V8 gets.
module Manifold.Compiled.Runtime
  ( Arr
  , loopI
  , chkI
  , rdU
  , wrU
  , NumRef
  , newR
  , getR
  , setR
  , floorF
  , CompiledStep (..)
  , spaceFingerprint
  ) where

import qualified Data.Vector.Unboxed.Mutable as MV
import Linear.V3 (V3 (..))

import Manifold.Field
import Manifold.Space
import Manifold.Stage.Expr (E, sym)
import Manifold.Stage.Print
import Manifold.World (Layout (..), WorldArrays)

type Arr = MV.IOVector Double

-- | @loopI lo hi body@: the printed @for@ loop. The counter is an 'Int'
-- from @lo@ (a whole number) while it is below @hi@ (compared as numbers,
-- so a NaN bound runs nothing, as in JavaScript).
loopI :: Double -> Double -> (Int -> IO ()) -> IO ()
loopI lo hi body = go (truncate lo)
  where go !i | fromIntegral i < hi = body i >> go (i + 1)
              | otherwise = pure ()
{-# INLINE loopI #-}

-- | @chkI a base lo hi@: the printed step's check that @a@ holds indices
-- @base + lo@ to @base + hi@, before it reads or writes them with 'rdU' and
-- 'wrU' (see 'Manifold.Stage.Imp.arrayAccess': one check per row of an
-- array instead of one per access).
chkI :: Arr -> Int -> Int -> Int -> IO ()
chkI a base lo hi
  | base + lo >= 0 && base + hi < MV.length a = pure ()
  | otherwise = outOfBounds a base lo hi
{-# INLINE chkI #-}

outOfBounds :: Arr -> Int -> Int -> Int -> IO ()
outOfBounds a base lo hi = ioError $ userError $
  "Manifold.Compiled: indices " ++ show (base + lo) ++ " to " ++ show (base + hi)
  ++ " outside an array of " ++ show (MV.length a)
{-# NOINLINE outOfBounds #-}

rdU :: Arr -> Int -> IO Double
rdU = MV.unsafeRead
{-# INLINE rdU #-}

wrU :: Arr -> Int -> Double -> IO ()
wrU a i !x = MV.unsafeWrite a i x
{-# INLINE wrU #-}

-- | A mutable local (the printed @let@): one unboxed number.
newtype NumRef = NumRef (MV.IOVector Double)

-- (not 'MV.replicate': its fill loop costs more than the one write)
newR :: Double -> IO NumRef
newR !x = do
  r <- MV.unsafeNew 1
  MV.unsafeWrite r 0 x
  pure (NumRef r)
{-# INLINE newR #-}

getR :: NumRef -> IO Double
getR (NumRef r) = MV.unsafeRead r 0
{-# INLINE getR #-}

setR :: NumRef -> Double -> IO ()
setR (NumRef r) !x = MV.unsafeWrite r 0 x
{-# INLINE setR #-}

-- | A space's step, compiled: the phases in the order of
-- 'Manifold.Step.stepPhases', for the space and polygon the fingerprint
-- describes.
data CompiledStep = CompiledStep
  { compiledSpace :: String
  , compiledFingerprint :: String
  , compiledPhases :: [(String, WorldArrays Arr -> IO ())]
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

