-- | What a space is (paper §2.2, §2.6, §4.3): a surface @f = 0@ given by a
-- polymorphic distance field, an optional boundary @b(p) >= 0@, a gravity
-- field, a quotient, and how to look at it and what to put on it first.
module Manifold.Space
  ( Space (..)
  , Quotient (..)
  , Camera (..)
  , Placement (..)
  , ShapeKind (..)
  , space
  , quotientName
  , Isometry (..)
  , identityIso
  , applyIso
  , applyLinear
  , inverseIso
  , quotientImages
  , selfImage
  , wrapLattice
  , nearestImage
  , nearestImageWith
  , distanceToDomain
  , quotientWrap
  , domainDistance
  , pickSigns
  , hasBoundary
  , field
  , evalField
  , evalBoundary
  , evalGravity
  , uniformGravity
  , noGravity
  ) where

import Data.Maybe (isJust)
import Linear.Metric (quadrance)
import Linear.V3 (V3 (..))
import Linear.Vector ((^-^))

import Manifold.Field
import Manifold.Metric

-- $setup
-- >>> import Linear.Metric (norm)
-- >>> import Manifold.AD (scalarFn)
-- >>> import Manifold.Spaces (sphere)

-- | How points are identified.
data Quotient
  = NoQuotient -- ^ none: the surface itself.
  | Antipodal -- ^ @p ~ −p@: the space must be symmetric about the origin.
  | Lattice
      { latticePeriod :: Double -- ^ @L@, the side of the fundamental square
      , latticeFlip :: Bool -- ^ whether a translation along x mirrors z
      }
    -- ^ The plane @y = 0@ modulo translations by the period along x and
    -- along z (the flat torus); with the flip, a translation along x also
    -- mirrors z, @(x, z) ~ (x + L, −z)@ (the flat Klein bottle). The
    -- fundamental domain is the square @[−L/2, L/2]²@; bodies are kept in it.
  deriving (Show, Eq)

-- | The quotient's name, as @manifold spaces@ lists it.
--
-- >>> map quotientName [NoQuotient, Antipodal, Lattice 2 False, Lattice 2 True]
-- ["none","antipodal","translations","glide"]
quotientName :: Quotient -> String
quotientName NoQuotient = "none"
quotientName Antipodal = "antipodal"
quotientName (Lattice _ False) = "translations"
quotientName (Lattice _ True) = "glide"

-- | An isometry of R³ that is diagonal in the axes: @p ↦ signs·p + shift@
-- (componentwise). Enough for every quotient here: @p ↦ −p@, translations,
-- and translations composed with a mirror.
data Isometry = Isometry
  { isoSigns :: V3 Double -- ^ each axis kept (1) or mirrored (−1)
  , isoShift :: V3 Double -- ^ the translation after the mirroring
  } deriving (Show, Eq)

-- | The isometry that moves nothing.
identityIso :: Isometry
identityIso = Isometry (V3 1 1 1) (V3 0 0 0)

-- | The image of a point.
--
-- >>> applyIso (Isometry (V3 1 1 (-1)) (V3 2 0 0)) (V3 0.5 0 0.25 :: V3 Double)
-- V3 2.5 0.0 (-0.25)
applyIso :: Field a => Isometry -> V3 a -> V3 a
applyIso (Isometry s t) p = (fmap constant s * p) + fmap constant t

-- | The isometry's linear part (how it maps directions).
applyLinear :: Field a => Isometry -> V3 a -> V3 a
applyLinear (Isometry s _) v = fmap constant s * v

-- | The isometry that undoes this one.
--
-- >>> let g = Isometry (V3 1 1 (-1)) (V3 2 0 1)
-- >>> applyIso (inverseIso g) (applyIso g (V3 0.5 0 0.25 :: V3 Double))
-- V3 0.5 0.0 0.25
inverseIso :: Isometry -> Isometry
inverseIso (Isometry s t) = Isometry s (negate (s * t))

-- | The images a body meets: the non-trivial elements of the quotient's
-- group that move the fundamental domain next to itself (for a lattice, the
-- 8 neighbouring squares; bodies must be smaller than half the period).
-- The list is closed under inverses.
--
-- >>> map length [quotientImages NoQuotient, quotientImages Antipodal, quotientImages (Lattice 2 True)]
-- [0,1,8]
quotientImages :: Quotient -> [Isometry]
quotientImages NoQuotient = []
quotientImages Antipodal = [Isometry (V3 (-1) (-1) (-1)) (V3 0 0 0)]
quotientImages (Lattice period flipped) =
  [ Isometry (V3 1 1 (mirror i)) (V3 (period * fromIntegral i) 0 (period * fromIntegral k))
  | i <- [-1, 0, 1 :: Int], k <- [-1, 0, 1 :: Int], (i, k) /= (0, 0) ]
  where
    mirror i = if flipped && odd i then -1 else 1

