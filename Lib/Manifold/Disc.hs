-- | The hyperbolic plane's flat pictures: the Poincaré and the Klein disc of
-- the hyperboloid @y² − x² − z² = 1@ ("Manifold.Metric"'s Minkowski space),
-- the Lorentz boosts that move a viewer through the plane, and a grid of its
-- geodesics. The page draws hyperbolic spaces through these (printed into
-- web/gen by "Manifold.Stage.Kernels"); the physics never uses them.
--
-- A view is a Lorentz matrix @B@ (a 3 × 3 matrix keeping the metric
-- @x² − y² + z²@ and the upper sheet): a world point @p@ is seen at @B p@,
-- and the picture is centred on the vertex @(0, 1, 0)@ of what it sees. A
-- matrix is nine numbers, row by row.
module Manifold.Disc
  ( fromPoincare
  , toPoincare
  , fromKlein
  , toKlein
  , translationTo
  , applyBoost
  , composeBoosts
  , inverseBoost
  , renormaliseBoost
  , geodesicGrid
  ) where

import Linear.V3 (V3 (..))

import Manifold.Field

-- $setup
-- >>> let close a b = abs (a - b) < (1e-12 :: Double)

-- | The hyperboloid's point at @(u, w)@ of the Poincaré disc (the
-- stereographic projection from @(0, −1, 0)@, inverted); @u@ along x, @w@
-- along z.
--
-- >>> fromPoincare 0 (0 :: Double)
-- V3 0.0 1.0 0.0
-- >>> let V3 x y z = fromPoincare 0.3 (-0.5 :: Double) in close (y * y - x * x - z * z) 1
-- True
fromPoincare :: Field a => a -> a -> V3 a
fromPoincare u w =
  let r2 = u * u + w * w
      d = 1 - r2
  in V3 (2 * u / d) ((1 + r2) / d) (2 * w / d)

-- | A hyperboloid point's place in the Poincaré disc.
--
-- >>> let (u, w) = toPoincare (fromPoincare 0.3 (-0.5 :: Double)) in (close u 0.3, close w (-0.5))
-- (True,True)
toPoincare :: Field a => V3 a -> (a, a)
toPoincare (V3 x y z) = (x / (1 + y), z / (1 + y))

-- | The hyperboloid's point at @(u, w)@ of the Klein disc (the central
-- projection onto the plane @y = 1@, inverted), where geodesics are straight.
--
-- >>> let V3 x y z = fromKlein 0.6 (0.2 :: Double) in (close (y * y - x * x - z * z) 1, close (x / y) 0.6)
-- (True,True)
fromKlein :: Field a => a -> a -> V3 a
fromKlein u w =
  let s = 1 / sqrt (1 - u * u - w * w)
  in V3 (u * s) s (w * s)

-- | A hyperboloid point's place in the Klein disc.
toKlein :: Field a => V3 a -> (a, a)
toKlein (V3 x y z) = (x / y, z / y)

-- | The boost that carries the vertex @(0, 1, 0)@ to the point @p@ of the
-- sheet along the geodesic between them, turning nothing about it: a
-- translation of the plane (the identity at the vertex). A walk that keeps
-- the point under a pointer takes @p@ to @q@ by @translationTo q@ after the
-- inverse of @translationTo p@.
--
-- >>> let p = fromPoincare 0.4 (-0.3 :: Double); V3 x y z = applyBoost (translationTo p) (V3 0 1 0) in (close x (let V3 a _ _ = p in a), close y (let V3 _ b _ = p in b))
-- (True,True)
-- >>> translationTo (V3 0 1 (0 :: Double))
-- [1.0,0.0,0.0,0.0,1.0,0.0,0.0,0.0,1.0]
translationTo :: Field a => V3 a -> [a]
translationTo (V3 x y z) =
  let k = 1 / (1 + y)
  in [ 1 + k * x * x, x, k * x * z
     , x, y, z
     , k * x * z, z, 1 + k * z * z ]

