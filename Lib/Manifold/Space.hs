{-# LANGUAGE DeriveFunctor #-}
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
  , IsometryOf (..)
  , Isometry
  , diagonalIso
  , identityIso
  , linearMap
  , applyIso
  , applyLinear
  , inverseIso
  , determinant
  , isoCoefficients
  , isoFromCoefficients
  , quotientImages
  , quotientMetric
  , mostImages
  , jointsRefused
  , wrapJump
  , selfImage
  , wrapLattice
  , nearestImage
  , nearestImageWith
  , distanceToDomain
  , Wrapped (..)
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
import Linear.V3 (V3 (..))
import Linear.Vector ((^-^))

import Manifold.Bolza (inradius, sideExcess, touchingImages, wrapIntoOctagon)
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
  | OctagonPairings
    -- ^ The hyperbolic plane (the hyperboloid in Minkowski space) modulo
    -- the group that pairs opposite sides of the regular octagon with
    -- angles π/4 centred at the vertex @(0, 1, 0)@: the Bolza surface, of
    -- genus 2 ("Manifold.Bolza"). Bodies are kept in the octagon.
  deriving (Show, Eq)

-- | The quotient's name, as @manifold spaces@ lists it.
--
-- >>> map quotientName [NoQuotient, Antipodal, Lattice 2 False, Lattice 2 True, OctagonPairings]
-- ["none","antipodal","translations","glide","octagon"]
quotientName :: Quotient -> String
quotientName NoQuotient = "none"
quotientName Antipodal = "antipodal"
quotientName (Lattice _ False) = "translations"
quotientName (Lattice _ True) = "glide"
quotientName OctagonPairings = "octagon"

-- | An isometry of the ambient space: @p ↦ L p + t@, its linear part @L@
-- by rows. R³'s quotients use diagonal ones (@p ↦ −p@, translations,
-- translations composed with a mirror); the Bolza surface's are Lorentz
-- matrices with no shift. The step passes one as twelve numbers
-- ('isoCoefficients'), so its coefficients may be staged too.
data IsometryOf a = Isometry
  { isoLinear :: V3 (V3 a) -- ^ the linear part's rows
  , isoShift :: V3 a -- ^ the translation after it
  } deriving (Show, Eq, Functor)

-- | An isometry with numbers for coefficients: what a quotient is made of.
type Isometry = IsometryOf Double

-- | The diagonal isometry @p ↦ signs·p + shift@ (componentwise).
diagonalIso :: Num a => V3 a -> V3 a -> IsometryOf a
diagonalIso (V3 a b c) = Isometry (V3 (V3 a 0 0) (V3 0 b 0) (V3 0 0 c))

-- | The isometry that moves nothing.
identityIso :: Num a => IsometryOf a
identityIso = diagonalIso (V3 1 1 1) (V3 0 0 0)

-- | A linear map (by rows) applied to a vector.
--
-- >>> linearMap (V3 (V3 0 1 0) (V3 (-1) 0 0) (V3 0 0 2)) (V3 1 2 3 :: V3 Double)
-- V3 2.0 (-1.0) 6.0
linearMap :: Num a => V3 (V3 a) -> V3 a -> V3 a
linearMap (V3 r0 r1 r2) v = V3 (row r0) (row r1) (row r2)
  where row (V3 a b c) = let V3 x y z = v in a * x + b * y + c * z

-- | The image of a point.
--
-- >>> applyIso (diagonalIso (V3 1 1 (-1)) (V3 2 0 0)) (V3 0.5 0 0.25 :: V3 Double)
-- V3 2.5 0.0 (-0.25)
applyIso :: Num a => IsometryOf a -> V3 a -> V3 a
applyIso (Isometry l t) p = linearMap l p + t

-- | The isometry's linear part (how it maps directions).
applyLinear :: Num a => IsometryOf a -> V3 a -> V3 a
applyLinear (Isometry l _) = linearMap l

