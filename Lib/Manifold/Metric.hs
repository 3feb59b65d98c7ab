-- | The ambient metric a space's surface sits in: R³'s dot product, or
-- Minkowski space's @⟨a, b⟩ = a_x b_x − a_y b_y + a_z b_z@, in which the
-- hyperboloid @y² − x² − z² = 1@ is the hyperbolic plane (no surface of R³
-- is: Hilbert's theorem). Every dot product, length, normal, tangent
-- projection and rotation in a tangent plane the physics takes is the
-- space's metric's.
--
-- A Minkowski space's surface must be spacelike (its normal timelike,
-- @⟨n, n⟩ = −1@), so that the metric it induces on the surface is a
-- Riemannian one: lengths and angles of tangent vectors are what they are on
-- any surface.
--
-- The 'Euclidean' metric's functions are "Linear"'s own, so a Euclidean
-- space's step prints and computes exactly as it did before metrics
-- existed.
module Manifold.Metric
  ( Metric (..)
  , metricName
  , inner
  , quadranceIn
  , normIn
  , normalizeIn
  , raise
  , normalSign
  , perpendicular
  , gridPoint
  , gaussianCurvatureIn
  ) where

import Linear.Matrix ((!*))
import Linear.Metric (dot, norm, quadrance)
import Linear.V3 (V3 (..), cross)
import Linear.Vector ((*^))

import Manifold.AD (adjugate, gaussianCurvature, secondOrder)
import Manifold.Field

-- | The ambient metric of a space.
data Metric
  = Euclidean -- ^ R³'s dot product
  | Minkowski -- ^ signature (+, −, +) in (x, y, z): y is time-like
  deriving (Show, Eq)

-- | How @manifold spaces@ and the page name a metric.
--
-- >>> map metricName [Euclidean, Minkowski]
-- ["euclidean","minkowski"]
metricName :: Metric -> String
metricName Euclidean = "euclidean"
metricName Minkowski = "minkowski"

-- | The inner product of two vectors.
--
-- >>> inner Minkowski (V3 1 2 3) (V3 1 1 1 :: V3 Double)
-- 2.0
inner :: Field a => Metric -> V3 a -> V3 a -> a
{-# INLINE inner #-}
inner Euclidean a b = a `dot` b
inner Minkowski (V3 ax ay az) (V3 bx by bz) = ax * bx - ay * by + az * bz

-- | A vector's inner product with itself (negative for a time-like vector
-- of the Minkowski metric).
quadranceIn :: Field a => Metric -> V3 a -> a
{-# INLINE quadranceIn #-}
quadranceIn Euclidean v = quadrance v
quadranceIn m v = inner m v v

-- | The length of a vector: @√|⟨v, v⟩|@.
--
-- >>> normIn Minkowski (V3 0 2 0 :: V3 Double)
-- 2.0
normIn :: Field a => Metric -> V3 a -> a
{-# INLINE normIn #-}
normIn Euclidean v = norm v
normIn m v = sqrt (abs (quadranceIn m v))

-- | @v/|v|@, or the zero vector where @|v| = 0@ (never NaN).
--
-- >>> normalizeIn Minkowski (V3 0 0 2 :: V3 Double)
-- V3 0.0 0.0 1.0
-- >>> normalizeIn Minkowski (V3 0 0 0 :: V3 Double)
-- V3 0.0 0.0 0.0
normalizeIn :: Field a => Metric -> V3 a -> V3 a
{-# INLINE normalizeIn #-}
normalizeIn m v =
  let l = normIn m v
      inv = select l (recip (maxF l tiny)) 0
  in inv *^ v
  where tiny = constant 1e-300

-- | A covector (a field's gradient) raised to the vector the metric pairs
-- it with: the direction of the surface's normal.
--
-- >>> raise Minkowski (V3 1 2 3 :: V3 Double)
-- V3 1.0 (-2.0) 3.0
raise :: Field a => Metric -> V3 a -> V3 a
{-# INLINE raise #-}
raise Euclidean g = g
raise Minkowski (V3 x y z) = V3 x (negate y) z

-- | @⟨n, n⟩@ of a surface's unit normal under this metric: 1, or −1 for a
-- Minkowski space (whose surfaces are space-like).
normalSign :: Metric -> Double
normalSign Euclidean = 1
normalSign Minkowski = -1

-- | The tangent vector a quarter turn from @u@ in the tangent plane with
-- unit normal @n@, counter-clockwise seen from the side @n@ points to:
-- @n × u@, lowered by the metric (for the Minkowski metric, the Lorentzian
-- cross product). It has @u@'s length; @⟨perpendicular n u, v⟩@ is the
-- triple product @(u × v) · n@ under either metric.
--
-- >>> perpendicular Minkowski (V3 0 1 0) (V3 1 0 0 :: V3 Double) == V3 0 0 (-1)
-- True
perpendicular :: Field a => Metric -> V3 a -> V3 a -> V3 a
{-# INLINE perpendicular #-}
perpendicular m n u = raise m (n `cross` u)

-- | Where the broad phase files a point of the surface: coordinates in
-- which two points are never farther apart, along any axis, than their
-- chord's length under the metric, so that the grid's cells of the largest
-- body's diameter find every touching pair. In R³ the point itself; on the
-- hyperboloid its Poincaré disc coordinates doubled, @2 (x, z)/(1 + y)@ in
-- x and z (the disc's metric is at least twice its Euclidean one, and a
-- geodesic distance is at most its chord).
--
-- >>> gridPoint Minkowski (V3 0 1 0 :: V3 Double)
-- V3 0.0 0.0 0.0
gridPoint :: Field a => Metric -> V3 a -> V3 a
{-# INLINE gridPoint #-}
gridPoint Euclidean p = p
gridPoint Minkowski (V3 x y z) = let s = 2 / (1 + y) in V3 (s * x) 0 (s * z)

-- | The Gaussian curvature of the level surface through @p@ under the
-- metric: 'gaussianCurvature' in R³; in Minkowski space, for a space-like
-- surface, @K = −∇f · adj(H) ∇f / q²@ with @q = ∇f · η∇f@ (Gauss's equation
-- with ⟨n, n⟩ = −1: the R³ formula's ratio of the second fundamental form's
-- determinant to the first's, both restricted to the tangent plane).
-- The hyperboloid is the hyperbolic plane, of curvature −1 everywhere:
--
-- >>> import Manifold.AD (scalarFn)
-- >>> let hyperboloid = scalarFn (\(V3 x y z) -> sqrt (1 + x * x + z * z) - y)
-- >>> abs (gaussianCurvatureIn Minkowski hyperboloid (V3 1 (sqrt 3) 1 :: V3 Double) + 1) < 1e-12
-- True
gaussianCurvatureIn :: Field a => Metric -> ScalarFn -> V3 a -> a
gaussianCurvatureIn Euclidean f p = gaussianCurvature f p
gaussianCurvatureIn m f p =
  let (g, h) = secondOrder f p
      q = g `dot` raise m g
  in constant (normalSign m) * (g `dot` (adjugate h !* g)) / (q * q)
