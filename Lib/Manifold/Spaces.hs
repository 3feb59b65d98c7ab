-- | The catalogue of spaces. Adding a space is adding one value here (or in a
-- module of your own) and listing it in 'catalogue'.
module Manifold.Spaces
  ( catalogue
  , lookupSpace
  , spaceNames
  , plane, sphere, torus, trumpet, cube, hemisphere, disc, rectangle
  , projectivePlane, kleinBottle, moebius, funnel
  , flatTorus, flatKlein, flatPeriod
  , hyperbolicPlane, hyperbolicGravity, bolza
  , torusMajor, torusMinor
  ) where

import Data.List (find)
import Linear.Metric (norm)
import Linear.V2 (V2 (..))
import Linear.V3 (V3 (..))

import Manifold.AD (scalarFn)
import Manifold.Field
import Manifold.Metric (Metric (..))
import Manifold.Space

-- | Every space the command line, the page and the tests know, in the
-- page's order.
--
-- >>> length catalogue
-- 16
catalogue :: [Space]
catalogue =
  [ plane, sphere, torus, trumpet, cube, hemisphere, disc, rectangle
  , projectivePlane, kleinBottle, moebius, funnel, flatTorus, flatKlein
  , hyperbolicPlane, bolza ]

-- | The catalogue's names, in order.
--
-- >>> take 4 spaceNames
-- ["plane","sphere","torus","trumpet"]
spaceNames :: [String]
spaceNames = map spaceName catalogue

-- | The catalogue space of this name.
--
-- >>> fmap spaceDescription (lookupSpace "hemisphere")
-- Just "the lower half of the unit sphere (y <= 0), a bowl with a rim"
-- >>> fmap spaceName (lookupSpace "cylinder")
-- Nothing
lookupSpace :: String -> Maybe Space
lookupSpace n = find ((== n) . spaceName) catalogue

-- Fields -----------------------------------------------------------------

planeField :: Field a => V3 a -> a
planeField (V3 _ y _) = y

unitSphereField :: Field a => V3 a -> a
unitSphereField p = norm p - 1

-- | Distance from the y axis.
radial :: Field a => V3 a -> a
radial (V3 x _ z) = sqrt (x * x + z * z)

-- | The torus's radii: from the y axis to the tube's centre ('torusMajor'),
-- and the tube's ('torusMinor').
torusMajor, torusMinor :: Double
torusMajor = 0.8
torusMinor = 0.5

torusField :: Field a => V3 a -> a
torusField p@(V3 _ y _) = norm (V2 (radial p - constant torusMajor) y) - constant torusMinor

-- Scenes -----------------------------------------------------------------

ring :: Int -> Double -> Double -> ShapeKind -> Double -> [Placement]
ring n r y shape size =
  [ Placement (V3 (r * cos t) y (r * sin t)) (if even k then shape else CircleShape) size False
  | k <- [0 .. n - 1], let t = 2 * pi * fromIntegral k / fromIntegral n ]

grid :: [Double] -> [Double] -> ShapeKind -> Double -> [Placement]
grid xs zs shape size =
  [ Placement (V3 x 0 z) (if even (i + j) then shape else CircleShape) size False
  | (i, x) <- zip [0 :: Int ..] xs, (j, z) <- zip [0 :: Int ..] zs ]

-- | A camera on the origin. Spaces whose gravity is −z in the plane y = 0
-- are looked at from the −z side, so that "down" is down on the screen.
look :: V3 Double -> Camera
look eye = Camera eye (V3 0 0 0) (V3 0 1 0) 45

-- The catalogue ------------------------------------------------------------

-- | The plane @y = 0@, gravity along −z, a row of static squares as a
-- floor.
plane :: Space
plane = (space "plane" "the flat plane y = 0; gravity along -z" (scalarFn planeField))
  { spaceGravity = uniformGravity (V3 0 0 (-4))
  , spaceCamera = Camera (V3 0 3.2 (-3.2)) (V3 0 0 (-0.5)) (V3 0 1 0) 45
  , spaceScene = grid [-0.6, 0, 0.6] [-0.3, 0.3] SquareShape 0.2
      ++ [Placement (V3 x 0 (-1.2)) SquareShape 0.3 True | x <- [-1.2, -0.8 .. 1.2]]
  }

