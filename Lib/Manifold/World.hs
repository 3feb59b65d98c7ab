{-# LANGUAGE FlexibleContexts, DeriveTraversable, LambdaCase #-}
-- | The world and its step, written once against the imperative layer: GHC
-- runs it natively over unboxed vectors, and the staging layer prints it as
-- the page's JavaScript.
--
-- State is a struct of arrays with a fixed capacity, so a step allocates
-- nothing and the page can draw straight from the arrays.
--
-- This first part is the motion of free bodies (paper §2.4, §4.1): gravity
-- projected to the tangent plane, @coord += veloc * dt@, the pull back onto
-- the surface, the transport of velocity and axis, and the geodesic polygons
-- (§3.4). A step that would produce a non-finite value leaves the body as it
-- was and counts a warning.
module Manifold.World
  ( WorldArrays (..)
  , Layout (..)
  , WalkLoops (..)
  , layout
  , arraySizes
  , arrayNames
  , Slot (..)
  , Meta (..)
  , imageTableAt
  , imageStride
  , Param (..)
  , ContactField (..)
  , PrevField (..)
  , keptFields
  , MouseField (..)
  , JointField (..)
  , JointKind (..)
  , IslandField (..)
  , islandStride
  , readIsland
  , writeIsland
  , moving
  , jointStride
  , maxJoints
  , partnersPerBody
  , readJoint
  , writeJoint
  , readJoint3
  , writeJoint3
  , scalarSlots
  , contactStride
  , prevStride
  , contactsPerBody
  , maxContacts
  , maxBuckets
  , verticesPerBody
  , hullStride
  , hullLocalAt
  , hullWorldAt
  , hullScratch
    -- * Access
  , read3
  , write3
  , share3
  , readSlot
  , writeSlot
  , readMeta
  , writeMeta
  , readParam
  , readContact
  , writeContact
  , readContact3
  , writeContact3
  , readPrev
  , writePrev
  , readMouse
  , writeMouse
  , outlineVertex
  , bodyFrame
  , BodyFrame (..)
  , finiteness
  , countWarning
  , finiteOr0
    -- * Motion
  , substepLength
  , applyGravity
  , integrate
  , wrapIntoDomain
  , tangentVelocities
  , polygoniseAll
  , polygoniseEvery
  , polygoniseBody
  , polygoniseInline
  , walkCorners
  , bodyAxes
  , cornerWalkSteps
  , hasConstantGradient
  , constantGradient
  , toList3
  , onSurfaceTolerance
  , outlineRadiiInto
  ) where

import Linear.V3 (V3 (..))
import Control.Monad (foldM, forM_, unless, when, (<=<))
import Data.Maybe (isJust)
import Linear.Metric (quadrance)
import Linear.Vector ((*^), (^+^), (^-^))

import Manifold.Body (PolygonParams (..), vertexIndex)
import Manifold.ContactManifold (maxHullCorners)
import Manifold.Field
import Manifold.Metric
import Manifold.Space
import Manifold.Stage.Expr (literalValue, sym)
import Manifold.Stage.Imp
import Manifold.Surface

-- | The world's arrays, one record for every interpretation.
data WorldArrays a = WorldArrays
  { wMeta :: a -- ^ see 'Meta'
  , wParams :: a -- ^ see 'Param'
  , wPos :: a -- ^ 3 per body
  , wVel :: a -- ^ 3 per body
  , wAxis :: a -- ^ 3 per body, a unit tangent vector
  , wNormal :: a -- ^ 3 per body, the unit surface normal at the centre
  , wScalars :: a -- ^ 'scalarSlots' per body, see 'Slot'
  , wRadii :: a -- ^ directions per body: the outline's radius in each polygon direction
  , wVerts :: a -- ^ 3 × vertices per body: the cached polygon
  , wOutline :: a -- ^ 3 × directions per body: the polygon's outline vertices again, side by side (what the narrow phase reads)
  , wGrid :: a -- ^ broad phase: per hash bucket a count, then per bucket a start
  , wCellOf :: a -- ^ broad phase: each body's cell (its key)
  , wItems :: a -- ^ broad phase: bodies sorted by bucket; at its end, last slot first, the static bodies kept out of the grid ('LargeCount')
  , wContacts :: a -- ^ 'contactStride' per contact, see 'ContactField'
  , wPrev :: a -- ^ the last step's contacts for warm starting: owner, key, normal and friction impulse
  , wBodyPrev :: a -- ^ per body: where its contacts start in 'wPrev', and how many
  , wMouse :: a -- ^ see 'MouseField'
  , wProbe :: a -- ^ narrow phase scratch: how deep each outline vertex of a pair's two bodies lies in the other (and a hull's corners walked for its self-contact)
  , wNear :: a -- ^ broad phase scratch: the bodies whose bounds overlap the current one's
  , wWalk :: a -- ^ polygon walk scratch: @walkStride@ numbers per direction, the walk's state between its loops
  , wJoints :: a -- ^ 'jointStride' per joint, see 'JointField' ("Manifold.Joint")
  , wFlip :: a -- ^ per body: 1, or −1 when the last wrap into the fundamental domain mirrored it (the joints' anchors follow)
  , wPartners :: a -- ^ per body: 'partnersPerBody' bodies it is joined to and does not collide with (−1: none), found each step
  , wIslands :: a -- ^ per body: 'IslandField' (the islands' union–find, "Manifold.Sleep")
  , wSeenParams :: a -- ^ the parameters as the last step saw them (a change wakes every body)
  , wHull :: a -- ^ 'hullStride' per body: its hull's rounding radius, corners in its own frame and corners walked onto the surface (see 'hullLocalAt')
  } deriving (Show, Functor, Foldable, Traversable)

-- | Sizes that depend on the polygon parameters and the capacity.
data Layout = Layout
  { capacity :: Int
  , polygon :: PolygonParams
  , walkLoops :: WalkLoops -- ^ how the polygon walk's loops are arranged on curved surfaces
  } deriving (Show, Eq)

-- | How the polygon walk arranges its loops across the directions on a
-- curved surface: the same arithmetic either way, but the two engines run
-- best with different ones (see 'polygoniseBody'). On a flat surface the
-- walk takes one loop a step either way.
data WalkLoops
  = LoopPerStep -- ^ one loop across the directions for each geodesic step (the page's engine)
  | LoopPerNewtonIteration -- ^ one for each Newton iteration of a step (the compiled native step)
  deriving (Show, Eq)

layout :: Int -> Layout
layout cap = Layout cap (PolygonParams 24 4) LoopPerStep

-- | Per body.
--
-- 'TurnCos' and 'TurnSin' are the cosine and sine of 'Angle' as the outline
-- was last walked ('polygoniseBody' writes them with the vertices), so that
-- the narrow phase turns a point into the body's own directions without an
-- arctangent.
--
-- 'MovedX', 'MovedY', 'MovedZ' and 'Turned' are how far the body has moved
-- (velocity times time, summed over the sub-steps) and turned since the
-- step's contacts were found: the solver updates each contact's depth from
-- them without finding the contacts again.
--
-- 'Asleep' is 1 for a body of a sleeping island ("Manifold.Sleep"), 0
-- otherwise; 'SleepTimer' is how long the body has moved slower than the
-- sleep threshold (s); 'Island' names a sleeping body's island (the index
-- of one of its bodies; −1 for an awake body).
--
-- 'BodyFriction' and 'BodyRestitution' are the body's material (its
-- friction coefficient and restitution), or −1 where the body takes the
-- scene's ('Friction' and 'Restitution', which the page's sliders set):
-- "Manifold.Solver" mixes a pair's as Box2D does.
--
-- 'Size' is what the body's slop and contact margins scale with: a
-- circle's radius, a polygon's circumradius, a box's least half-extent, a
-- capsule's radius ('Manifold.Hull.hullThickness'); 'BoundRadius' is how
-- far it reaches from its centre.
--
-- 'Corners' is how many corners the body's hull has
-- ("Manifold.ContactManifold", 'wHull'): 1 for a circle, a geodesic disc
-- of radius 'Size' whose contacts with another circle come from the
-- distance between the centres, 2 for a capsule, 4 for a box; 0 for a
-- body that collides by its sampled outline.
data Slot = Angle | Omega | InvMass | InvInertia | Size | BoundRadius | TurnCos | TurnSin
  | MovedX | MovedY | MovedZ | Turned
  | Asleep | SleepTimer | Island
  | BodyFriction | BodyRestitution | Corners
  deriving (Show, Eq, Enum, Bounded)

