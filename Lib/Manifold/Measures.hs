-- | What the page plots and inspects of a world: the bodies' kinetic energy
-- (translation and spin), the angular momentum of their centres about the
-- space's axis where it has one ('spaceAxis'), and one body's speed,
-- energy and contacts. On a surface of revolution the surface's push on a
-- body lies in the plane through the axis, so nothing but gravity across
-- the axis, a wall or a contact turns the centres about it: without them
-- the axial momentum stays as it was (Clairaut's relation, body by body).
-- Written as imperative programs so that the page gets them generated.
module Manifold.Measures
  ( MeasureSlot (..)
  , measureSize
  , measureWorld
  , measureBody
  ) where

import Data.Maybe (fromMaybe)
import Linear.Metric (dot)
import Linear.V3 (V3 (..), cross)

import Manifold.Field
import Manifold.Metric
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.World

-- | What a measure array holds, in this order: the world's kinetic energy
-- and axial momentum ('measureWorld'), then one body's speed, kinetic
-- energy and contact rows ('measureBody').
data MeasureSlot = KineticEnergy | AxialMomentum | BodySpeed | BodyEnergy | BodyContacts
  deriving (Show, Eq, Enum, Bounded)

-- | The numbers a measure array holds.
--
-- >>> measureSize
-- 5
measureSize :: Int
measureSize = length [minBound .. maxBound :: MeasureSlot]

-- | A body's kinetic energy, ½ m |v|² + ½ I ω², and the angular momentum
-- of its centre about the axis a, m ⟨a × p, v⟩ (m (p × v) · a in R³: the
-- velocity's share along the rotation the axis generates, an isometry of
-- either metric); a static body (inverse mass 0) has neither.
bodyMotion :: Imp m => Metric -> WorldArrays (Array m) -> V3 (Scalar m) -> Index m -> m (Scalar m, Scalar m, Scalar m)
bodyMotion metric w a i = do
  invMass <- readSlot w i InvMass
  invInertia <- readSlot w i InvInertia
  omega <- readSlot w i Omega
  p <- read3 (wPos w) i
  v <- read3 (wVel w) i
  moving <- share (select invMass 1 0)
  m <- share (moving / maxF invMass 1e-300)
  inertia <- share (moving / maxF invInertia 1e-300)
  energy <- share (0.5 * m * quadranceIn metric v + 0.5 * inertia * omega * omega)
  axial <- share (m * rotationShare metric a p v)
  pure (energy, axial, normIn metric v)

-- | @⟨a × p, v⟩@: how much of velocity @v@ at @p@ is along the rotation
-- about axis @a@.
rotationShare :: Field a => Metric -> V3 a -> V3 a -> V3 a -> a
rotationShare Euclidean a p v = dot (cross p v) a
rotationShare metric a p v = inner metric (cross a p) v

-- | @measureWorld sp w out@: the bodies' total kinetic energy and their
-- centres' angular momentum about the space's axis (0 without one) into
-- @out@.
measureWorld :: Imp m => Space -> WorldArrays (Array m) -> Array m -> m ()
{-# SPECIALIZE measureWorld :: Space -> WorldArrays NativeArray -> NativeArray -> Native () #-}
measureWorld sp w out = do
  n <- readMeta w BodyCount
  energyR <- newRef 0
  axialR <- newRef 0
  forLoop 0 (toIndex n) $ \i -> do
    (energy, axial, _) <- bodyMotion (spaceMetric sp) w (axisOf sp) i
    readRef energyR >>= writeRef energyR . (+ energy)
    readRef axialR >>= writeRef axialR . (+ axial)
  readRef energyR >>= writeArray out (slot KineticEnergy)
  readRef axialR >>= writeArray out (slot AxialMomentum)

-- | @measureBody sp w out i@: body @i@'s speed, kinetic energy and the
-- contact rows of the last step it is in (either side) into @out@.
measureBody :: Imp m => Space -> WorldArrays (Array m) -> Array m -> Index m -> m ()
{-# SPECIALIZE measureBody :: Space -> WorldArrays NativeArray -> NativeArray -> Int -> Native () #-}
measureBody sp w out i = do
  (energy, _, speed) <- bodyMotion (spaceMetric sp) w (axisOf sp) i
  writeArray out (slot BodySpeed) speed
  writeArray out (slot BodyEnergy) energy
  rows <- readMeta w ContactCount
  body <- share (toScalar i)
  touching <- newRef 0
  forLoop 0 (toIndex rows) $ \c -> do
    a <- readContact w c CA
    b <- readContact w c CB
    -- 1 where the row's body a or b is this one (indices are whole numbers)
    let is x = select (0.25 - (x - body) * (x - body)) 1 0
    hit <- share (maxF (is a) (is b))
    readRef touching >>= writeRef touching . (+ hit)
  readRef touching >>= writeArray out (slot BodyContacts)

-- | The space's axis, or 0 (no axial momentum).
axisOf :: Field a => Space -> V3 a
axisOf sp = fmap constant (fromMaybe (V3 0 0 0) (spaceAxis sp))

-- | Where a measure sits in the out array.
slot :: Imp m => MeasureSlot -> Index m
slot = fromIntegral . fromEnum