-- | The unit sphere, @|p| − 1@; gravity pulls to the south pole.
--
-- >>> evalField sphere (V3 0 0 1)
-- 0.0
-- >>> evalGravity sphere (V3 0 0 1 :: V3 Double)
-- V3 0.0 (-4.0) 0.0
sphere :: Space
sphere = (space "sphere" "the unit sphere; gravity pulls to the south pole" (scalarFn unitSphereField))
  { spaceGravity = uniformGravity (V3 0 (-4) 0)
  , spaceCamera = look (V3 0 (-1.8) 2.6)
  , spaceAxis = Just (V3 0 1 0)
  , spaceScene = ring 6 0.6 (-0.8) SquareShape 0.2
  }

-- | A torus about the y axis: curvature positive on the outside, negative
-- on the inside.
--
-- >>> evalField torus (V3 (torusMajor + torusMinor) 0 0)
-- 0.0
torus :: Space
torus = (space "torus" "a torus about the y axis, R = 0.8, r = 0.5 (curvature > 0 outside, < 0 inside)" (scalarFn torusField))
  { spaceGravity = uniformGravity (V3 0 0 (-4))
  , spaceCamera = look (V3 0 2.2 (-2.8))
  , spaceAxis = Just (V3 0 1 0)
  , spaceScene = ring 6 1.3 0 SquareShape 0.18
  }

-- | The horn @√(x² + z²) = e^y@, narrowing downwards: bodies falling into
-- it jam in the neck.
trumpet :: Space
trumpet = (space "trumpet" "sqrt(x²+z²) = exp y, a pseudosphere-like horn narrowing downwards; bodies jam in the neck" (scalarFn trumpetField))
  { spaceGravity = uniformGravity (V3 0 (-0.6) 0)
  , spaceCamera = Camera (V3 0 1.5 4.5) (V3 0 (-0.5) 0) (V3 0 1 0) 45
  , spaceAxis = Just (V3 0 1 0)
  , spaceScene = ring 4 (exp 0.3) 0.3 SquareShape 0.3
  , spaceBounds = 4
  }
  where trumpetField p@(V3 _ y _) = radial p - expF y

-- | A cube with rounded edges: flat faces, curved edges and corners.
cube :: Space
cube = (space "cube" "a cube with rounded edges (half-size 0.6, rounding 0.3)" (scalarFn roundedCube))
  { spaceGravity = uniformGravity (V3 0 (-4) 0)
  , spaceCamera = look (V3 1.8 1.8 2.6)
  , spaceScene = [Placement (V3 x 0.9 z) SquareShape 0.2 False | (x, z) <- [(-0.4, -0.4), (0.4, -0.4), (0, 0.4)]]
  }
  where
    roundedCube (V3 x y z) =
      let q = V3 (abs x - 0.6) (abs y - 0.6) (abs z - 0.6)
          V3 qx qy qz = q
          outside = norm (fmap (maxF 0) q)
          inside = minF 0 (maxF qx (maxF qy qz))
      in outside + inside - 0.3

-- | The lower half of the unit sphere, with a boundary at the rim.
hemisphere :: Space
hemisphere = (space "hemisphere" "the lower half of the unit sphere (y <= 0), a bowl with a rim" (scalarFn unitSphereField))
  { spaceBoundary = Just (scalarFn (\(V3 _ y _) -> negate y))
  , spaceGravity = uniformGravity (V3 0 (-4) 0)
  , spaceCamera = look (V3 0 2.2 2.2)
  , spaceAxis = Just (V3 0 1 0)
  , spaceScene = ring 5 0.5 (-0.8) SquareShape 0.18
  }

-- | The unit disc of the plane, with a circular wall.
disc :: Space
disc = (space "disc" "the unit disc on the plane y = 0, with a circular wall" (scalarFn planeField))
  { spaceBoundary = Just (scalarFn (\p -> 1 - radial p))
  , spaceGravity = uniformGravity (V3 0 0 (-4))
  , spaceCamera = look (V3 0 2.2 (-1.6))
  , spaceAxis = Just (V3 0 1 0)
  , spaceScene = grid [-0.4, 0, 0.4] [-0.2, 0.3] SquareShape 0.15
  }