-- | A matrix (nine numbers, row by row) times a point.
applyBoost :: Field a => [a] -> V3 a -> V3 a
applyBoost [m0, m1, m2, m3, m4, m5, m6, m7, m8] (V3 x y z) =
  V3 (m0 * x + m1 * y + m2 * z) (m3 * x + m4 * y + m5 * z) (m6 * x + m7 * y + m8 * z)
applyBoost m _ = error ("applyBoost: a matrix is nine numbers, not " ++ show (length m))

-- | The product @m n@ (first @n@, then @m@).
--
-- >>> let m = composeBoosts (translationTo (fromPoincare 0.4 0.1)) (translationTo (fromPoincare (-0.4) (-0.1 :: Double))) in and (zipWith close m [1, 0, 0, 0, 1, 0, 0, 0, 1])
-- True
composeBoosts :: Field a => [a] -> [a] -> [a]
composeBoosts m n =
  [ sum [ at m i k * at n k j | k <- [0 .. 2] ] | i <- [0 .. 2], j <- [0 .. 2] ]
  where at x i j = x !! (3 * i + j)

-- | The inverse of a Lorentz matrix: @J mᵀ J@ with @J = diag(1, −1, 1)@.
--
-- >>> let m = composeBoosts (translationTo (fromKlein 0.6 0.2)) (translationTo (fromPoincare 0.1 (-0.7 :: Double))) in and (zipWith close (composeBoosts (inverseBoost m) m) [1, 0, 0, 0, 1, 0, 0, 0, 1])
-- True
inverseBoost :: Field a => [a] -> [a]
inverseBoost m = [ sign i * sign j * m !! (3 * j + i) | i <- [0 .. 2], j <- [0 .. 2] ]
  where sign k = if k == (1 :: Int) then -1 else 1

-- | The Lorentz matrix nearest a product of many (which round-off moves off
-- the group): its columns made orthonormal again in the Minkowski metric,
-- the time-like one (the image of the vertex) first, keeping their
-- directions.
--
-- >>> let m = translationTo (fromPoincare 0.5 (0.2 :: Double)) in and (zipWith close (renormaliseBoost m) m)
-- True
renormaliseBoost :: Field a => [a] -> [a]
renormaliseBoost m =
  let col j = V3 (m !! j) (m !! (3 + j)) (m !! (6 + j))
      ip (V3 a b c) (V3 d e f) = a * d - b * e + c * f
      scale k (V3 a b c) = V3 (k * a) (k * b) (k * c)
      plus (V3 a b c) (V3 d e f) = V3 (a + d) (b + e) (c + f)
      t = scale (1 / sqrt (negate (ip (col 1) (col 1)))) (col 1)
      -- off t: v + ⟨v, t⟩ t (⟨t, t⟩ = −1); off a unit space-like a: v − ⟨v, a⟩ a
      offT v = plus v (scale (ip v t) t)
      unit v = scale (1 / sqrt (ip v v)) v
      x = unit (offT (col 0))
      z0 = offT (col 2)
      z = unit (plus z0 (scale (negate (ip z0 x)) x))
      V3 x0 x1 x2 = x
      V3 t0 t1 t2 = t
      V3 z1 z2 z3 = z
  in [x0, t0, z1, x1, t1, z2, x2, t2, z3]

-- | The grid of geodesics the page draws: the signed distances, along the
-- geodesics through the vertex in x and in z, of the geodesics through a
-- point perpendicular to those; a line of the grid is where one of them is
-- a whole number of spacings (the planes @x = y tanh d@ and @z = y tanh d@
-- through the origin: geodesics).
--
-- >>> let (g, h) = geodesicGrid (V3 (sinh 0.8) (cosh 0.8) (0 :: Double)) in (close g 0.8, close h 0)
-- (True,True)
geodesicGrid :: Field a => V3 a -> (a, a)
geodesicGrid (V3 x y z) = (0.5 * log ((y + x) / (y - x)), 0.5 * log ((y + z) / (y - z)))
