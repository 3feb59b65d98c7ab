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
  , hasBoundary
  , field
  , evalField
  , evalBoundary
  , evalGravity
  , uniformGravity
  , noGravity
  ) where

import Linear.V3 (V3 (..))

import Manifold.Field

-- | How points are identified.
data Quotient
  = NoQuotient
  | Antipodal -- ^ @p ~ −p@: the space must be symmetric about the origin.
  deriving (Show, Eq)

quotientName :: Quotient -> String
quotientName NoQuotient = "none"
quotientName Antipodal = "antipodal"

-- | A pinhole camera looking at @cameraTarget@ from @cameraEye@.
data Camera = Camera
  { cameraEye :: V3 Double
  , cameraTarget :: V3 Double
  , cameraUp :: V3 Double
  , cameraFov :: Double -- ^ vertical field of view, degrees
  } deriving (Show, Eq)

data ShapeKind = CircleShape | SquareShape | PolygonShape Int
  deriving (Show, Eq)

-- | A body of the default scene: where it starts (projected onto the surface
-- on load), its shape and its size (circumradius).
data Placement = Placement
  { placeAt :: V3 Double
  , placeShape :: ShapeKind
  , placeSize :: Double
  , placeStatic :: Bool -- ^ a fixed body (a floor, a wall)
  } deriving (Show, Eq)

data Space = Space
  { spaceName :: String
  , spaceDescription :: String
  , spaceField :: ScalarFn
  , spaceBoundary :: Maybe ScalarFn -- ^ the allowed region is @b(p) >= 0@
  , spaceGravity :: VectorFn -- ^ an R³ field; the engine projects it
  , spaceQuotient :: Quotient
  , spaceCamera :: Camera
  , spaceScene :: [Placement]
  , spaceBounds :: Double -- ^ radius of a ball around the origin holding the part of the surface worth drawing and simulating
  }

-- | A space with no boundary, no quotient, no gravity, a camera on the z axis
-- and an empty scene: the record to update when defining one.
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
  }

hasBoundary :: Space -> Bool
hasBoundary = maybe False (const True) . spaceBoundary

-- | The field of a space, at any scalar.
field :: Field a => Space -> V3 a -> a
field s = evalFn (spaceField s)

evalField :: Space -> V3 Double -> Double
evalField = field

-- | The boundary function; a space without a boundary is everywhere inside
-- (the constant 1).
evalBoundary :: Field a => Space -> V3 a -> a
evalBoundary s p = case spaceBoundary s of
  Nothing -> 1
  Just b -> evalFn b p

evalGravity :: Field a => Space -> V3 a -> V3 a
evalGravity s = let VectorFn g = spaceGravity s in g

uniformGravity :: V3 Double -> VectorFn
uniformGravity g = VectorFn (const (fmap constant g))

noGravity :: VectorFn
noGravity = uniformGravity (V3 0 0 0)