-- | The world's counters. 'AwakeCount' is the movable bodies awake after
-- the last step's wake phase, 'IslandCount' the islands as 'countIslands'
-- last counted them, 'WakeRequest' 1 when an island is marked to wake
-- ("Manifold.Sleep"), 'KeptRows' the contact rows the step kept from the
-- last instead of finding them anew ("Manifold.Collide").
data Meta = BodyCount | Warnings | ContactCount | Capacity | GridBuckets | CellSize | DroppedContacts | LastAdded | Picked | PickedSign
  | JointCount | LastJoint | AwakeCount | IslandCount | WakeRequest | LargeCount | KeptRows
  deriving (Show, Eq, Enum, Bounded)

-- | The engine's parameters, set by the scene (and the page's controls).
data Param = Dt | GravityOn | Substeps | Iterations | Friction | Restitution | ContactHertz | DampingRatio | Pushout
  | Slop | Speculative | BounceThreshold | WarmStart | PolygonStep | JointHertz | JointDampingRatio
  | Sleep | SleepSpeed | SleepTime | KeepContacts
  deriving (Show, Eq, Enum, Bounded)

-- | One contact row pair (normal and friction) of the solver. The first body
-- (@a@) is pushed along the direction, the second (@b@, or none) against it.
--
-- The narrow phase writes the bodies, the key, the rows ('JaX' … 'TbW'),
-- the depth, the self-contact scale and the point; the solver's
-- preparation writes the rest: the rows' masses, the depth beyond the slop
-- ('CPenetration'), the contact's softness ('CBiasRate', 'CMassScale',
-- 'CImpulseScale', see "Manifold.Solver"), the normal velocity before the
-- step ('CApproach', for restitution), the normal impulse applied in
-- all ('CTotalImpulse') and the pair's mixed friction and restitution
-- ('CFriction', 'CRestitution').
--
-- 'CKept' is 1 for a row that the next step may keep instead of finding
-- the pair's contacts again (a pair's or a boundary's row, not an image's
-- or a self-contact's: "Manifold.Collide"); 'CDriftX' … 'CDriftZ' are how
-- far the pair has moved relative to each other since its rows were found
-- (body a's motion less body b's), 'CTurnA' and 'CTurnB' how far each
-- body has turned.
data ContactField
  = CA | CB | COwner | CKey
  | JaX | JaY | JaZ | JaW | JbX | JbY | JbZ | JbW
  | TaX | TaY | TaZ | TaW | TbX | TbY | TbZ | TbW
  | CDepth | NormalMass | TangentMass | ImpulseN | ImpulseT | CSelfScale
  | PointX | PointY | PointZ
  | CPenetration | CBiasRate | CMassScale | CImpulseScale | CApproach | CTotalImpulse
  | CFriction | CRestitution
  | CKept | CDriftX | CDriftY | CDriftZ | CTurnA | CTurnB
  deriving (Show, Eq, Enum, Bounded)

-- | What the world remembers of one of the last step's contact rows: the
-- body that owns the row, its key (the contact's identity, see
-- "Manifold.Collide") and its normal and friction impulses, for warm
-- starting; and for a row the next step may keep ('PrevKept' 1), what
-- keeping it takes: its bodies, its depth at the step's end (as found,
-- less how far the bodies moved apart along its normal row), the pair's
-- drift and turns since it was found ('CDriftX' … 'CTurnB'), its point and
-- its rows ('JaX' … 'TbW', in that order). A body's rows are consecutive
-- ('wBodyPrev' holds where they start and how many there are).
data PrevField = PrevOwner | PrevKey | PrevNormal | PrevFriction
  | PrevKept | PrevA | PrevB | PrevDepth | PrevDriftX | PrevDriftY | PrevDriftZ | PrevTurnA | PrevTurnB
  | PrevPointX | PrevPointY | PrevPointZ
  | PrevJaX | PrevJaY | PrevJaZ | PrevJaW | PrevJbX | PrevJbY | PrevJbZ | PrevJbW
  | PrevTaX | PrevTaY | PrevTaZ | PrevTaW | PrevTbX | PrevTbY | PrevTbZ | PrevTbW
  deriving (Show, Eq, Enum, Bounded)

