-- | The one scalar class every distance field and every geometry function is
-- written against.
--
-- Geometry code never branches with 'Ord': a staged (code-building) scalar
-- cannot be compared in Haskell, only in the code it prints. So branching is
-- a method of the class ('select'), and 'minF'/'maxF' are built from it. The
-- same source then runs natively at 'Double', is differentiated at the dual
-- numbers of "Manifold.AD", and is printed as JavaScript and GLSL by the
-- staging layer.
{-# LANGUAGE MagicHash, UnboxedTuples #-}
module Manifold.Field
  ( Field (..)
  , clampF
  , atan2F
  , ScalarFn (..)
  , VectorFn (..)
  ) where

import Data.Bits (shiftL)
import GHC.Exts (Double (..), Double#)
import GHC.Float (castWord64ToDouble)
import Linear.V3 (V3 (..))

import Manifold.Elementary

-- $setup
-- GHCi runs this module as object code (it has unboxed tuples), so the
-- examples see its exports through this import:
--
-- >>> import Manifold.Field

-- | Scalars of the physics.
--
-- Laws (checked by the differential tests for every instance):
--
-- * @select c t e@ is @t@ where @c > 0@ and @e@ otherwise, NaN included
--   (a NaN condition chooses @e@, as @c > 0 ? t : e@ does in JS and GLSL);
-- * @minF a b = select (b - a) a b@, @maxF a b = select (a - b) a b@;
-- * 'constant' embeds a 'Double' exactly (NaN and infinities included).
--
-- >>> select 1 10 20 :: Double
-- 10.0
-- >>> select (0 / 0) 10 20 :: Double
-- 20.0
-- >>> (minF 2 3, maxF 2 3) :: (Double, Double)
-- (2.0,3.0)
class Floating a => Field a where
  -- | A 'Double' as a scalar: a number natively, a literal in staged code.
  constant :: Double -> a
  -- | @select c t e@: @t@ where @c > 0@, else @e@ (see the laws above).
  select :: a -> a -> a -> a

  -- | The smaller of two scalars, by 'select'.
  minF :: a -> a -> a
  minF a b = select (b - a) a b

  -- | The larger of two scalars, by 'select'.
  maxF :: a -> a -> a
  maxF a b = select (a - b) a b

  -- | The largest integer not above the argument (derivative 0).
  floorF :: a -> a

  -- | The engine's sine ("Manifold.Elementary"): the same bits on every
  -- backend, unlike the platform's 'sin' (libm natively, V8's in the
  -- page). The physics uses these four; a space of one's own may use the
  -- 'Floating' functions, which are the platform's.
  sinF :: a -> a
  sinF = sinWith (exact floorF select constant)
  -- | The engine's cosine (see 'sinF').
  cosF :: a -> a
  cosF = cosWith (exact floorF select constant)
  -- | The engine's arctangent (see 'sinF').
  atanF :: a -> a
  atanF = atanWith (exact floorF select constant)
  -- | The engine's exponential (see 'sinF').
  expF :: a -> a
  expF = expWith (exact floorF select constant)

  -- | A scalar function's value at this scalar. 'Double' overrides it to
  -- call the function's compiled 'evalRaw' instead of its polymorphic
  -- body.
  evalFn :: ScalarFn -> V3 a -> a
  evalFn f = evalPoly f
  -- | A scalar function's gradient at this scalar ('Double': the compiled
  -- 'valueGradRaw').
  gradFn :: ScalarFn -> V3 a -> V3 a
  gradFn f = gradPoly f
  -- | Both at once (one evaluation natively; staged code shares them anyway).
  valueGradFn :: ScalarFn -> V3 a -> (a, V3 a)
  valueGradFn f p = (evalFn f p, gradFn f p)