-- | The isometry that undoes this one, in the space's metric: the linear
-- part of an isometry of R³ is orthogonal (its inverse its transpose), a
-- Lorentz matrix's inverse is @J Lᵀ J@ with @J = diag(1, −1, 1)@; either
-- way no division, so a diagonal isometry's inverse is exact.
--
-- >>> let g = diagonalIso (V3 1 1 (-1)) (V3 2 0 1)
-- >>> applyIso (inverseIso Euclidean g) (applyIso g (V3 0.5 0 0.25 :: V3 Double))
-- V3 0.5 0.0 0.25
inverseIso :: Num a => Metric -> IsometryOf a -> IsometryOf a
inverseIso metric (Isometry l t) =
  let V3 (V3 a b c) (V3 d e f) (V3 g h i) = l
      back = case metric of
        Euclidean -> V3 (V3 a d g) (V3 b e h) (V3 c f i)
        Minkowski -> V3 (V3 a (negate d) g) (V3 (negate b) e (negate h)) (V3 c (negate f) i)
  in Isometry back (negate (linearMap back t))

-- | The determinant of a linear map (by rows).
determinant :: Num a => V3 (V3 a) -> a
determinant (V3 (V3 a b c) (V3 d e f) (V3 g h i)) = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)

-- | The isometry as the twelve numbers the step passes: the linear part's
-- rows, then the shift.
isoCoefficients :: IsometryOf a -> [a]
isoCoefficients (Isometry (V3 r0 r1 r2) t) = concatMap v3List [r0, r1, r2, t]
  where v3List (V3 a b c) = [a, b, c]

-- | The isometry of twelve numbers ('isoCoefficients').
isoFromCoefficients :: [a] -> IsometryOf a
isoFromCoefficients [a, b, c, d, e, f, g, h, i, x, y, z] = Isometry (V3 (V3 a b c) (V3 d e f) (V3 g h i)) (V3 x y z)
isoFromCoefficients cs = error ("isoFromCoefficients: twelve numbers, not " ++ show (length cs))

-- | The images a body meets: the non-trivial elements of the quotient's
-- group that move the fundamental domain next to itself (for a lattice, the
-- 8 neighbouring squares; bodies must be smaller than half the period).
-- The list is closed under inverses.
--
-- >>> map length [quotientImages NoQuotient, quotientImages Antipodal, quotientImages (Lattice 2 True), quotientImages OctagonPairings]
-- [0,1,8,48]
quotientImages :: Quotient -> [Isometry]
quotientImages NoQuotient = []
quotientImages Antipodal = [diagonalIso (V3 (-1) (-1) (-1)) (V3 0 0 0)]
quotientImages (Lattice period flipped) =
  [ diagonalIso (V3 1 1 (mirror i)) (V3 (period * fromIntegral i) 0 (period * fromIntegral k))
  | i <- [-1, 0, 1 :: Int], k <- [-1, 0, 1 :: Int], (i, k) /= (0, 0) ]
  where
    mirror i = if flipped && odd i then -1 else 1
quotientImages OctagonPairings = [ Isometry (rows m) (V3 0 0 0) | m <- touchingImages ]

