-- | The torus's angle coordinates as a chart onto the flat torus's square
-- (paper §4.4, Fig. 17): the embedded torus and the flat torus are the same
-- topological space, and the angles around the y axis (ψ) and around the
-- tube (φ) identify each with the square [−L/2, L/2]². The page draws each
-- simulation on the other's surface through this map, and starts both from
-- one scene given in the square's coordinates, so that the difference in
-- their motion is the difference in metric.
module Manifold.Chart
  ( torusToSquare
  , squareToTorus
  , squareVelocityOnTorus
  , Launch (..)
  , comparisonLaunches
  , embeddedSizeScale
  , launchOnTorus
  , launchOnSquare
  ) where

import Linear.V3 (V3 (..))

import Manifold.Field
import Manifold.Space (ShapeKind (..))
import Manifold.Spaces (torusMajor, torusMinor, flatPeriod)

-- | Angle per unit of the square: a whole period is a whole turn.
anglePerUnit :: Double
anglePerUnit = 2 * pi / flatPeriod

-- | A point near the embedded torus to the square's coordinates @(x, 0, z)@:
-- @x@ from ψ (around the y axis, 0 on +x), @z@ from φ (around the tube, 0 on
-- the outer equator, ±L/2 on the inner one).
torusToSquare :: Field a => V3 a -> V3 a
torusToSquare (V3 x y z) =
  let psi = atan2F z x
      rho = sqrt (x * x + z * z)
      phi = atan2F y (rho - constant torusMajor)
      k = constant (recip anglePerUnit)
  in V3 (k * psi) 0 (k * phi)

-- | The square's point @(x, _, z)@ on the embedded torus:
-- @((R + r cos φ) cos ψ, r sin φ, (R + r cos φ) sin ψ)@ with ψ, φ from x, z.
-- The square's centre is on the outer equator:
--
-- >>> squareToTorus (V3 0 0 0 :: V3 Double)
-- V3 1.3 0.0 0.0
-- >>> torusToSquare (squareToTorus (V3 0.5 0 (-0.25))) :: V3 Double
-- V3 0.5 0.0 (-0.25)
squareToTorus :: Field a => V3 a -> V3 a
squareToTorus (V3 x _ z) =
  let psi = constant anglePerUnit * x
      phi = constant anglePerUnit * z
      rho = constant torusMajor + constant torusMinor * cos phi
  in V3 (rho * cos psi) (constant torusMinor * sin phi) (rho * sin psi)

-- | The velocity on the torus that moves the angles as velocity @v@ moves
-- the square's coordinates at point @p@ (the chart's derivative).
squareVelocityOnTorus :: Floating a => V3 a -> V3 a -> V3 a
squareVelocityOnTorus (V3 x _ z) (V3 vx _ vz) =
  let k = realToFrac anglePerUnit
      psi = k * x
      phi = k * z
      r = realToFrac torusMinor
      rho = realToFrac torusMajor + r * cos phi
      dpsi = k * vx
      dphi = k * vz
  in V3 (negate rho * sin psi * dpsi - r * sin phi * cos psi * dphi)
        (r * cos phi * dphi)
        (rho * cos psi * dpsi - r * sin phi * sin psi * dphi)

-- | A body of the comparison scene in the square's coordinates.
data Launch = Launch
  { launchShape :: ShapeKind
  , launchSize :: Double -- ^ on the flat torus; on the embedded one times 'embeddedSizeScale'
  , launchAt :: V3 Double -- ^ (x, 0, z) in the square
  , launchVelocity :: V3 Double -- ^ (vx, 0, vz) in the square's coordinates per second
  , launchOmega :: Double
  }

-- | The embedded torus is larger than the square (its outer equator is
-- 2π(R + r) = 8.2 long, its inner one 1.9, the square's side 2), so its
-- bodies are drawn twice as large.
embeddedSizeScale :: Double
embeddedSizeScale = 2

-- | The side-by-side scene (no gravity): a square launched along the outer
-- equator with a small tilt, a circle the same way along the inner equator,
-- a pentagon round the tube, and two circles on top of the tube that meet
-- head on (all but the second in view of the torus's default camera).
comparisonLaunches :: [Launch]
comparisonLaunches =
  [ Launch SquareShape 0.1 (V3 (-0.6) 0 0) (V3 0.12 0 0.02) 0
  , Launch CircleShape 0.1 (V3 (-0.6) 0 (-1)) (V3 0.12 0 0.02) 0
  , Launch (PolygonShape 5) 0.1 (V3 0.5 0 (-0.25)) (V3 0 0 0.1) 0.5
  , Launch CircleShape 0.1 (V3 (-0.55) 0 0.4) (V3 0.1 0 0) 0
  , Launch CircleShape 0.1 (V3 (-0.05) 0 0.4) (V3 (-0.1) 0 0) 0
  ]

-- | A launch as a body on the embedded torus: position, velocity, size.
launchOnTorus :: Launch -> (V3 Double, V3 Double, Double)
launchOnTorus l = (squareToTorus (launchAt l), squareVelocityOnTorus (launchAt l) (launchVelocity l), embeddedSizeScale * launchSize l)

-- | A launch as a body on the flat torus.
launchOnSquare :: Launch -> (V3 Double, V3 Double, Double)
launchOnSquare l = (launchAt l, launchVelocity l, launchSize l)
