{-# LANGUAGE MagicHash, UnboxedTuples #-}
-- | Forward-mode automatic differentiation over R³ (paper §3.2).
--
-- A dual number carries a value and its gradient with respect to the three
-- coordinates of the point. Nesting duals (@D (D a)@) gives second
-- derivatives, hence the Hessian and the curvatures of a surface @f = 0@.
module Manifold.AD
  ( D (..)
  , valueD
  , gradientD
  , variables
  , grad
  , scalarFn
  , valueAndGrad
  , hessian
  , gaussianCurvature
  , meanCurvature
  , secondOrder
  , adjugate
  ) where

import GHC.Exts (Double (..), inline)
import Linear.Matrix (M33, (!*))
import Linear.V3 (V3 (..), cross)
import Linear.Metric (dot, quadrance)
import Linear.Vector ((*^), (^+^), (^-^), zero)

import Manifold.Field

-- $setup
-- GHCi runs this module as object code (it has unboxed tuples), so the
-- examples see its exports and these imports only:
--
-- >>> import Manifold.AD
-- >>> import Manifold.Field
-- >>> import Linear.V3 (V3 (..))
-- >>> import Linear.Matrix (M33)
-- >>> import Linear.Metric (quadrance)

-- | A value and its gradient.
--
-- >>> let V3 x y _ = variables (V3 2 3 5 :: V3 Double) in x * y + sin y
-- D 6.141120008059867 (V3 3.0 1.0100075033995546 0.0)
data D a = D !a !(V3 a)
  deriving (Show, Eq)

-- | The value of a dual number.
valueD :: D a -> a
valueD (D x _) = x

-- | The gradient of a dual number.
gradientD :: D a -> V3 a
gradientD (D _ g) = g

lift :: Num a => a -> D a
lift x = D x zero
{-# INLINE lift #-}

-- | Apply a function with known derivative: the chain rule.
chain :: Num a => (a -> a) -> (a -> a) -> D a -> D a
chain f f' (D x dx) = D (f x) (f' x *^ dx)
{-# INLINE chain #-}

instance Field a => Num (D a) where
  D x dx + D y dy = D (x + y) (dx ^+^ dy)
  D x dx - D y dy = D (x - y) (dx ^-^ dy)
  D x dx * D y dy = D (x * y) (y *^ dx ^+^ x *^ dy)
  negate (D x dx) = D (negate x) (fmap negate dx)
  -- signum 0 = 0, so |x| has derivative 0 at 0 (the paper's choice).
  abs (D x dx) = D (abs x) (signum x *^ dx)
  signum (D x _) = lift (signum x)
  fromInteger = lift . fromInteger
  {-# INLINE (+) #-}
  {-# INLINE (-) #-}
  {-# INLINE (*) #-}
  {-# INLINE negate #-}
  {-# INLINE abs #-}
  {-# INLINE signum #-}
  {-# INLINE fromInteger #-}

instance Field a => Fractional (D a) where
  D x dx / D y dy = D (x / y) (recip y *^ dx ^-^ (x / (y * y)) *^ dy)
  recip = chain recip (\x -> negate (recip (x * x)))
  fromRational = lift . fromRational
  {-# INLINE (/) #-}
  {-# INLINE recip #-}
  {-# INLINE fromRational #-}

instance Field a => Floating (D a) where
  pi = lift pi
  exp = chain exp exp
  log = chain log recip
  sqrt (D x dx) = let s = sqrt x in D s (recip (2 * s) *^ dx)
  sin = chain sin cos
  cos = chain cos (negate . sin)
  tan = chain tan (\x -> let c = cos x in recip (c * c))
  asin = chain asin (\x -> recip (sqrt (1 - x * x)))
  acos = chain acos (\x -> negate (recip (sqrt (1 - x * x))))
  atan = chain atan (\x -> recip (1 + x * x))
  sinh = chain sinh cosh
  cosh = chain cosh sinh
  tanh = chain tanh (\x -> let t = tanh x in 1 - t * t)
  asinh = chain asinh (\x -> recip (sqrt (x * x + 1)))
  acosh = chain acosh (\x -> recip (sqrt (x * x - 1)))
  atanh = chain atanh (\x -> recip (1 - x * x))
  D x dx ** D y dy =
    let p = x ** y
    in D p ((y * x ** (y - 1)) *^ dx ^+^ (p * log x) *^ dy)
  logBase b x = log x / log b
  {-# INLINE pi #-}
  {-# INLINE exp #-}
  {-# INLINE log #-}
  {-# INLINE sqrt #-}
  {-# INLINE sin #-}
  {-# INLINE cos #-}
  {-# INLINE tan #-}
  {-# INLINE asin #-}
  {-# INLINE acos #-}
  {-# INLINE atan #-}
  {-# INLINE sinh #-}
  {-# INLINE cosh #-}
  {-# INLINE tanh #-}
  {-# INLINE asinh #-}
  {-# INLINE acosh #-}
  {-# INLINE atanh #-}
  {-# INLINE (**) #-}
  {-# INLINE logBase #-}

instance Field a => Field (D a) where
  constant = lift . constant
  select (D c _) (D t dt) (D e de) = D (select c t e) (select c <$> dt <*> de)
  floorF (D x _) = lift (floorF x)
  sinF = chain sinF cosF
  cosF = chain cosF (negate . sinF)
  atanF = chain atanF (\x -> recip (1 + x * x))
  expF = chain expF expF
  {-# INLINE sinF #-}
  {-# INLINE cosF #-}
  {-# INLINE atanF #-}
  {-# INLINE expF #-}
  {-# INLINE constant #-}
  {-# INLINE select #-}
  {-# INLINE floorF #-}

-- | The coordinates of a point as independent variables: each carries the
-- unit gradient of its own axis.
--
-- >>> variables (V3 1 2 3 :: V3 Double)
-- V3 (D 1.0 (V3 1.0 0.0 0.0)) (D 2.0 (V3 0.0 1.0 0.0)) (D 3.0 (V3 0.0 0.0 1.0))
variables :: Num a => V3 a -> V3 (D a)
variables (V3 x y z) = V3 (D x (V3 1 0 0)) (D y (V3 0 1 0)) (D z (V3 0 0 1))
{-# INLINE variables #-}

-- | A scalar function of a point, with its gradient by AD, and both also
-- compiled for 'Double' (see 'ScalarFn'). Inlined where it is used so that
-- GHC specialises the function there.
--
-- >>> let f = scalarFn (\(V3 x y z) -> x * x + y * z)
-- >>> evalFn f (V3 1 2 3 :: V3 Double)
-- 7.0
-- >>> gradFn f (V3 1 2 3 :: V3 Double)
-- V3 2.0 3.0 2.0
scalarFn :: (forall a. Field a => V3 a -> a) -> ScalarFn
scalarFn f = ScalarFnOf f (grad f) evalD valueGradD
  where
    -- 'inline': the field's body is compiled into these two, at Double and
    -- at dual numbers of Double, rather than called with boxed arguments
    evalD x y z = case inline f (V3 (D# x) (D# y) (D# z)) :: Double of D# v -> v
    valueGradD x y z = case inline f (variables (V3 (D# x) (D# y) (D# z))) :: D Double of
      D (D# v) (V3 (D# gx) (D# gy) (D# gz)) -> (# v, gx, gy, gz #)
{-# INLINE scalarFn #-}

-- | The gradient of a scalar function of a point.
--
-- >>> grad (\(V3 x y z) -> x * y * z) (V3 1 2 3 :: V3 Double)
-- V3 6.0 3.0 2.0
-- >>> grad (\(V3 x _ _) -> exp (2 * x)) (V3 0 0 0 :: V3 Double)
-- V3 2.0 0.0 0.0
grad :: Field a => (V3 (D a) -> D a) -> V3 a -> V3 a
grad f = gradientD . f . variables

-- | The value of a scalar function of a point and its gradient, from one
-- evaluation.
--
-- >>> valueAndGrad (\(V3 x y _) -> x * x + 3 * y) (V3 2 1 0 :: V3 Double)
-- (7.0,V3 4.0 3.0 0.0)
valueAndGrad :: Field a => (V3 (D a) -> D a) -> V3 a -> (a, V3 a)
valueAndGrad f p = let D v g = f (variables p) in (v, g)

-- | Second derivatives by nesting: the Jacobian of the gradient.
--
-- >>> hessian (\(V3 x y z) -> x * x * y + z) (V3 1 2 3 :: V3 Double)
-- V3 (V3 4.0 2.0 0.0) (V3 2.0 0.0 0.0) (V3 0.0 0.0 0.0)
hessian :: Field a => (V3 (D (D a)) -> D (D a)) -> V3 a -> M33 a
hessian f p = fmap gradientD (gradientD (f (variables (variables p))))

-- | The gradient and the Hessian at once (one nested evaluation).
--
-- >>> secondOrder (scalarFn (\(V3 x y z) -> x * y + z * z)) (V3 1 2 3 :: V3 Double)
-- (V3 2.0 1.0 6.0,V3 (V3 0.0 1.0 0.0) (V3 1.0 0.0 0.0) (V3 0.0 0.0 2.0))
secondOrder :: Field a => ScalarFn -> V3 a -> (V3 a, M33 a)
secondOrder sf p =
  let D (D _ g) rows = evalPoly sf (variables (variables p))
  in (g, fmap gradientD rows)

-- | Gaussian curvature of the level set through @p@ of a scalar field:
-- @K = ∇f · adj(H) ∇f / |∇f|⁴@ (Goldman, "Curvature formulas for implicit
-- curves and surfaces", 2005).
--
-- The unit sphere has curvature 1 everywhere, the sphere of radius 2 a
-- quarter, a cylinder 0:
--
-- >>> let sphereOf r = scalarFn (\p -> sqrt (quadrance p) - constant r)
-- >>> gaussianCurvature (sphereOf 1) (V3 0 1 0 :: V3 Double)
-- 1.0
-- >>> gaussianCurvature (sphereOf 2) (V3 0 0 2 :: V3 Double)
-- 0.25
-- >>> gaussianCurvature (scalarFn (\(V3 x _ z) -> x * x + z * z - 1)) (V3 1 0.5 0 :: V3 Double)
-- 0.0
gaussianCurvature :: Field a => ScalarFn -> V3 a -> a
gaussianCurvature f p =
  let (g, h) = secondOrder f p
      q = quadrance g
  in g `dot` (adjugate h !* g) / (q * q)

-- | Mean curvature, @(|∇f|² tr H − ∇f·H∇f) / (2|∇f|³)@: positive on a sphere
-- whose field grows outwards.
--
-- >>> meanCurvature (scalarFn (\p -> sqrt (quadrance p) - 1)) (V3 0 1 0 :: V3 Double)
-- 1.0
meanCurvature :: Field a => ScalarFn -> V3 a -> a
meanCurvature f p =
  let (g, h) = secondOrder f p
      q = quadrance g
      V3 (V3 hxx _ _) (V3 _ hyy _) (V3 _ _ hzz) = h
  in (q * (hxx + hyy + hzz) - g `dot` (h !* g)) / (2 * q * sqrt q)

-- | The adjugate (transposed cofactor matrix) of a 3×3 matrix: @A · adj A
-- = det A · I@, defined where the inverse is not.
--
-- >>> adjugate (V3 (V3 2 0 0) (V3 0 3 0) (V3 0 0 4) :: M33 Int)
-- V3 (V3 12 0 0) (V3 0 8 0) (V3 0 0 6)
adjugate :: Num a => M33 a -> M33 a
adjugate (V3 r0 r1 r2) =
  let V3 c0x c0y c0z = r1 `cross` r2
      V3 c1x c1y c1z = r2 `cross` r0
      V3 c2x c2y c2z = r0 `cross` r1
  in V3 (V3 c0x c1x c2x) (V3 c0y c1y c2y) (V3 c0z c1z c2z)