-- | The fields a kept row carries from one step to the next, as the
-- contact array names them and as the remembered rows do (after
-- 'PrevKept', in the order a saved scene lists them).
keptFields :: [(ContactField, PrevField)]
keptFields =
  [(CA, PrevA), (CB, PrevB), (CDepth, PrevDepth)]
    ++ zip [CDriftX .. CTurnB] [PrevDriftX .. PrevTurnB]
    ++ zip [PointX .. PointZ] [PrevPointX .. PrevPointZ]
    ++ zip [JaX .. TbW] [PrevJaX .. PrevTbW]

-- | The mouse joint.
data MouseField = MActive | MBody | MLocalR | MLocalTheta | MTargetX | MTargetY | MTargetZ
  | MFrequency | MDamping | MMaxForce | MImpulseU | MImpulseW | MSign
  deriving (Show, Eq, Enum, Bounded)

-- | What a joint holds ("Manifold.Joint"). The first fields say what the
-- joint is: its kind ('JointKind'), its bodies (@b@ −1 for the world), each
-- anchor in its body's own polar coordinates (the geodesic distance from the
-- centre and the angle from the body's direction, as the mouse joint keeps
-- its grabbed point) or, against the world, as a surface point, and the
-- settings of the kind. The impulses are kept from step to step (warm
-- starting). The rest is what each step's preparation finds for the
-- sub-steps: the anchors (body b's at the image nearest body a's), how
-- each anchor moves with its body ('Manifold.Anchor.anchorMotion': per
-- unit of the body's slide along its frame's two directions, per radian
-- of its turn; body b's in its own frame, which is kept too), the
-- image's signs, the pin's two row directions (body a's frame), the
-- anchors' distance, and for the angular rows the image's orientation
-- ('JSigma'), the relative angle's error and the rows' mass.
data JointField
  = JKind | JA | JB
  | JRadiusA | JThetaA | JRadiusB | JThetaB | JWorldX | JWorldY | JWorldZ
  | JLength | JMinLength | JMaxLength | JHertz | JDamping
  | JReference | JLimitOn | JLower | JUpper | JMotorOn | JMotorSpeed | JMaxTorque
  | JImpulse1 | JImpulse2 | JImpulseAxial | JImpulseLower | JImpulseUpper | JImpulseMotor | JImpulseAngle
  | JAnchorAX | JAnchorAY | JAnchorAZ | JAnchorBX | JAnchorBY | JAnchorBZ
  | JSlideUAX | JSlideUAY | JSlideUAZ | JSlideWAX | JSlideWAY | JSlideWAZ | JTurnAX | JTurnAY | JTurnAZ
  | JSlideUBX | JSlideUBY | JSlideUBZ | JSlideWBX | JSlideWBY | JSlideWBZ | JTurnBX | JTurnBY | JTurnBZ
  | JUBX | JUBY | JUBZ | JWBX | JWBY | JWBZ
  | JSignX | JSignY | JSignZ | JE1X | JE1Y | JE1Z | JE2X | JE2Y | JE2Z
  | JChord | JSigma | JAngleError | JAngularMass | JCollide
  deriving (Show, Eq, Enum, Bounded)

-- | The kinds of joint.
data JointKind
  = Revolute -- ^ a pin: the anchors coincide; optionally a motor and angle limits
  | Distance -- ^ the anchors a length apart: rigid, a spring, or a rope between two lengths
  | Weld -- ^ the anchors coincide and the relative angle holds
  deriving (Show, Eq, Enum, Bounded)

-- | What the islands' union–find ("Manifold.Sleep") keeps of a body: its
-- parent (itself for an island's root), its rank, at a root the shortest
-- sleep timer of the island, and whether the sleeping island the body names
-- is to wake. Scratch, but for the mark: not part of the state's hash.
data IslandField = IslandParent | IslandRank | IslandCalm | IslandWake
  deriving (Show, Eq, Enum, Bounded)

count' :: forall e. (Enum e, Bounded e) => e -> Int
count' _ = fromEnum (maxBound :: e) + 1

scalarSlots, contactStride, prevStride, jointStride, islandStride :: Int
scalarSlots = count' Angle
islandStride = count' IslandParent
jointStride = count' JKind
contactStride = count' CA
prevStride = count' PrevOwner

-- | A body's numbers in 'wHull': the radius that rounds its hull, then
-- each corner in the body's own frame (@a@ along its direction, @b@
-- along normal × direction: "Manifold.Hull"), then each corner where the
-- last polygon walk put it on the surface ('walkCorners'), up to
-- 'maxHullCorners' of each.
hullStride :: Int
hullStride = 1 + 5 * maxHullCorners

-- | Where corner @k@'s frame coordinates @(a, b)@ and its walked point
-- @(x, y, z)@ start among a body's 'hullStride' numbers.
hullLocalAt, hullWorldAt :: Num a => a -> a
hullLocalAt k = 1 + 2 * k
hullWorldAt k = fromIntegral (1 + 2 * maxHullCorners) + 3 * k

-- | The narrow phase's scratch for a pair of hulls in their tangent plane
-- ('wProbe'): each body's corners and edge normals, two numbers each.
hullScratch :: Int
hullScratch = 4 * maxHullCorners

-- | Where the probe array's table of the quotient's isometries starts
-- (after the narrow phase's scratch): the identity, then each image, as
-- 'imageStride' numbers ("Manifold.Collide" writes it every step). The
-- contact search loops over it and the pair narrow phase reads an image
-- from it by its index, the numbers unboxed (V8 boxes a number argument of
-- a function it does not inline).
imageTableAt :: Layout -> Int
imageTableAt l = maximum [2 * polyDirections (polygon l), 2 * hullScratch, 3 * cornerWalkSteps * maxHullCorners]

-- | An image's numbers in the table: its twelve coefficients
-- ('isoCoefficients'), then 1 where a body may meet itself through it
-- ('selfImage').
imageStride :: Int
imageStride = 13

-- | The polygon walk's scratch numbers per direction (see 'polygoniseBody').
walkStride :: Int
walkStride = 12

-- | Contacts a body may own (pairs it leads, its boundary contacts).
contactsPerBody :: Int
contactsPerBody = 8

-- | The broad phase's hash table has at most this many buckets.
maxBuckets :: Int
maxBuckets = 262144

verticesPerBody :: Layout -> Int
verticesPerBody l = 1 + polyDirections (polygon l) * polySteps (polygon l)

maxContacts :: Layout -> Int
maxContacts l = contactsPerBody * max 1 (capacity l)

-- | The bodies a body is joined to that it does not collide with: beyond
-- these, joined bodies collide.
partnersPerBody :: Int
partnersPerBody = 4

-- | The joints a world holds: two a body (a grid's bodies are joined to
-- their right and lower neighbours).
maxJoints :: Layout -> Int
maxJoints l = 2 * max 1 (capacity l)

arraySizes :: Layout -> WorldArrays Int
arraySizes l = let c = max 1 (capacity l) in WorldArrays
  { wMeta = count' BodyCount
  , wParams = count' Dt
  , wPos = 3 * c, wVel = 3 * c, wAxis = 3 * c, wNormal = 3 * c
  , wScalars = scalarSlots * c
  , wRadii = polyDirections (polygon l) * c
  , wVerts = 3 * verticesPerBody l * c
  , wOutline = 3 * polyDirections (polygon l) * c
  , wGrid = 2 * maxBuckets
  , wCellOf = c
  , wItems = c
  , wContacts = contactStride * maxContacts l
  , wPrev = prevStride * maxContacts l
  , wBodyPrev = 2 * c
  , wMouse = count' MActive
  , wProbe = imageTableAt l + imageStride * (1 + mostImages)
  , wNear = c
  , wWalk = walkStride * polyDirections (polygon l)
  , wJoints = jointStride * maxJoints l
  , wFlip = c
  , wPartners = partnersPerBody * c
  , wIslands = islandStride * c
  , wSeenParams = count' Dt
  , wHull = hullStride * c
  }

arrayNames :: WorldArrays String
arrayNames = WorldArrays "meta" "params" "pos" "vel" "axis" "normal" "scalars" "radii" "verts"
  "outline" "grid" "cellOf" "items" "contacts" "prev" "bodyPrev" "mouse" "probe" "near" "walk" "joints" "flip" "partners"
  "islands" "seenParams" "hull"

read3 :: Imp m => Array m -> Index m -> m (V3 (Scalar m))
{-# INLINE read3 #-}
read3 a i = readAt3 a (3 * i)

write3 :: Imp m => Array m -> Index m -> V3 (Scalar m) -> m ()
{-# INLINE write3 #-}
write3 a i = writeAt3 a (3 * i)

-- | Three consecutive numbers from the given offset.
readAt3 :: Imp m => Array m -> Index m -> m (V3 (Scalar m))
{-# INLINE readAt3 #-}
readAt3 a o = V3 <$> readArray a o <*> readArray a (o + 1) <*> readArray a (o + 2)

writeAt3 :: Imp m => Array m -> Index m -> V3 (Scalar m) -> m ()
{-# INLINE writeAt3 #-}
writeAt3 a o (V3 x y z) = writeArray a o x >> writeArray a (o + 1) y >> writeArray a (o + 2) z

share3 :: Imp m => V3 (Scalar m) -> m (V3 (Scalar m))
{-# INLINE share3 #-}
share3 = shareAll

ix :: (Imp m, Enum e) => e -> Index m
{-# INLINE ix #-}
ix = fromIntegral . fromEnum

-- | Where field @f@ of record @k@ is in an array of records of @stride@ numbers.
fieldAt :: (Imp m, Enum e) => Int -> Index m -> e -> Index m
{-# INLINE fieldAt #-}
fieldAt stride k f = fromIntegral stride * k + ix f

readSlot :: Imp m => WorldArrays (Array m) -> Index m -> Slot -> m (Scalar m)
{-# INLINE readSlot #-}
readSlot w i s = readArray (wScalars w) (fieldAt scalarSlots i s)

writeSlot :: Imp m => WorldArrays (Array m) -> Index m -> Slot -> Scalar m -> m ()
{-# INLINE writeSlot #-}
writeSlot w i s = writeArray (wScalars w) (fieldAt scalarSlots i s)

readMeta :: Imp m => WorldArrays (Array m) -> Meta -> m (Scalar m)
{-# INLINE readMeta #-}
readMeta w k = readArray (wMeta w) (ix k)

writeMeta :: Imp m => WorldArrays (Array m) -> Meta -> Scalar m -> m ()
{-# INLINE writeMeta #-}
writeMeta w k = writeArray (wMeta w) (ix k)

readParam :: Imp m => WorldArrays (Array m) -> Param -> m (Scalar m)
{-# INLINE readParam #-}
readParam w k = readArray (wParams w) (ix k)

readContact :: Imp m => WorldArrays (Array m) -> Index m -> ContactField -> m (Scalar m)
{-# INLINE readContact #-}
readContact w c k = readArray (wContacts w) (fieldAt contactStride c k)

writeContact :: Imp m => WorldArrays (Array m) -> Index m -> ContactField -> Scalar m -> m ()
{-# INLINE writeContact #-}
writeContact w c k = writeArray (wContacts w) (fieldAt contactStride c k)

-- | Three consecutive fields starting at the given one.
readContact3 :: Imp m => WorldArrays (Array m) -> Index m -> ContactField -> m (V3 (Scalar m))
{-# INLINE readContact3 #-}
readContact3 w c k = readAt3 (wContacts w) (fieldAt contactStride c k)

writeContact3 :: Imp m => WorldArrays (Array m) -> Index m -> ContactField -> V3 (Scalar m) -> m ()
{-# INLINE writeContact3 #-}
writeContact3 w c k = writeAt3 (wContacts w) (fieldAt contactStride c k)

readPrev :: Imp m => WorldArrays (Array m) -> Index m -> PrevField -> m (Scalar m)
{-# INLINE readPrev #-}
readPrev w k f = readArray (wPrev w) (fieldAt prevStride k f)

writePrev :: Imp m => WorldArrays (Array m) -> Index m -> PrevField -> Scalar m -> m ()
{-# INLINE writePrev #-}
writePrev w k f = writeArray (wPrev w) (fieldAt prevStride k f)

readJoint :: Imp m => WorldArrays (Array m) -> Index m -> JointField -> m (Scalar m)
{-# INLINE readJoint #-}
readJoint w j k = readArray (wJoints w) (fieldAt jointStride j k)

writeJoint :: Imp m => WorldArrays (Array m) -> Index m -> JointField -> Scalar m -> m ()
{-# INLINE writeJoint #-}
writeJoint w j k = writeArray (wJoints w) (fieldAt jointStride j k)

-- | Three consecutive fields starting at the given one.
readJoint3 :: Imp m => WorldArrays (Array m) -> Index m -> JointField -> m (V3 (Scalar m))
{-# INLINE readJoint3 #-}
readJoint3 w j k = readAt3 (wJoints w) (fieldAt jointStride j k)

writeJoint3 :: Imp m => WorldArrays (Array m) -> Index m -> JointField -> V3 (Scalar m) -> m ()
{-# INLINE writeJoint3 #-}
writeJoint3 w j k = writeAt3 (wJoints w) (fieldAt jointStride j k)

readIsland :: Imp m => WorldArrays (Array m) -> Index m -> IslandField -> m (Scalar m)
{-# INLINE readIsland #-}
readIsland w i f = readArray (wIslands w) (fieldAt islandStride i f)

writeIsland :: Imp m => WorldArrays (Array m) -> Index m -> IslandField -> Scalar m -> m ()
{-# INLINE writeIsland #-}
writeIsland w i f = writeArray (wIslands w) (fieldAt islandStride i f)

-- | 1 for a body the step moves (movable and awake), 0 for a static or a
-- sleeping one.
moving :: Imp m => WorldArrays (Array m) -> Index m -> m (Scalar m)
{-# INLINE moving #-}
moving w i = do
  invMass <- readSlot w i InvMass
  asleep <- readSlot w i Asleep
  share (select invMass (1 - asleep) 0)

readMouse :: Imp m => WorldArrays (Array m) -> MouseField -> m (Scalar m)
readMouse w k = readArray (wMouse w) (ix k)

writeMouse :: Imp m => WorldArrays (Array m) -> MouseField -> Scalar m -> m ()
writeMouse w k = writeArray (wMouse w) (ix k)

-- | Outline vertex @d@ (the last step along direction @d@) of body @i@,
-- from 'wOutline': the narrow phase reads a body's outline vertices
-- together, and in 'wVerts' each sits on a cache line of its own among the
-- inner vertices (read from here, the collision phase of the settled piles
-- of 3000 bodies took 3 to 15 % less time, manifold bench).
outlineVertex :: Imp m => Layout -> WorldArrays (Array m) -> Index m -> Index m -> m (V3 (Scalar m))
{-# INLINE outlineVertex #-}
outlineVertex l w i d = read3 (wOutline w) (fromIntegral (polyDirections (polygon l)) * i + d)

-- | What the narrow phase needs of a body.
data BodyFrame s = BodyFrame
  { bfCentre :: !(V3 s)
  , bfNormal :: !(V3 s)
  , bfU :: !(V3 s) -- ^ the axis
  , bfW :: !(V3 s) -- ^ normal × axis ('perpendicular')
  , bfAngle :: !s
  , bfSize :: !s
  , bfInvMass :: !s
  , bfInvInertia :: !s
  }

bodyFrame :: Imp m => Metric -> WorldArrays (Array m) -> Index m -> m (BodyFrame (Scalar m))
{-# INLINE bodyFrame #-}
bodyFrame m w i = do
  c <- read3 (wPos w) i
  n <- read3 (wNormal w) i
  u <- read3 (wAxis w) i
  wv <- share3 (perpendicular m n u)
  BodyFrame c n u wv <$> readSlot w i Angle <*> readSlot w i BoundRadius
    <*> readSlot w i InvMass <*> readSlot w i InvInertia

-- | 1 where every value is finite, otherwise a non-positive number or NaN:
-- @x − x@ is 0 exactly when @x@ is finite.
finiteness :: Field a => [a] -> a
{-# INLINE finiteness #-}
finiteness xs = 1 - abs (sum [x - x | x <- xs])

-- | The value where it is finite, 0 where it is not.
finiteOr0 :: Field a => a -> a
{-# INLINE finiteOr0 #-}
finiteOr0 x = select (finiteness [x]) x 0

countWarning :: Imp m => WorldArrays (Array m) -> m ()
{-# INLINE countWarning #-}
countWarning w = readMeta w Warnings >>= writeMeta w Warnings . (+ 1)

-- | The length of one sub-step: the step's @dt@ over its sub-steps.
substepLength :: Imp m => WorldArrays (Array m) -> m (Scalar m)
{-# INLINE substepLength #-}
substepLength w = do
  dt <- readParam w Dt
  n <- readParam w Substeps
  share (dt / n)

-- | Gravity for a time @h@, projected to the tangent plane, for every
-- movable body.
applyGravity :: Imp m => Space -> WorldArrays (Array m) -> Scalar m -> m ()
{-# SPECIALIZE applyGravity :: Space -> WorldArrays NativeArray -> Double -> Native () #-}
applyGravity sp w h = do
  count <- readMeta w BodyCount
  on <- readParam w GravityOn
  forEach (toIndex count) $ \i -> do
    m <- moving w i
    whenPositive (m * on) $ do
      p <- read3 (wPos w) i
      v <- read3 (wVel w) i
      n <- read3 (wNormal w) i
      let g = tangentProjection (spaceMetric sp) n (evalGravity sp p)
          v' = v ^+^ h *^ g
      ifPositive (finiteness (toList3 v')) (write3 (wVel w) i v') (countWarning w)

-- | Move every body along its velocity for a time @h@ (paper §2.4, §4.1:
-- @coord += veloc * dt@ for position and angle together): a geodesic step
-- of the centre, the velocity and axis carried to the new tangent plane;
-- how far each body moved and turned is added up for the solver (see
-- 'MovedX'). A step that would produce a non-finite value leaves the body
-- as it was and counts a warning. Sleeping bodies stay where they are.
-- Bodies may end outside a quotient's
-- fundamental domain: 'wrapIntoDomain' brings them back once a step, after
-- the sub-steps, so that within a step every body keeps one frame.
integrate :: Imp m => Space -> WorldArrays (Array m) -> Scalar m -> m ()
{-# SPECIALIZE integrate :: Space -> WorldArrays NativeArray -> Double -> Native () #-}
integrate sp w dt = do
  count <- readMeta w BodyCount
  let f = spaceField sp
      metric = spaceMetric sp
  forEach (toIndex count) $ \i -> readSlot w i Asleep >>= \asleep -> whenPositive (0.5 - asleep) $ do
    p <- read3 (wPos w) i
    axis <- read3 (wAxis w) i
    angle <- readSlot w i Angle
    omega <- readSlot w i Omega
    n <- read3 (wNormal w) i
    -- the solver pushes along rows found at the step's start, in the
    -- tangent planes the bodies had then: what of that leaves the tangent
    -- plane here is the surface's to take (the walk below keeps the speed,
    -- and would turn it into speed along the surface)
    v <- read3 (wVel w) i >>= share3 . tangentProjection metric n
    let (p0, v0, n0) = geodesicStepFrom metric f dt n (p, v)
    p1 <- share3 p0
    -- a fast body over a tight bend (a rounded cube edge) can end its three
    -- Newton steps short of the surface: three more, which leave a settled
    -- point exactly where it is (and then nothing else changes either)
    let (p2, g2) = projectAlongWithGradient f n p1
        moved = select (quadrance (p2 ^-^ p1)) 1 0
    movedS <- share moved
    p' <- share3 p2
    n' <- share3 (select movedS <$> normalOf metric g2 <*> n0)
    v' <- share3 (select movedS <$> (normIn metric v0 *^ normalizeIn metric (tangentProjection metric n' v0)) <*> v0)
    axis' <- share3 (normalizeIn metric (tangentProjection metric n' axis))
    -- a step is good when everything is finite and the point is on the
    -- surface: where a step is longer than the surface is wide (down the
    -- trumpet's neck) the pull-back can converge to nowhere near it
    residual <- share (evalFn f p')
    let angle' = angle + dt * omega
        ok = minF (finiteness (concatMap toList3 [p', v', axis', n'] ++ [angle', residual]))
                  (constant onSurfaceTolerance - abs residual)
    ifPositive ok
      (do write3 (wPos w) i p'
          write3 (wVel w) i v'
          write3 (wAxis w) i axis'
          write3 (wNormal w) i n'
          writeSlot w i Angle angle'
          let V3 dx dy dz = dt *^ v
              add slot d = readSlot w i slot >>= writeSlot w i slot . (+ d)
          add MovedX dx
          add MovedY dy
          add MovedZ dz
          add Turned (dt * omega))
      -- keep the last good position, axis and angle; the motion that led
      -- out of the surface's good region is dropped
      (do write3 (wVel w) i (V3 0 0 0)
          writeSlot w i Omega 0
          countWarning w)

-- | Bring every body back into the quotient's fundamental domain (nothing
-- on a space without one), its vectors (velocity, axis, normal) carried by
-- the wrap's linear map. Through a flipping edge a body comes out
-- mirrored: its angle and angular velocity change sign (orientation
-- reverses); 'wFlip' says which bodies did, for the joints
-- ("Manifold.Joint").
wrapIntoDomain :: Imp m => Space -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE wrapIntoDomain :: Space -> WorldArrays NativeArray -> Native () #-}
wrapIntoDomain sp w = case quotientWrap (spaceQuotient sp) of
  Nothing -> pure ()
  Just wrap -> do
    count <- readMeta w BodyCount
    forEach (toIndex count) $ \i -> readSlot w i Asleep >>= \asleep -> ifPositive asleep (writeArray (wFlip w) i 1) $ do
      p <- read3 (wPos w) i
      let Wrapped p' carry s = wrap p
      sS <- share s
      carryS <- mapM shareAll carry
      writeArray (wFlip w) i sS
      write3 (wPos w) i p'
      mapM_ (\arr -> read3 arr i >>= write3 arr i . linearMap carryS) [wVel w, wAxis w, wNormal w]
      readSlot w i Angle >>= writeSlot w i Angle . (sS *)
      readSlot w i Omega >>= writeSlot w i Omega . (sS *)
      -- a held body keeps the grabbed point's polar angle, mirrored too
      active <- readMouse w MActive
      held <- readMouse w MBody
      whenPositive (active * (0.5 - abs (held - toScalar i))) $
        readMouse w MLocalTheta >>= writeMouse w MLocalTheta . (sS *)

-- | Every body's velocity projected onto its tangent plane: the step's
-- last relaxing solve pushes along rows of the tangent planes the bodies
-- had when the step began, so that a velocity ends a little off the plane
-- it now has (a plane's rows and velocities never leave it: nothing to do).
tangentVelocities :: Imp m => Space -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE tangentVelocities :: Space -> WorldArrays NativeArray -> Native () #-}
tangentVelocities sp w
  | hasConstantGradient (spaceField sp) = pure ()
  | otherwise = do
      count <- readMeta w BodyCount
      forEach (toIndex count) $ \i -> readSlot w i Asleep >>= \asleep -> whenPositive (0.5 - asleep) $ do
        n <- read3 (wNormal w) i
        read3 (wVel w) i >>= write3 (wVel w) i . tangentProjection (spaceMetric sp) n

-- | How far off the surface (in field value) a step may end and still count
-- as good.
onSurfaceTolerance :: Double
onSurfaceTolerance = 1e-7

toList3 :: V3 a -> [a]
toList3 (V3 a b c) = [a, b, c]

-- | The outline radius of a shape in each polygon direction, scaled by size,
-- for body @i@ (the page calls this when it adds a body).
outlineRadiiInto :: Imp m => Layout -> (Scalar m -> Scalar m) -> WorldArrays (Array m) -> Index m -> Scalar m -> m ()
outlineRadiiInto l outline w i size = do
  let nd = polyDirections (polygon l)
  forEach (fromIntegral nd) $ \d -> do
    let theta = toScalar d * constant (2 * pi / fromIntegral nd)
    writeArray (wRadii w) (fromIntegral nd * i + d) (size * outline theta)

-- | Whether a field's gradient is the same everywhere (a plane): its
-- symbolic gradient at a symbolic point is made of numbers.
hasConstantGradient :: ScalarFn -> Bool
hasConstantGradient = isJust . constantGradient

-- | A field's gradient where it is the same everywhere (a plane).
constantGradient :: ScalarFn -> Maybe (V3 Double)
constantGradient f = traverse literalValue (gradFn f (V3 (sym "x") (sym "y") (sym "z")))

-- | Walk every awake body's geodesic polygon into the vertex cache (paper
-- §3.4): a sleeping body has not moved since its last walk.
polygoniseAll :: Imp m => Space -> Layout -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE polygoniseAll :: Space -> Layout -> WorldArrays NativeArray -> Native () #-}
polygoniseAll sp l w = do
  count <- readMeta w BodyCount
  forEach (toIndex count) $ \i -> do
    asleep <- readSlot w i Asleep
    whenPositive (0.5 - asleep) (polygoniseOutline sp l w i)
  -- then the hulls' corners, in a subroutine of their own (in the phase,
  -- even a call a body made the trumpet's phase larger than V8 optimises)
  subroutine "walkAllCorners" [] $ \_ -> do
    bodies <- readMeta w BodyCount
    forEach (toIndex bodies) $ \i -> do
      asleep <- readSlot w i Asleep
      whenPositive (0.5 - asleep) (cornersOf sp w i)

-- | Walk every body's polygon, sleeping or not (what the page asks for when
-- the polygon parameters change).
polygoniseEvery :: Imp m => Space -> Layout -> WorldArrays (Array m) -> m ()
polygoniseEvery sp l w = do
  count <- readMeta w BodyCount
  forEach (toIndex count) (polygoniseBody sp l w)

-- | Walk one body's polygon: from the centre, a geodesic in each direction,
-- in equal steps of the outline radius over the step count (paper §3.4).
--
-- A body no larger than the 'PolygonStep' parameter walks each direction in
-- one step instead: one RATTLE step of length @h@ lands within about
-- @h³/(6R²)@ of the geodesic's end on a surface of curvature radius @R@
-- (for the default step 0.05 and @R@ = 0.3, 0.5 % of @h@), and the polygon
-- walk is most of the engine's work. Its inner vertices, which only the
-- page draws, are then put on the chords from the centre (they sink below
-- the surface by about @h²/(8R)@, inside the page's depth tolerance).
polygoniseBody :: Imp m => Space -> Layout -> WorldArrays (Array m) -> Index m -> m ()
polygoniseBody sp l w i = polygoniseOutline sp l w i >> walkCorners sp w i

-- | 'polygoniseBody' with the corners walked in line: for a procedure
-- that takes arrays besides the world's (the page's addBody, given a
-- polygon's corners), which cannot call the step's subroutines (a
-- subroutine takes its caller's arrays, so it would be staged twice,
-- differently, under one name).
polygoniseInline :: Imp m => Space -> Layout -> WorldArrays (Array m) -> Index m -> m ()
polygoniseInline sp l w i = polygoniseOutline sp l w i >> cornersOf sp w i

-- | 'polygoniseBody''s outline, without the hull's corners.
polygoniseOutline :: Imp m => Space -> Layout -> WorldArrays (Array m) -> Index m -> m ()
polygoniseOutline sp l w i = do
  let f = spaceField sp
      metric = spaceMetric sp
      flat = hasConstantGradient f
      pp = polygon l
      nd = polyDirections pp
      ns = polySteps pp
      vpb = fromIntegral (verticesPerBody l)
      vertexIx d k = vpb * i + vertexIndex pp d (fromIntegral k) -- step k (1..ns) along d
      outlineIx d = fromIntegral nd * i + d
  p <- read3 (wPos w) i
  axis <- read3 (wAxis w) i
  n <- read3 (wNormal w) i
  angle <- readSlot w i Angle
  hmax <- readParam w PolygonStep
  rmax <- readSlot w i BoundRadius
  write3 (wVerts w) (vpb * i) p
  u <- share3 axis
  v <- share3 (perpendicular metric n axis)
  -- positive: walk in 'ns' steps; otherwise one (a step of 0 or less means always 'ns')
  fine <- share (select hmax (rmax - hmax) 1)
  -- the direction's cosine and sine, turned by 2π/nd from one direction to
  -- the next (two transcendental calls a body instead of two a direction)
  cos0 <- share (cosF angle)
  sin0 <- share (sinF angle)
  writeSlot w i TurnCos cos0
  writeSlot w i TurnSin sin0
  cosRef <- newRef cos0
  sinRef <- newRef sin0
  let turnC = constant (cos (2 * pi / fromIntegral nd))
      turnS = constant (sin (2 * pi / fromIntegral nd))
      nextDirection = do
        c <- readRef cosRef
        s <- readRef sinRef
        writeRef cosRef (c * turnC - s * turnS)
        writeRef sinRef (s * turnC + c * turnS)
        share3 (c *^ u ^+^ s *^ v)
      {-# INLINE nextDirection #-}
      radius d = readArray (wRadii w) (fromIntegral nd * i + d)
      directions = forEach (fromIntegral nd)
      scratch = wWalk w
      at d field = fromIntegral walkStride * d + field
      -- a direction's walk state: where its step starts and the unit normal
      -- there, the direction, and the Newton iterate
      (pointAt, directionAt, normalAt, iterateAt) = (0, 3, 6, 9)
      -- Every direction takes its step before any takes the next: one
      -- direction's arithmetic is a chain of roots and divisions, each
      -- waiting on the last, while the directions are independent, so
      -- loops across them let the processor overlap the directions instead
      -- of waiting on each chain in turn. 'stepLoopsWalk' makes a step in one
      -- loop (and a single step turns the direction where it is walked);
      -- 'newtonLoopsWalk' gives each Newton iteration of a step its own
      -- loop. The arithmetic is 'geodesicStepFrom''s, in the same order
      -- either way. Compiled natively (LLVM's code waits on the chains),
      -- Newton loops made the walk of the sphere with 1000 bodies twice as
      -- fast; in Chromium (whose code is busy with more instructions) they
      -- gained nothing and, with the steps counted in a loop so that V8
      -- optimises them, made the torus with 3000 bodies a quarter slower. On
      -- a flat surface Newton has nothing to wait on, and step loops are
      -- quicker in both.
      stepLoopsWalk steps stepLength vertex = do
        let fused = steps == 1
        unless fused $ directions $ \d -> nextDirection >>= writeAt3 scratch (at d directionAt)
        forM_ [1 .. steps] $ \k -> directions $ \d -> do
          let startAt field centre = if k == 1 then pure centre else readAt3 scratch (at d field)
          h <- stepLength d
          q0 <- startAt pointAt p
          nq <- startAt normalAt n
          dir <- if fused then nextDirection else readAt3 scratch (at d directionAt)
          projected <- projectAlongWithGradient f nq <$> share3 (q0 ^+^ h *^ dir)
          endStep steps vertex k d h nq (q0, dir) projected
      {-# INLINE stepLoopsWalk #-}
      -- A loop across the directions for each Newton iteration (the first
      -- also moves the point, the last ends the step), for each step. (Four
      -- steps of these loops, and one, unrolled in one function are more
      -- than Chromium's V8 optimises: the walk ran 10 to 20 times slower.
      -- Natively, the steps counted in a loop instead made the walk slower
      -- than one loop a step.)
      newtonLoopsWalk steps stepLength vertex = do
        directions $ \d -> nextDirection >>= writeAt3 scratch (at d directionAt)
        forM_ [1 .. steps] $ \k -> forM_ [1 .. stepProjectionIterations] $ \j -> directions $ \d -> do
          let startAt field centre = if k == 1 then pure centre else readAt3 scratch (at d field)
              start = do
                h <- stepLength d
                pd <- (,) <$> startAt pointAt p <*> readAt3 scratch (at d directionAt)
                pure (h, pd)
          nq <- startAt normalAt n
          q <- if j == 1 then (\(h, (q0, dir)) -> share3 (q0 ^+^ h *^ dir)) =<< start
               else readAt3 scratch (at d iterateAt)
          let projected = newtonAlong f nq q
          if j < stepProjectionIterations then writeAt3 scratch (at d iterateAt) =<< share3 (fst projected) else do
            (h, pd) <- start
            endStep steps vertex k d h nq pd projected
      {-# INLINE newtonLoopsWalk #-}
      -- the end of step k along direction d, once its moved point is back
      -- on the surface: the vertex, and the state the next step starts from
      endStep steps vertex k d h nq pd projected = do
        let (q1, dir1, n1) = geodesicStepEnd metric h nq pd projected
        q <- share3 q1
        vertex k d q
        when (k < steps) $ do
          writeAt3 scratch (at d pointAt) q
          writeAt3 scratch (at d directionAt) =<< share3 dir1
          writeAt3 scratch (at d normalAt) =<< share3 n1
      {-# INLINE endStep #-}
      -- a single step's end is the outline vertex; the inner vertices go on
      -- the chord from the centre
      outlineVertex' d q = do
        o <- share3 (finite q)
        write3 (wVerts w) (vertexIx d ns) o
        write3 (wOutline w) (outlineIx d) o
        forM_ [1 .. ns - 1] $ \k ->
          write3 (wVerts w) (vertexIx d k) (p ^+^ constant (fromIntegral k / fromIntegral ns) *^ (o ^-^ p))
      {-# INLINE outlineVertex' #-}
      -- a walk that fails (a singular point) leaves the vertex at the
      -- centre rather than poison the polygon
      finite q = select (finiteness (toList3 q)) <$> q <*> p
  -- (the page's loops first: then the symbolic flatness test is only made
  -- when staging the compiled step, not for every body of a generic step)
  let walk = if walkLoops l == LoopPerStep || flat then stepLoopsWalk else newtonLoopsWalk
  ifPositive fine
    (walk ns (share . (/ fromIntegral ns) <=< radius)
          (\k d q -> do
              o <- share3 (finite q)
              write3 (wVerts w) (vertexIx d k) o
              when (k == ns) $ write3 (wOutline w) (outlineIx d) o))
    (walk 1 radius (\_ d q -> outlineVertex' d q))

-- | Walk body @i@'s hull corners onto the surface ('hullWorldAt'): each
-- along the geodesic from the centre in its direction in the body's
-- frame, as far as its distance from the centre, as the outline is walked
-- (in 'cornerWalkSteps' steps for a body larger than the 'PolygonStep'
-- parameter, else in one). A circle's one corner is its centre; a body
-- without a hull has none. Run after the outline's walk, whose turn of
-- the body's angle ('TurnCos', 'TurnSin') it takes.
--
-- Printed as a JavaScript subroutine of the body's index alone (numbers
-- passed to it would each be a heap object a call); the step's polygon
-- phase walks every body's corners in one subroutine of its own.
walkCorners :: Imp m => Space -> WorldArrays (Array m) -> Index m -> m ()
{-# INLINE walkCorners #-}
walkCorners sp w i = subroutine "walkCorners" [toScalar i] $ \case
  [i'] -> cornersOf sp w (toIndex i')
  _ -> error "walkCorners: one argument"

-- | 'walkCorners''s walk.
cornersOf :: Imp m => Space -> WorldArrays (Array m) -> Index m -> m ()
{-# INLINE cornersOf #-}
cornersOf sp w i = do
  corners <- readSlot w i Corners
  ifPositive (corners - 1.5) (walkHullCorners sp w i corners)
    (whenPositive (corners - 0.5) $ read3 (wPos w) i >>= writeAt3 (wHull w) (fromIntegral hullStride * i + hullWorldAt 0))

-- | The walk of 'walkCorners' for a body with two corners or more.
walkHullCorners :: Imp m => Space -> WorldArrays (Array m) -> Index m -> Scalar m -> m ()
{-# INLINE walkHullCorners #-}
walkHullCorners sp w i corners = do
  let base = fromIntegral hullStride * i
      metric = spaceMetric sp
      f = spaceField sp
      walk p r dir steps = foldM (\qd _ -> shareBoth (geodesicStep metric f (r / fromIntegral steps) qd)) (p, dir) [1 .. steps :: Int]
      shareBoth (q, d) = (,) <$> share3 q <*> share3 d
  p <- read3 (wPos w) i
  hmax <- readParam w PolygonStep
  rmax <- readSlot w i BoundRadius
  fine <- share (select hmax (rmax - hmax) 1)
  (d1, d2) <- bodyAxes metric w i
  forLoop 0 (toIndex corners) $ \k -> do
    a <- readArray (wHull w) (base + hullLocalAt k)
    b <- readArray (wHull w) (base + hullLocalAt k + 1)
    r <- share (sqrt (a * a + b * b))
    dir <- share3 ((a / r) *^ d1 ^+^ (b / r) *^ d2)
    let put (q, _) = writeAt3 (wHull w) (base + hullWorldAt k) =<< share3 (select (finiteness (toList3 q)) <$> q <*> p)
    ifPositive fine (walk p r dir cornerWalkSteps >>= put) (walk p r dir 1 >>= put)

-- | Body @i@'s direction and normal × direction in its tangent plane: the
-- axes of its frame coordinates @(a, b)@ (its reference axis turned by its
-- angle).
bodyAxes :: Imp m => Metric -> WorldArrays (Array m) -> Index m -> m (V3 (Scalar m), V3 (Scalar m))
{-# INLINE bodyAxes #-}
bodyAxes metric w i = do
  u <- read3 (wAxis w) i
  n <- read3 (wNormal w) i
  v <- share3 (perpendicular metric n u)
  c0 <- readSlot w i TurnCos
  s0 <- readSlot w i TurnSin
  (,) <$> share3 (c0 *^ u ^+^ s0 *^ v) <*> share3 (c0 *^ v ^-^ s0 *^ u)

-- | How many geodesic steps walk a large body's corners (as many as its
-- outline's and its anchors').
cornerWalkSteps :: Int
cornerWalkSteps = 4