-- | Whether a body meets its own image under this isometry in the contact
-- search: of an isometry and its inverse (both in 'quotientImages'), one
-- is chosen, so that the body's contact with its own image is found once.
selfImage :: Isometry -> Bool
selfImage g = let g' = inverseIso g in g == g' || toList (isoShift g) > toList (isoShift g')
  where toList (V3 a b c) = [a, b, c]

-- | A point of the plane moved into the fundamental square @[−L/2, L/2)²@ by
-- the lattice's group, and the sign its z axis (and so orientation) took:
-- −1 when the flip was used an odd number of times.
--
-- >>> wrapLattice 2 True (V3 1.5 0 0.25 :: V3 Double)
-- (V3 (-0.5) 0.0 (-0.25),-1.0)
wrapLattice :: Field a => Double -> Bool -> V3 a -> (V3 a, a)
wrapLattice period flipped (V3 x y z) =
  let l = constant period
      kx = floorF ((x + 0.5 * l) / l)
      kz = floorF ((z + 0.5 * l) / l)
      parity = kx - 2 * floorF (0.5 * kx)
      s = if flipped then 1 - 2 * parity else 1
  in (V3 (x - kx * l) y (s * (z - kz * l)), s)

-- | How far a point of the plane is outside the fundamental square (0 inside).
--
-- >>> map (distanceToDomain 2) [V3 0.5 0 0.5, V3 4 0 (-5)] :: [Double]
-- [0.0,5.0]
distanceToDomain :: Field a => Double -> V3 a -> a
distanceToDomain period (V3 x _ z) =
  let h = constant (0.5 * period)
      dx = maxF 0 (abs x - h)
      dz = maxF 0 (abs z - h)
  in sqrt (dx * dx + dz * dz)

-- The quotient as the engine meets it: the collision phase, the motion,
-- picking and grabbing ask these (and 'quotientImages', 'nearestImage',
-- 'selfImage'), never the quotient's constructors.

-- | Where a point that left the fundamental domain comes back into it,
-- and the orientation it comes back with (1, or −1 through a flipping
-- edge); 'Nothing' for a quotient whose points never leave it.
quotientWrap :: Field a => Quotient -> Maybe (V3 a -> (V3 a, a))
quotientWrap = \case
  Lattice period flipped -> Just (wrapLattice period flipped)
  _ -> Nothing

-- | How far a point is outside the fundamental domain, for a quotient that
-- has one: a body's images farther than its reach meet nothing.
domainDistance :: Field a => Quotient -> Maybe (V3 a -> a)
domainDistance = \case
  Lattice period _ -> Just (distanceToDomain period)
  _ -> Nothing

-- | The signs a pick tries a surface point with: a body of the antipodal
-- quotient is also found through the image −q of the point picked.
pickSigns :: Quotient -> [Double]
pickSigns = \case
  Antipodal -> [1, -1]
  _ -> [1]

-- | Of the images of point @q@ (itself included), the one nearest @ref@;
-- with no quotient (or the antipodal one, whose images are far apart), @q@.
nearestImage :: Field a => Quotient -> V3 a -> V3 a -> V3 a
nearestImage (Lattice period flipped) ref q =
  let (q0, _) = wrapLattice period flipped q
      candidates = q0 : [applyIso g q0 | g <- quotientImages (Lattice period flipped)]
      pick (best, bd) c =
        let d = quadrance (c ^-^ ref)
            closer = bd - d -- positive: c is nearer than the best so far
        in (select closer <$> c <*> best, minF d bd)
  in fst (foldl pick (q0, quadrance (q0 ^-^ ref)) (drop 1 candidates))
nearestImage _ _ q = q

-- | Of the images of point @q@ (itself included) under the quotient's
-- group, the one nearest @ref@, with the signs of the isometry that gives
-- it (how it maps directions).
nearestImageWith :: Field a => Quotient -> V3 a -> V3 a -> (V3 a, V3 a)
nearestImageWith quo ref q = fst (foldl pick ((q, V3 1 1 1), quadrance (q ^-^ ref)) candidates)
  where
    candidates = [ (applyIso g q, fmap constant (isoSigns g)) | g <- quotientImages quo ]
    pick ((best, bestSigns), bd) (c, cs) =
      let d = quadrance (c ^-^ ref)
          closer = bd - d
      in ((select closer <$> c <*> best, select closer <$> cs <*> bestSigns), minF d bd)

-- | A pinhole camera looking at @cameraTarget@ from @cameraEye@.
data Camera = Camera
  { cameraEye :: V3 Double -- ^ where the camera is
  , cameraTarget :: V3 Double -- ^ the point at the centre of the view
  , cameraUp :: V3 Double -- ^ the direction that is up on the screen
  , cameraFov :: Double -- ^ vertical field of view, degrees
  } deriving (Show, Eq)

-- | The built-in shapes a scene names ("Manifold.Body" makes their
-- outlines).
data ShapeKind
  = CircleShape
  | SquareShape
  | PolygonShape Int -- ^ a regular polygon with this many sides (3 or more)
  | BoxShape Double Double -- ^ half-extents along the body's direction and across it
  | CapsuleShape Double Double -- ^ a segment along the body's direction (half its length), rounded by a radius
  | VerticesShape [(Double, Double)] Double -- ^ a convex polygon of 3 to 8 corners @(a, b)@ in the body's frame (placed by its centre of mass), rounded by a radius (0: sharp)
  deriving (Show, Eq)

-- | A body of the default scene: where it starts (projected onto the surface
-- on load), its shape and its size (circumradius).
data Placement = Placement
  { placeAt :: V3 Double -- ^ near the surface; projected onto it
  , placeShape :: ShapeKind
  , placeSize :: Double -- ^ circumradius
  , placeStatic :: Bool -- ^ a fixed body (a floor, a wall)
  } deriving (Show, Eq)

-- | A space: everything the engine, the page and the command line know of
-- it. Define one by updating 'space'.
data Space = Space
  { spaceName :: String -- ^ how scenes, the page and the command line name it
  , spaceDescription :: String -- ^ one line, for @manifold spaces@ and the page
  , spaceField :: ScalarFn -- ^ the surface is @f(p) = 0@
  , spaceBoundary :: Maybe ScalarFn -- ^ the allowed region is @b(p) >= 0@
  , spaceGravity :: VectorFn -- ^ an R³ field; the engine projects it
  , spaceQuotient :: Quotient -- ^ which points are one
  , spaceCamera :: Camera -- ^ the page's first view
  , spaceScene :: [Placement] -- ^ the bodies the page starts with
  , spaceBounds :: Double -- ^ radius of a ball around the origin holding the part of the surface worth drawing and simulating
  , spaceMetric :: Metric -- ^ the ambient metric the surface sits in ("Manifold.Metric"): R³'s, or Minkowski space's for the hyperbolic spaces
  , spaceAxis :: Maybe (V3 Double) -- ^ a unit axis through the origin the surface, its boundary and its quotient are symmetric about, if any: the bodies' angular momentum about it is conserved where gravity does not turn them about it ("Manifold.Measures")
  }

-- | A space in R³ with no boundary, no quotient, no gravity, a camera on the z axis
-- and an empty scene: the record to update when defining one.
--
-- >>> let ball = (space "ball" "the sphere of radius 2" (scalarFn (\p -> norm p - 2))) { spaceBounds = 4 }
-- >>> evalField ball (V3 0 3 0)
-- 1.0
space :: String -> String -> ScalarFn -> Space
space name description f = Space
  { spaceName = name
  , spaceDescription = description
  , spaceField = f
  , spaceBoundary = Nothing
  , spaceGravity = noGravity
  , spaceQuotient = NoQuotient
  , spaceCamera = Camera (V3 0 1.5 3.5) (V3 0 0 0) (V3 0 1 0) 45
  , spaceScene = []
  , spaceBounds = 3
  , spaceMetric = Euclidean
  , spaceAxis = Nothing
  }

-- | Whether the space has a boundary (a wall the bodies meet).
hasBoundary :: Space -> Bool
hasBoundary = isJust . spaceBoundary

-- | The field of a space, at any scalar: its value is 0 on the surface.
field :: Field a => Space -> V3 a -> a
field s = evalFn (spaceField s)

-- | The field of a space at a point, natively.
--
-- >>> evalField sphere (V3 0 3 0)
-- 2.0
-- >>> evalField sphere (V3 0.6 0 0.8)
-- 0.0
evalField :: Space -> V3 Double -> Double
evalField = field

-- | The boundary function; a space without a boundary is everywhere inside
-- (the constant 1).
--
-- >>> evalBoundary sphere (V3 0 (-1) 0) :: Double
-- 1.0
evalBoundary :: Field a => Space -> V3 a -> a
evalBoundary s p = case spaceBoundary s of
  Nothing -> 1
  Just b -> evalFn b p

-- | The space's gravity at a point (an R³ vector; the engine projects it
-- onto the tangent plane).
--
-- >>> evalGravity sphere (V3 1 0 0 :: V3 Double)
-- V3 0.0 (-4.0) 0.0
evalGravity :: Field a => Space -> V3 a -> V3 a
evalGravity s = let VectorFn g = spaceGravity s in g

-- | The same gravity everywhere.
uniformGravity :: V3 Double -> VectorFn
uniformGravity g = VectorFn (const (fmap constant g))

-- | No gravity: what 'space' gives a new space.
noGravity :: VectorFn
noGravity = uniformGravity (V3 0 0 0)
