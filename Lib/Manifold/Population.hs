{-# LANGUAGE FlexibleContexts #-}
-- | Adding and removing bodies at run time, written once: the native engine
-- and the page's JavaScript add a body the same way (projected onto the
-- surface, velocity onto the tangent plane, mass and moment of inertia
-- integrated from the outline as in paper §2.4).
module Manifold.Population
  ( BodyArgs (..)
  , addBodyWith
  , removeBody
  , placementAngle
  ) where

import Linear.Metric (dot, norm)
import Linear.V3 (V3 (..), cross)
import Linear.Vector ((*^))

import Manifold.Body (PolygonParams (..), massIntegrals)
import Manifold.Field
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.Surface
import Manifold.World

-- | A new body's description, in the interpretation's scalars.
data BodyArgs s = BodyArgs
  { baSize :: s
  , baDensity :: s
  , baStatic :: s -- ^ 1 for a static body, 0 otherwise
  , baPos :: V3 s
  , baVel :: V3 s
  , baAngle :: s
  , baOmega :: s
  }

-- | Add a body with the given outline (for size 1). Sets 'LastAdded' to its
-- index, or to −1 when the world is full or the position does not project
-- onto the surface.
addBodyWith :: Imp m => Space -> Layout -> WorldArrays (Array m) -> (Scalar m -> Scalar m) -> BodyArgs (Scalar m) -> m ()
addBodyWith sp l w outline b = do
  count <- readMeta w BodyCount
  cap <- readMeta w Capacity
  let f = spaceField sp
  p <- share3 (projectToSurface f (baPos b))
  n <- share3 (unitNormal f p)
  -- every condition must hold; a NaN (a vanished gradient) fails it
  let usable = allPositive [cap - count - 0.5, norm n - 0.5, finiteness (toList3 p ++ toList3 n)]
  ifPositive usable
    (do let i = toIndex count
            movable = 1 - baStatic b
            v = movable *^ tangentProjection n (baVel b)
            axis = referenceAxis n
        write3 (wPos w) i p
        write3 (wVel w) i v
        axis' <- share3 axis
        write3 (wAxis w) i axis'
        write3 (wNormal w) i n
        (m, inertia) <- massIntegrals outline (baSize b) (baDensity b)
        writeSlot w i Angle (baAngle b)
        writeSlot w i Omega (movable * baOmega b)
        writeSlot w i InvMass (select movable (select m (recip m) 0) 0)
        writeSlot w i InvInertia (select movable (select inertia (recip inertia) 0) 0)
        writeSlot w i Size (baSize b)
        outlineRadiiInto l outline w i (baSize b)
        let nd = polyDirections (polygon l)
        reach <- newRef 0
        forEach (fromIntegral nd) $ \d -> do
          r <- readArray (wRadii w) (fromIntegral nd * i + d)
          modifyRef reach (maxF r)
        readRef reach >>= writeSlot w i BoundRadius
        writeArray (wBodyPrev w) (2 * i + 1) 0
        writeMeta w BodyCount (count + 1)
        writeMeta w LastAdded count
        polygoniseBody sp l w i)
    (writeMeta w LastAdded (-1))

-- | 1 when every condition is positive, else 0 (NaN counts as not positive).
allPositive :: Field a => [a] -> a
allPositive = foldr (\c rest -> select c rest 0) 1

-- | Remove body @i@: the last body takes its place (so indices above @i@
-- are stable but the last one's becomes @i@). Warm starting is forgotten
-- for one step; a mouse joint on the removed body is released.
removeBody :: Imp m => Layout -> WorldArrays (Array m) -> Index m -> m ()
removeBody l w i = do
  count <- readMeta w BodyCount
  whenPositive (minF (toScalar i + 0.5) (count - toScalar i - 0.5)) $ do
    let lastI = toIndex (count - 1)
        move arr (k :: Int) = forEach (fromIntegral k) $ \o ->
          readArray arr (fromIntegral k * lastI + o) >>= writeArray arr (fromIntegral k * i + o)
    move (wPos w) 3
    move (wVel w) 3
    move (wAxis w) 3
    move (wNormal w) 3
    move (wScalars w) scalarSlots
    move (wRadii w) (polyDirections (polygon l))
    move (wVerts w) (3 * verticesPerBody l)
    move (wOutline w) (3 * polyDirections (polygon l))
    writeMeta w BodyCount (count - 1)
    forEach (toIndex count) $ \k -> writeArray (wBodyPrev w) (2 * k + 1) 0
    grabbed <- readMouse w MBody
    active <- readMouse w MActive
    whenPositive (minF active (0.5 - abs (grabbed - toScalar i))) (writeMouse w MActive 0)
    whenPositive (minF active (0.5 - abs (grabbed - (count - 1)))) (writeMouse w MBody (toScalar i))

-- | The angle that, given to 'addBodyWith' with body @i@'s position, puts
-- its outline where it is now, into 'PlacementAngle': what a saved scene
-- holds. A body's angle is measured from the axis it has carried along
-- since it was placed, and a body placed anew starts from the reference
-- axis at its position; the two differ once it has moved on a curved
-- surface.
placementAngle :: Imp m => Space -> WorldArrays (Array m) -> Index m -> m ()
placementAngle sp w i = do
  p <- read3 (wPos w) i
  n <- share3 (unitNormal (spaceField sp) p)
  start <- share3 (referenceAxis n)
  carried <- read3 (wAxis w) i
  angle <- readSlot w i Angle
  writeMeta w PlacementAngle (angle + atan2F ((n `cross` start) `dot` carried) (start `dot` carried))
