-- | The one scalar class every distance field and every geometry function is
-- written against.
--
-- Geometry code never branches with 'Ord': a staged (code-building) scalar
-- cannot be compared in Haskell, only in the code it prints. So branching is
-- a method of the class ('select'), and 'minF'/'maxF' are built from it. The
-- same source then runs natively at 'Double', is differentiated at the dual
-- numbers of "Manifold.AD", and is printed as JavaScript and GLSL by the
-- staging layer.
module Manifold.Field
  ( Field (..)
  , clampF
  , atan2F
  , smoothMinF
  , ScalarFn (..)
  , VectorFn (..)
  ) where

import Linear.V3 (V3)

-- | Scalars of the physics.
--
-- Laws (checked by the differential tests for every instance):
--
-- * @select c t e@ is @t@ where @c > 0@ and @e@ otherwise, NaN included
--   (a NaN condition chooses @e@, as @c > 0 ? t : e@ does in JS and GLSL);
-- * @minF a b = select (b - a) a b@, @maxF a b = select (a - b) a b@;
-- * 'constant' embeds a 'Double' exactly (NaN and infinities included).
class Floating a => Field a where
  constant :: Double -> a
  select :: a -> a -> a -> a

  minF :: a -> a -> a
  minF a b = select (b - a) a b

  maxF :: a -> a -> a
  maxF a b = select (a - b) a b

  -- | The largest integer not above the argument (derivative 0).
  floorF :: a -> a

  -- | A scalar function's value, and its gradient, at this scalar.
  evalFn :: ScalarFn -> V3 a -> a
  evalFn f = evalPoly f
  gradFn :: ScalarFn -> V3 a -> V3 a
  gradFn f = gradPoly f

instance Field Double where
  constant = id
  select c t e = if c > 0 then t else e
  {-# INLINE select #-}
  floorF x
    | isNaN x || isInfinite x || x == 0 = x -- keeps −0, as Math.floor does
    | otherwise = fromIntegral (floor x :: Integer)
  evalFn = evalDouble
  gradFn = gradDouble

-- | @clampF lo hi x@.
clampF :: Field a => a -> a -> a -> a
clampF lo hi = maxF lo . minF hi

-- | The angle of the point @(x, y)@, in @(−π, π]@, by half-angle formulas
-- (so that it needs no comparison outside 'select'); 0 at the origin.
atan2F :: Field a => a -> a -> a
atan2F y x =
  let r = sqrt (x * x + y * y)
  in select x (2 * atan (y / (r + x)))
       (select (abs y) (2 * atan ((r - x) / y)) (select (negate x) pi 0))

-- | Polynomial smooth minimum with blend width @k@ (Quilez), used to round
-- shapes such as the cube.
smoothMinF :: Field a => a -> a -> a -> a
smoothMinF k a b =
  let h = clampF 0 1 (0.5 + 0.5 * (b - a) / k)
  in b * (1 - h) + a * h - k * h * (1 - h)

-- | A scalar function of a point, polymorphic in the scalar: a distance field,
-- a boundary @b(p) >= 0@. Built by 'Manifold.AD.scalarFn', which also keeps
-- the function and its gradient compiled for 'Double': a function stored in a
-- record cannot be specialised where it is used, so the native engine would
-- otherwise run every field through dictionaries.
data ScalarFn = ScalarFnOf
  { evalPoly :: forall a. Field a => V3 a -> a
  , gradPoly :: forall a. Field a => V3 a -> V3 a -- ^ by forward AD
  , evalDouble :: V3 Double -> Double
  , gradDouble :: V3 Double -> V3 Double
  }

-- | A vector field of R³, polymorphic in the scalar (e.g. gravity).
newtype VectorFn = VectorFn (forall a. Field a => V3 a -> V3 a)