-- | The most images any quotient has (the Bolza surface's 48).
mostImages :: Int
mostImages = maximum (map (length . quotientImages) [NoQuotient, Antipodal, Lattice 1 True, OctagonPairings])

-- | A matrix of nine numbers row by row (as "Manifold.Disc" writes them)
-- as rows.
rows :: [a] -> V3 (V3 a)
rows [a, b, c, d, e, f, g, h, i] = V3 (V3 a b c) (V3 d e f) (V3 g h i)
rows m = error ("rows: a matrix is nine numbers, not " ++ show (length m))

-- | Why a space's scenes can have no joints ('Nothing': they can): a joint
-- takes the image its bodies meet through by the signs of a diagonal
-- isometry ("Manifold.Joint"), which the Bolza surface's are not. The
-- scene readers (the command line's and the page's) and the page's joint
-- tool refuse a joint with this message.
jointsRefused :: Space -> Maybe String
jointsRefused sp = case spaceQuotient sp of
  OctagonPairings -> Just ("joints are not supported on " ++ spaceName sp ++ ": a joint across its octagon's sides would need its side pairings")
  _ -> Nothing

-- | How far a wrap into the fundamental domain moves a point at least (in
-- R³): consecutive points of a curve further apart than half of it were
-- wrapped between them, and the page breaks the curve there. A lattice's
-- period; on the Bolza surface the chord between the middles of two
-- paired sides (@2 sinh r@, @r@ the inradius); 'Nothing' where points are
-- never wrapped.
--
-- >>> map wrapJump [NoQuotient, Lattice 2 False]
-- [Nothing,Just 2.0]
wrapJump :: Quotient -> Maybe Double
wrapJump = \case
  Lattice period _ -> Just period
  OctagonPairings -> Just (2 * sinh inradius)
  _ -> Nothing

-- | The metric a quotient's isometries keep: Minkowski space's for the
-- hyperbolic quotients, R³'s for the others.
quotientMetric :: Quotient -> Metric
quotientMetric OctagonPairings = Minkowski
quotientMetric _ = Euclidean

-- | Whether a body meets its own image under this isometry in the contact
-- search: of an isometry and its inverse (both in 'quotientImages'), one
-- is chosen, so that the body's contact with its own image is found once.
selfImage :: Quotient -> Isometry -> Bool
selfImage quo g =
  let g' = inverseIso (quotientMetric quo) g
      key h = isoCoefficients h
  in g == g' || key g > key g'

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

-- | A point brought back into the fundamental domain: where it comes back,
-- the linear map that carries its vectors (velocity, frame) along, and
-- the orientation it comes back with (1, or −1 through a flipping edge,
-- which reverses angles).
data Wrapped a = Wrapped
  { wrappedPoint :: V3 a
  , wrappedLinear :: V3 (V3 a)
  , wrappedOrientation :: a
  }

-- | Where a point that left the fundamental domain comes back into it
-- ('Wrapped'); 'Nothing' for a quotient whose points never leave it.
quotientWrap :: Field a => Quotient -> Maybe (V3 a -> Wrapped a)
quotientWrap = \case
  Lattice period flipped -> Just $ \p ->
    let (p', s) = wrapLattice period flipped p
    in Wrapped p' (V3 (V3 1 0 0) (V3 0 1 0) (V3 0 0 s)) s
  OctagonPairings -> Just $ \p -> let (p', m) = wrapIntoOctagon p in Wrapped p' (rows m) 1
  _ -> Nothing

-- | How far a point is outside the fundamental domain, for a quotient that
-- has one: a body's images farther than its reach meet nothing. Never more
-- than the chord ('Manifold.Metric.normIn') from the point to the domain,
-- which is what a reach is measured in.
domainDistance :: Field a => Quotient -> Maybe (V3 a -> a)
domainDistance = \case
  Lattice period _ -> Just (distanceToDomain period)
  -- the hyperbolic distance beyond the side it is farthest beyond (the
  -- side excess is its sinh), which is less than the chord to the octagon
  OctagonPairings -> Just $ \p ->
    let e = maxF 0 (foldr1 maxF [sideExcess k p | k <- [0 .. 7]])
    in log (e + sqrt (e * e + 1))
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
nearestImage quo ref q = case quotientWrap quo of
  Nothing -> q
  Just wrap -> fst (nearestImageWith quo ref (wrappedPoint (wrap q)))

-- | Of the images of point @q@ (itself included) under the quotient's
-- group, the one nearest @ref@, with the linear part of the isometry that
-- gives it (how it maps directions). The candidates are compared by their
-- quadrance in the quotient's metric, a choice by 'select' so that it
-- stages.
nearestImageWith :: Field a => Quotient -> V3 a -> V3 a -> (V3 a, V3 (V3 a))
nearestImageWith quo ref q = fst (foldl pick ((q, linearPart identityIso), quadranceIn metric (q ^-^ ref)) candidates)
  where
    metric = quotientMetric quo
    candidates = [ (applyIso g' q, linearPart g') | g <- quotientImages quo, let g' = fmap constant g ]
    linearPart = isoLinear
    pick ((best, bestLinear), bd) (c, cl) =
      let d = quadranceIn metric (c ^-^ ref)
          closer = bd - d -- positive: c is nearer than the best so far
          choose a b = select closer <$> a <*> b
      in ((choose c best, choose <$> cl <*> bestLinear), minF d bd)

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