-- | A 3 × 2 rectangle of the plane, walled.
rectangle :: Space
rectangle = (space "rectangle" "the rectangle |x| <= 1.5, |z| <= 1 on the plane y = 0, a box with walls" (scalarFn planeField))
  { spaceBoundary = Just (scalarFn (\(V3 x _ z) -> minF (1.5 - abs x) (1 - abs z)))
  , spaceGravity = uniformGravity (V3 0 0 (-4))
  , spaceCamera = look (V3 0 2.8 (-2.0))
  , spaceScene = grid [-0.8, -0.3, 0.3, 0.8] [-0.3, 0.3] SquareShape 0.18
  }

-- | The real projective plane: the unit sphere with @p ~ −p@, gravity
-- pulling to the pole (one point). Gravity for quotient spaces must be odd
-- (@g(−p) = −g(p)@) so that a body and its image feel the same force.
projectivePlane :: Space
projectivePlane = (space "projective-plane" "the real projective plane: the unit sphere with p ~ -p; gravity pulls to the pole (0,±1,0), one point" (scalarFn unitSphereField))
  { spaceQuotient = Antipodal
  , spaceGravity = VectorFn (\(V3 _ y _) -> V3 0 (4 * y) 0)
  , spaceCamera = look (V3 0 1.2 3)
  , spaceAxis = Just (V3 0 1 0)
  , spaceScene = ring 3 0.8 0.5 SquareShape 0.2
  }

-- | The torus centred on the origin with @p ~ −p@: a Klein bottle.
kleinBottle :: Space
kleinBottle = (space "klein-bottle" "the origin-centred torus with p ~ -p, a Klein bottle (the paper's projective torus); gravity pulls to the axis" (scalarFn torusField))
  { spaceQuotient = Antipodal
  , spaceGravity = VectorFn (\(V3 x _ z) -> V3 (-3 * x) 0 (-3 * z))
  , spaceCamera = look (V3 0 2.2 2.8)
  , spaceAxis = Just (V3 0 1 0)
  , spaceScene = ring 3 1.3 0 SquareShape 0.18
  }

-- | A band of the unit cylinder with @p ~ −p@: a Möbius strip, its edges
-- a boundary.
moebius :: Space
moebius = (space "moebius" "the cylinder of radius 1, |y| <= 0.4, with p ~ -p: a Moebius strip; gravity pulls to the centre line" (scalarFn (\p -> radial p - 1)))
  { spaceQuotient = Antipodal
  , spaceBoundary = Just (scalarFn (\(V3 _ y _) -> 0.4 - abs y))
  , spaceGravity = VectorFn (\(V3 _ y _) -> V3 0 (-4 * y) 0)
  , spaceCamera = look (V3 0 2.2 2.8)
  , spaceAxis = Just (V3 0 1 0)
  , spaceScene = ring 3 1 0.1 SquareShape 0.15
  }

-- | The paper's two-dimensional trumpet: a region of the plane narrowing
-- exponentially, gravity pushing bodies into the neck.
funnel :: Space
funnel = (space "funnel" "the paper's two-dimensional trumpet: the plane with |x| <= exp(0.9z - 0.7), |z| <= 1; gravity pushes into the neck" (scalarFn planeField))
  { spaceBoundary = Just (scalarFn (\(V3 x _ z) -> minF (expF (0.9 * z - 0.7) - abs x) (1 - abs z)))
  , spaceGravity = uniformGravity (V3 0 0 (-4))
  , spaceCamera = look (V3 0 2.6 (-1.2))
  , spaceScene = [Placement (V3 x 0 z) SquareShape 0.15 False | (x, z) <- [(-0.3, 0.6), (0.3, 0.6), (0, 0.2)]]
  }

-- | The period of the flat spaces: the fundamental square is [−1, 1]² in x
-- and z (paper §4.4).
flatPeriod :: Double
flatPeriod = 2

-- | A camera above the square, looking down at it.
overSquare :: Camera
overSquare = Camera (V3 0 3.4 (-1.4)) (V3 0 0 0) (V3 0 1 0) 45

-- | The flat torus: the plane modulo the square lattice of period
-- 'flatPeriod' (curvature 0 everywhere, no gravity).
flatTorus :: Space
flatTorus = flatSpace "flat-torus" "the flat torus: the square [-1,1]^2 of the plane y = 0 with opposite edges glued (period 2 in x and z); curvature 0 everywhere, no gravity" False

-- | The flat Klein bottle: as 'flatTorus', but its x edges glued with a
-- mirror, @(x, z) ~ (x + 2, −z)@.
flatKlein :: Space
flatKlein = flatSpace "flat-klein" "the flat Klein bottle: the square [-1,1]^2 of the plane y = 0, z edges glued straight, x edges glued with a flip (x, z) ~ (x + 2, -z); no gravity" True