instance Field Double where
  constant = id
  select c t e = if c > 0 then t else e
  {-# INLINE select #-}
  floorF = c_floor -- C's floor keeps −0, NaN and the infinities, as Math.floor does
  {-# INLINE floorF #-}
  sinF = sinDouble
  cosF = cosDouble
  atanF = atanDouble
  expF = expDouble
  evalFn f (V3 (D# x) (D# y) (D# z)) = D# (evalRaw f x y z)
  {-# INLINE evalFn #-}
  gradFn f (V3 (D# x) (D# y) (D# z)) = case valueGradRaw f x y z of
    (# _, gx, gy, gz #) -> V3 (D# gx) (D# gy) (D# gz)
  {-# INLINE gradFn #-}
  valueGradFn f (V3 (D# x) (D# y) (D# z)) = case valueGradRaw f x y z of
    (# v, gx, gy, gz #) -> (D# v, V3 (D# gx) (D# gy) (D# gz))
  {-# INLINE valueGradFn #-}

foreign import ccall unsafe "math.h floor" c_floor :: Double -> Double

-- | @clampF lo hi x@: @x@ limited to @[lo, hi]@, by 'minF' and 'maxF'.
--
-- >>> map (clampF 0 1) [-0.5, 0.25, 2] :: [Double]
-- [0.0,0.25,1.0]
clampF :: Field a => a -> a -> a -> a
clampF lo hi = maxF lo . minF hi

-- | The kernels at 'Double', each compiled once with its constants as
-- plain numbers.
sinDouble, cosDouble, atanDouble, expDouble :: Double -> Double
sinDouble = sinWith doubleExact
cosDouble = cosWith doubleExact
atanDouble = atanWith doubleExact
-- one multiplication by 2^n where the result is normal ('expParts'): the
-- bits 'expWith' gives, without its walk over the bits of n
expDouble x =
  let (series, n) = expParts doubleExact x
  in if n > -1000 && n < 1000
       then series * castWord64ToDouble (fromIntegral (truncate n + 1023 :: Int) `shiftL` 52)
       else expWith doubleExact x

-- | 'Exact' at 'Double'.
doubleExact :: Exact Double
doubleExact = Exact c_floor (\c t e -> if c > 0 then t else e) id hornerVector
{-# INLINE doubleExact #-}

-- | The angle of the point @(x, y)@, in @(−π, π]@, by half-angle formulas
-- (so that it needs no comparison outside 'select') and the engine's
-- arctangent 'atanF'; 0 at the origin.
--
-- >>> atan2F 1 0 == (pi / 2 :: Double)
-- True
-- >>> atan2F 0 (-1) :: Double
-- 3.141592653589793
-- >>> atan2F 0 0 :: Double
-- 0.0
atan2F :: Field a => a -> a -> a
atan2F y x =
  let r = sqrt (x * x + y * y)
  in select x (2 * atanF (y / (r + x)))
       (select (abs y) (2 * atanF ((r - x) / y)) (select (negate x) pi 0))

-- | A scalar function of a point, polymorphic in the scalar: a distance field,
-- a boundary @b(p) >= 0@. Built by 'Manifold.AD.scalarFn', which also keeps
-- the function and its gradient compiled for 'Double': a function stored in a
-- record cannot be specialised where it is used, so the native engine would
-- otherwise run every field through dictionaries. The 'Double' versions take
-- and return unboxed numbers: a call through a record field is an unknown
-- call, and boxed arguments and results would allocate at every one of the
-- engine's hundreds of thousands of field evaluations per step.
data ScalarFn = ScalarFnOf
  { evalPoly :: forall a. Field a => V3 a -> a -- ^ the function, at any scalar
  , gradPoly :: forall a. Field a => V3 a -> V3 a -- ^ its gradient, by forward AD
  , evalRaw :: Double# -> Double# -> Double# -> Double# -- ^ the function at @x y z@, compiled for 'Double'
  , valueGradRaw :: Double# -> Double# -> Double# -> (# Double#, Double#, Double#, Double# #)
    -- ^ the value and the gradient's three components at @x y z@, compiled for 'Double'
  }

-- | A vector field of R³, polymorphic in the scalar (e.g. gravity).
newtype VectorFn = VectorFn (forall a. Field a => V3 a -> V3 a)
