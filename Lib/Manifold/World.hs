{-# LANGUAGE FlexibleContexts #-}
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
  , layout
  , arraySizes
  , arrayNames
  , Slot (..)
  , scalarSlots
  , verticesPerBody
  , stepFree
  , polygoniseAll
  , outlineRadiiInto
  ) where

import Linear.V3 (V3 (..))
import Linear.Vector ((*^), (^+^))

import Manifold.Body (PolygonParams (..))
import Manifold.Field
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.Surface

-- | The world's arrays, one record for every interpretation.
data WorldArrays a = WorldArrays
  { wMeta :: a -- ^ [body count, warnings]
  , wPos :: a -- ^ 3 per body
  , wVel :: a -- ^ 3 per body
  , wAxis :: a -- ^ 3 per body, a unit tangent vector
  , wNormal :: a -- ^ 3 per body, the unit surface normal at the centre
  , wScalars :: a -- ^ 'scalarSlots' per body: angle, ω, 1/m, 1/I, size, bounding radius
  , wRadii :: a -- ^ directions per body: the outline's radius in each polygon direction
  , wVerts :: a -- ^ 3 × vertices per body: the cached polygon
  }

-- | Sizes that depend on the polygon parameters and the capacity.
data Layout = Layout
  { capacity :: Int
  , polygon :: PolygonParams
  } deriving (Show, Eq)

layout :: Int -> Layout
layout cap = Layout cap (PolygonParams 24 4)

data Slot = Angle | Omega | InvMass | InvInertia | Size | BoundRadius
  deriving (Show, Eq, Enum, Bounded)

scalarSlots :: Int
scalarSlots = fromEnum (maxBound :: Slot) + 1

verticesPerBody :: Layout -> Int
verticesPerBody l = 1 + polyDirections (polygon l) * polySteps (polygon l)

arraySizes :: Layout -> WorldArrays Int
arraySizes l = let c = capacity l in WorldArrays
  { wMeta = 2
  , wPos = 3 * c, wVel = 3 * c, wAxis = 3 * c, wNormal = 3 * c
  , wScalars = scalarSlots * c
  , wRadii = polyDirections (polygon l) * c
  , wVerts = 3 * verticesPerBody l * c
  }

arrayNames :: WorldArrays String
arrayNames = WorldArrays "meta" "pos" "vel" "axis" "normal" "scalars" "radii" "verts"

read3 :: Imp m => Array m -> Index m -> m (V3 (Scalar m))
read3 a i = V3 <$> readArray a (3 * i) <*> readArray a (3 * i + 1) <*> readArray a (3 * i + 2)

write3 :: Imp m => Array m -> Index m -> V3 (Scalar m) -> m ()
write3 a i (V3 x y z) = writeArray a (3 * i) x >> writeArray a (3 * i + 1) y >> writeArray a (3 * i + 2) z

share3 :: Imp m => V3 (Scalar m) -> m (V3 (Scalar m))
share3 = shareAll

slot :: Imp m => WorldArrays (Array m) -> Index m -> Slot -> Index m
slot _ i s = fromIntegral scalarSlots * i + fromIntegral (fromEnum s)

readSlot :: Imp m => WorldArrays (Array m) -> Index m -> Slot -> m (Scalar m)
readSlot w i s = readArray (wScalars w) (slot w i s)

writeSlot :: Imp m => WorldArrays (Array m) -> Index m -> Slot -> Scalar m -> m ()
writeSlot w i s = writeArray (wScalars w) (slot w i s)

-- | 1 where every value is finite, otherwise a non-positive number or NaN:
-- @x − x@ is 0 exactly when @x@ is finite.
finiteness :: Field a => [a] -> a
finiteness xs = 1 - abs (sum [x - x | x <- xs])

-- | Free motion for one time step, for every body.
stepFree :: Imp m => Space -> WorldArrays (Array m) -> Scalar m -> Scalar m -> m ()
stepFree sp w dt gravityOn = do
  count <- readArray (wMeta w) 0
  let f = spaceField sp
  forEach (toIndex count) $ \i -> do
    p <- read3 (wPos w) i
    v <- read3 (wVel w) i
    axis <- read3 (wAxis w) i
    angle <- readSlot w i Angle
    omega <- readSlot w i Omega
    invMass <- readSlot w i InvMass
    n <- share3 (unitNormal f p)
    let gravity = tangentProjection n (evalGravity sp p)
        movable = select invMass 1 0
        v1 = v ^+^ (dt * gravityOn * movable) *^ gravity
    v1' <- share3 v1
    let (p1, v2) = geodesicStep f dt (p, v1')
    p' <- share3 p1
    n' <- share3 (unitNormal f p')
    v'' <- share3 v2
    axis'' <- share3 (safeNormalize (tangentProjection n' axis))
    let angle' = angle + dt * omega
    let ok = finiteness (concatMap toList3 [p', v'', axis'', n'] ++ [angle'])
    ifPositive ok
      (do write3 (wPos w) i p'
          write3 (wVel w) i v''
          write3 (wAxis w) i axis''
          write3 (wNormal w) i n'
          writeSlot w i Angle angle')
      (do warnings <- readArray (wMeta w) 1
          writeArray (wMeta w) 1 (warnings + 1))
  where
    toList3 (V3 a b c) = [a, b, c]

-- | The outline radius of a shape in each polygon direction, scaled by size,
-- for body @i@ (the page calls this when it adds a body).
outlineRadiiInto :: Imp m => Layout -> (Scalar m -> Scalar m) -> WorldArrays (Array m) -> Index m -> Scalar m -> m ()
outlineRadiiInto l outline w i size = do
  let nd = polyDirections (polygon l)
  forEach (fromIntegral nd) $ \d -> do
    let theta = toScalar d * constant (2 * pi / fromIntegral nd)
    writeArray (wRadii w) (fromIntegral nd * i + d) (size * outline theta)

-- | Walk every body's geodesic polygon into the vertex cache.
polygoniseAll :: Imp m => Space -> Layout -> WorldArrays (Array m) -> m ()
polygoniseAll sp l w = do
  count <- readArray (wMeta w) 0
  let f = spaceField sp
      pp = polygon l
      nd = polyDirections pp
      ns = polySteps pp
      vpb = fromIntegral (verticesPerBody l)
  forEach (toIndex count) $ \i -> do
    p <- read3 (wPos w) i
    axis <- read3 (wAxis w) i
    n <- read3 (wNormal w) i
    angle <- readSlot w i Angle
    write3 (wVerts w) (vpb * i) p
    (u, v) <- (\(a, b) -> (,) <$> share3 a <*> share3 b) (tangentFrame n axis)
    forEach (fromIntegral nd) $ \d -> do
      r <- readArray (wRadii w) (fromIntegral nd * i + d)
      let phi = angle + toScalar d * constant (2 * pi / fromIntegral nd)
      c <- share (cos phi)
      s <- share (sin phi)
      h <- share (r / fromIntegral ns)
      let walk 0 _ _ = pure ()
          walk k q dir = do
            let (q1, dir1) = geodesicStep f h (q, dir)
            q' <- share3 q1
            dir' <- share3 dir1
            write3 (wVerts w) (vpb * i + 1 + d * fromIntegral ns + fromIntegral (ns - k)) q'
            walk (k - 1 :: Int) q' dir'
      walk ns p (c *^ u ^+^ s *^ v)