-- | The plane y = 0 modulo the square lattice of period 2, its x edges
-- glued with a flip or not.
flatSpace :: String -> String -> Bool -> Space
flatSpace name description flipped = (space name description (scalarFn planeField))
  { spaceQuotient = Lattice flatPeriod flipped
  , spaceCamera = overSquare
  , spaceScene = grid [-0.5, 0.5] [-0.5, 0.5] SquareShape 0.18
  , spaceBounds = 2
  }

-- | The hyperbolic plane (curvature −1 everywhere), which no surface of R³
-- is: the upper sheet of the hyperboloid @y² − x² − z² = 1@ in Minkowski
-- space ("Manifold.Metric"). Gravity pulls to the vertex @(0, 1, 0)@.
--
-- >>> evalField hyperbolicPlane (V3 (sinh 1) (cosh 1) 0) < 1e-15
-- True
hyperbolicPlane :: Space
hyperbolicPlane = (space "hyperbolic-plane" "the hyperbolic plane (curvature -1): the hyperboloid y^2 - x^2 - z^2 = 1, y > 0, in Minkowski space; gravity pulls to the vertex (0,1,0)" (scalarFn hyperboloidField))
  { spaceMetric = Minkowski
  , spaceGravity = VectorFn (\(V3 _ y _) -> V3 0 (constant hyperbolicGravity / y) 0)
  , spaceCamera = Camera (V3 0 5.4 (-5.0)) (V3 0 1.6 0) (V3 0 1 0) 45
  , spaceAxis = Just (V3 0 1 0)
  , spaceScene = hyperbolicRing 6 0.7 SquareShape 0.2 ++ hyperbolicRing 3 1.4 SquareShape 0.25
  , spaceBounds = 4.5
  }
  where
    hyperbolicRing n r shape size =
      [ Placement (V3 (sinh r * cos t) (cosh r) (sinh r * sin t)) (if even k then shape else CircleShape) size False
      | k <- [0 .. n - 1 :: Int], let t = 2 * pi * (fromIntegral k + 0.5 * r) / fromIntegral n ]

-- | The upper sheet of the hyperboloid @y² − x² − z² = 1@: not a distance
-- (|∇f| runs from 1 to √2 in R³): the engine only needs the surface and
-- its normal, the tracer f/|∇f|.
hyperboloidField :: Field a => V3 a -> a
hyperboloidField (V3 x y z) = sqrt (1 + x * x + z * z) - y

-- | The Bolza surface: the hyperbolic plane modulo the group that pairs
-- opposite sides of the regular octagon with angles π/4 about the vertex
-- ("Manifold.Bolza"), the most symmetric compact surface of genus 2, of
-- area 4π. No gravity: no field on it both keeps to the group and pulls
-- anywhere, so its scenes are thrown bodies. A body leaving the octagon
-- through one side comes back through the opposite one.
bolza :: Space
bolza = (space "bolza" "the Bolza surface (genus 2, curvature -1): the hyperbolic plane modulo the side pairings of the regular octagon with angles pi/4; no gravity" (scalarFn hyperboloidField))
  { spaceMetric = Minkowski
  , spaceQuotient = OctagonPairings
  , spaceCamera = Camera (V3 0 12 (-11)) (V3 0 3 0) (V3 0 1 0) 45
  , spaceScene =
      [ Placement (V3 (sinh r * cos t) (cosh r) (sinh r * sin t)) shape 0.25 False
      | (k, (r, shape)) <- zip [0 :: Int ..] (replicate 8 (1.1, SquareShape) ++ replicate 8 (2.0, CircleShape))
      , let t = 2 * pi * fromIntegral k / 8 + (if r > 1.5 then pi / 8 else 0) ]
  , spaceBounds = 8.5
  }

-- | The pull of the hyperbolic plane's gravity: the ambient field
-- @(0, G/y, 0)@, projected onto the hyperboloid under the metric, is
-- @G tanh r@ toward the vertex at hyperbolic distance @r@ (the potential
-- @G log cosh r@): like the sphere's, it grows from the vertex, and it
-- stays bounded however far a body is thrown.
hyperbolicGravity :: Double
hyperbolicGravity = 4
