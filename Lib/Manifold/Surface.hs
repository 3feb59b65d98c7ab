-- | Geometry of a surface @f = 0@ embedded in R³ (paper §2.2, §2.4), under
-- the space's ambient metric ("Manifold.Metric"): normals, tangent
-- projections, lengths and the quarter turn in a tangent plane are the
-- metric's; the sphere tracer's distance and the Newton pull back onto the
-- surface are R³'s (they only find points of @f = 0@).
--
-- Everything here is polymorphic in the scalar class, so it runs natively,
-- under AD, and staged as JavaScript. Branching uses 'select', and iterations
-- have fixed counts (a converged iteration leaves the point where it is), so
-- that the staged code has no data-dependent control flow.
{-# LANGUAGE ScopedTypeVariables #-}
module Manifold.Surface
  ( fieldGradient
  , unitNormal
  , normalOf
  , traceDistance
  , projectToSurface
  , projectToSurfaceWith
  , projectAlongWithGradient
  , newtonAlong
  , stepProjectionIterations
  , defaultProjectionIterations
  , projectionTolerance
  , tangentProjection
  , transport
  , geodesicStep
  , geodesicStepFrom
  , geodesicStepEnd
  , expMap
  , geodesicPath
  , tangentFrame
  , referenceAxis
  , safeNormalize
  ) where

import Linear.Metric (dot, norm, quadrance)
import Linear.V3 (V3 (..))
import Linear.Vector ((*^), (^-^), (^+^))

import Manifold.Field
import Manifold.Metric

-- $setup
-- >>> import Manifold.AD (scalarFn)
-- >>> let unitSphere = scalarFn (\p -> norm p - 1)

-- | The gradient of a field, by forward AD.
fieldGradient :: Field a => ScalarFn -> V3 a -> V3 a
{-# INLINE fieldGradient #-}
fieldGradient = gradFn

-- | @v/|v|@ in R³, or the zero vector where @|v| = 0@ (never NaN).
--
-- >>> safeNormalize (V3 0 0 2 :: V3 Double)
-- V3 0.0 0.0 1.0
-- >>> safeNormalize (V3 0 0 0 :: V3 Double)
-- V3 0.0 0.0 0.0
safeNormalize :: Field a => V3 a -> V3 a
{-# INLINE safeNormalize #-}
safeNormalize = normalizeIn Euclidean

-- | The unit normal: the gradient raised by the metric, @η∇f/|η∇f|@
-- (@∇f/|∇f|@ in R³).
--
-- >>> unitNormal Euclidean unitSphere (V3 0 2 0 :: V3 Double)
-- V3 0.0 1.0 0.0
unitNormal :: Field a => Metric -> ScalarFn -> V3 a -> V3 a
{-# INLINE unitNormal #-}
unitNormal m f = normalOf m . fieldGradient f

-- | The unit normal from the field's gradient there.
normalOf :: Field a => Metric -> V3 a -> V3 a
{-# INLINE normalOf #-}
normalOf Euclidean = safeNormalize
normalOf m = normalizeIn m . raise m

-- | The sphere tracer's step: @|f|/|∇f|@, or @|f|@ where the gradient is
-- zero, infinite or NaN (on an axis of symmetry, at a centre), so a ray
-- never stalls or jumps there.
traceDistance :: Field a => ScalarFn -> V3 a -> a
traceDistance sf p =
  let f = abs (evalFn sf p)
      g = norm (fieldGradient sf p)
      usable = select (g - constant 1e-12) (select (constant 1e20 - g) 1 0) 0
  in select usable (f / g) f

-- | How near 0 the field must be for a point to count as on the surface:
-- projections stop moving it there.
projectionTolerance :: Double
projectionTolerance = 1e-10

-- | Enough Newton steps for points within a body's size of the surface: the
-- iteration converges quadratically, and converged steps are no-ops.
defaultProjectionIterations :: Int
defaultProjectionIterations = 8

-- | Pull a point back onto the surface along the normal (Newton's method on
-- @f@ along @∇f@: @p ← p − f ∇f/|∇f|²@), until @|f| < 1e-10@ or the count
-- runs out. A point where the gradient vanishes stays where it is.
--
-- >>> norm (projectToSurface unitSphere (V3 0 3 4) - V3 0 0.6 0.8 :: V3 Double) < 1e-15
-- True
-- >>> projectToSurface unitSphere (V3 0 0 0 :: V3 Double)
-- V3 0.0 0.0 0.0
projectToSurface :: Field a => ScalarFn -> V3 a -> V3 a
projectToSurface = projectToSurfaceWith defaultProjectionIterations

-- | 'projectToSurface' with at most this many Newton steps (the page's
-- sphere tracer takes two).
projectToSurfaceWith :: Field a => Int -> ScalarFn -> V3 a -> V3 a
projectToSurfaceWith n sf = go n
  where
    go 0 p = p
    go k p =
      let v = evalFn sf p
          g = fieldGradient sf p
          q = quadrance g
          -- move only while off the surface and where the gradient is
          -- usable; otherwise keep the point (component by component, so a
          -- NaN gradient cannot leak in)
          moving = select (abs v - constant projectionTolerance) (select q 1 0) 0
          s = v / q
      in go (k - 1) (select moving <$> (p ^-^ s *^ g) <*> p)

-- | The orthogonal projection (under the metric) of an ambient vector onto
-- the tangent plane with unit normal @n@: @v − ⟨n, v⟩ n / ⟨n, n⟩@.
--
-- >>> tangentProjection Euclidean (V3 0 1 0) (V3 1 2 3 :: V3 Double)
-- V3 1.0 0.0 3.0
-- >>> tangentProjection Minkowski (V3 0 1 0) (V3 1 2 3 :: V3 Double)
-- V3 1.0 0.0 3.0
tangentProjection :: Field a => Metric -> V3 a -> V3 a -> V3 a
{-# INLINE tangentProjection #-}
tangentProjection Euclidean n v = v ^-^ (n `dot` v) *^ n
tangentProjection m n v = v ^-^ (constant (normalSign m) * inner m n v) *^ n

-- | Carry a tangent vector to the tangent plane at another (nearby) point:
-- project (the Levi-Civita connection of an embedded surface is the projected
-- ambient derivative), then restore the old length.
transport :: Field a => Metric -> ScalarFn -> V3 a -> V3 a -> V3 a
{-# INLINE transport #-}
transport m sf p' v =
  let n = unitNormal m sf p'
      w = tangentProjection m n v
  in normIn m v *^ normalizeIn m w

-- | Newton steps when pulling back after a geodesic step: the point starts
-- @O(h²)@ off the surface and Newton converges quadratically, so three reach
-- rounding error for any step shorter than the surface's radius of
-- curvature.
stepProjectionIterations :: Int
stepProjectionIterations = 3

-- | Pull a point back onto the surface along a fixed direction @n@ (Newton
-- on @λ ↦ f(q + λn)@), and return the gradient of the field at the last
-- Newton iterate too. Moving along the normal of the point a step started
-- from is what makes 'geodesicStep' the RATTLE scheme for a particle held on
-- @f = 0@: second order, and it conserves the angular momentum that a
-- symmetry of the surface gives (Clairaut's relation on a surface of
-- revolution). Where @∇f · n@ vanishes the point is left where it is.
-- The gradient is the one at the point the final Newton step starts from:
-- each iteration evaluates
-- the value and the gradient together, and the last gradient serves as the
-- new point's normal. The final step moves the point by @|f|/|∇f·n|@, at
-- rounding error once converged, so the normal it leaves behind is the one
-- at the returned point to that order.
projectAlongWithGradient :: forall a. Field a => ScalarFn -> V3 a -> V3 a -> (V3 a, V3 a)
{-# INLINE projectAlongWithGradient #-}
projectAlongWithGradient sf n = go stepProjectionIterations
  where
    go :: Int -> V3 a -> (V3 a, V3 a)
    go k q =
      let (q', g) = newtonAlong sf n q
      in if k <= 1 then (q', g) else go (k - 1) q'

-- | One Newton iteration of 'projectAlongWithGradient': the next iterate, and the
-- field's gradient at this one. Converged (or where @∇f · n@ vanishes) the
-- point stays.
newtonAlong :: Field a => ScalarFn -> V3 a -> V3 a -> (V3 a, V3 a)
{-# INLINE newtonAlong #-}
newtonAlong sf n q =
  let (v, g) = valueGradFn sf q
      slope = g `dot` n
      moving = select (abs v - constant projectionTolerance) (select (abs slope) 1 0) 0
  in (select moving <$> (q ^-^ (v / slope) *^ n) <*> q, g)

-- | One step of a geodesic (RATTLE): move along the velocity for time @h@,
-- pull back onto the surface along the normal where the step began, take
-- the step's mean velocity, project it onto the new tangent plane and give it
-- back the speed it had. A step of length 0 changes nothing.
geodesicStep :: Field a => Metric -> ScalarFn -> a -> (V3 a, V3 a) -> (V3 a, V3 a)
geodesicStep m sf h (p, v) =
  let (p', v', _) = geodesicStepFrom m sf h (unitNormal m sf p) (p, v)
  in (p', v')

-- | 'geodesicStep' from a point whose unit normal is known, returning the
-- normal at the new point too: a walk of many steps evaluates the gradient
-- once per step fewer.
geodesicStepFrom :: Field a => Metric -> ScalarFn -> a -> V3 a -> (V3 a, V3 a) -> (V3 a, V3 a, V3 a)
{-# INLINE geodesicStepFrom #-}
geodesicStepFrom m sf h n (p, v) =
  geodesicStepEnd m h n (p, v) (projectAlongWithGradient sf n (p ^+^ h *^ v))

-- | The end of 'geodesicStepFrom', once the moved point @p + h·v@ has been
-- pulled back onto the surface: from that point and the gradient left by
-- 'projectAlongWithGradient', the new point, velocity and unit normal.
geodesicStepEnd :: Field a => Metric -> a -> V3 a -> (V3 a, V3 a) -> (V3 a, V3 a) -> (V3 a, V3 a, V3 a)
{-# INLINE geodesicStepEnd #-}
geodesicStepEnd m h n (p, v) (p', g') =
  let mean = select (abs h) (recip h) 0 *^ (p' ^-^ p)
      n' = normalOf m g'
      v' = normIn m v *^ normalizeIn m (tangentProjection m n' mean)
      moved = select (abs h) 1 0
      kept = 1 - moved
  in (moved *^ p' ^+^ kept *^ p, moved *^ v' ^+^ kept *^ v, moved *^ n' ^+^ kept *^ n)

-- | The exponential map: walk a geodesic of the given length from a point in
-- a tangent direction (normalised here), in @n@ equal steps. Returns the end
-- point and the unit direction there. On the unit sphere, a quarter of a
-- great circle from the north pole reaches the equator:
--
-- >>> let (p, dir) = expMap Euclidean unitSphere 64 (V3 0 1 0) (V3 1 0 0) (pi / 2 :: Double)
-- >>> norm (p - V3 1 0 0) < 1e-3 && norm (dir - V3 0 (-1) 0) < 1e-3
-- True
expMap :: Field a => Metric -> ScalarFn -> Int -> V3 a -> V3 a -> a -> (V3 a, V3 a)
expMap m sf n p dir len = last (geodesicPath m sf n p dir len)

-- | The points of the walk 'expMap' makes, the start included.
geodesicPath :: Field a => Metric -> ScalarFn -> Int -> V3 a -> V3 a -> a -> [(V3 a, V3 a)]
geodesicPath m sf n p dir len =
  let h = len / fromIntegral (max 1 n)
      d0 = normalizeIn m (tangentProjection m (unitNormal m sf p) dir)
  in take (max 1 n + 1) (iterate (geodesicStep m sf h) (p, d0))

-- | A tangent frame @(u, n × u)@ at a point with unit normal @n@, from a
-- tangent axis @u@ (the second vector is 'perpendicular''s).
tangentFrame :: Field a => Metric -> V3 a -> V3 a -> (V3 a, V3 a)
{-# INLINE tangentFrame #-}
tangentFrame m n u = (u, perpendicular m n u)

-- | The axis a body placed where the unit normal is @n@ starts with: the
-- x axis projected to the tangent plane, or the z axis where the x axis is
-- nearly the normal. A body's angle is measured from its axis, which it
-- then carries along.
referenceAxis :: Field a => Metric -> V3 a -> V3 a
{-# INLINE referenceAxis #-}
referenceAxis m n =
  let ax1 = tangentProjection m n (V3 1 0 0)
      ax2 = tangentProjection m n (V3 0 0 1)
      l1 = normIn m ax1
  in normalizeIn m (select (l1 - 0.5) 1 0 *^ ax1 ^+^ select (l1 - 0.5) 0 1 *^ ax2)
