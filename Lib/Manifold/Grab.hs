{-# LANGUAGE FlexibleContexts #-}
-- | Picking a body under a surface point and holding it with the mouse joint
-- (paper §3.3: the grabbed body is pulled towards the mouse's surface point
-- by a constraint). On a quotient space a body may be picked through its
-- image; the joint then works on the image's side, so targets are mapped
-- back.
module Manifold.Grab
  ( pickBody
  , grab
  , dragTo
  , release
  ) where

import Linear.V3 (V3 (..))
import Linear.Vector ((*^), (^-^))

import Manifold.Anchor (polarOf)
import Manifold.Collide (pointInBody)
import Manifold.Field
import Manifold.Metric
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.World

-- | The body whose shape holds the point (the deepest, if several), into
-- 'Picked' (−1 for none) and whether it was found through its antipodal
-- image into 'PickedSign' (1 or −1). A body of corners (a circle, a
-- capsule, a box, a polygon) holds what its hull holds, as it is drawn
-- and collides; another body what its sampled outline holds.
pickBody :: Imp m => Space -> Layout -> WorldArrays (Array m) -> V3 (Scalar m) -> m ()
pickBody sp l w q = do
  writeMeta w Picked (-1)
  writeMeta w PickedSign 1
  count <- readMeta w BodyCount
  best <- newRef 0
  depthRef <- newRef 0
  let signs = map constant (pickSigns (spaceQuotient sp))
      metric = spaceMetric sp
  forEach (toIndex count) $ \i -> do
    f <- bodyFrame metric w i
    corners <- readSlot w i Corners
    reach <- readSlot w i BoundRadius
    mapM_ (\sgn -> do
      -- on a lattice, the image of the point nearest the body
      q' <- share3 (nearestImage (spaceQuotient sp) (bfCentre f) (sgn *^ q))
      -- (a hull reaches its corners, beyond its Size: a box's least half-extent)
      whenPositive (select corners reach (bfSize f) - normIn metric (q' ^-^ bfCentre f)) $ do
        ifPositive corners
          (pointInHull metric w i f q' >>= writeRef depthRef)
          (pointInBody metric l w i f q' >>= writeRef depthRef . fst)
        depth <- readRef depthRef
        -- the centre itself counts as inside (its depth is its distance to
        -- the outline, which pointInBody measures too)
        b <- readRef best
        whenPositive (depth - b) $ do
          writeRef best depth
          writeMeta w Picked (toScalar i)
          writeMeta w PickedSign sgn) signs

-- | How deep point @q@ (near the surface) lies in body @i@'s hull, positive
-- inside: its corners, walked onto the surface, and the point seen in the
-- body's tangent plane; inside a polygon of three corners or more, the
-- radius plus the distance to the nearest edge's line; elsewhere the radius
-- less the distance to the nearest edge (a capsule's segment, a circle's
-- centre). Points far off the tangent plane (another sheet) are outside.
pointInHull :: Imp m => Metric -> WorldArrays (Array m) -> Index m -> BodyFrame (Scalar m) -> V3 (Scalar m) -> m (Scalar m)
pointInHull metric w i f q = do
  count <- readSlot w i Corners
  let base = fromIntegral hullStride * i
      local p = let d = p ^-^ bfCentre f in (inner metric d (bfU f), inner metric d (bfW f))
      corner k = do
        p <- V3 <$> readArray (wHull w) (base + hullWorldAt k) <*> readArray (wHull w) (base + hullWorldAt k + 1)
               <*> readArray (wHull w) (base + hullWorldAt k + 2)
        let (x, y) = local p
        (,) <$> share x <*> share y
      next k = toIndex (select (toScalar k + 1.5 - count) 0 (toScalar k + 1))
      (qx, qy) = local q
  height <- share (inner metric (q ^-^ bfCentre f) (bfNormal f))
  radius <- readArray (wHull w) base
  -- the corners' turning sense in the plane (its sign: the polygon's area's)
  area <- newRef 0
  forLoop 0 (toIndex count) $ \k -> do
    (ax, ay) <- corner k
    (bx, by) <- corner (next k)
    readRef area >>= writeRef area . (+ (ax * by - bx * ay))
  sense <- (\a -> select a 1 (-1)) <$> readRef area
  beyond <- newRef (-1e300) -- the largest signed distance beyond an edge's line
  nearest <- newRef 1e300 -- the least distance to an edge
  forLoop 0 (toIndex count) $ \k -> do
    (ax, ay) <- corner k
    (bx, by) <- corner (next k)
    ex <- share (bx - ax)
    ey <- share (by - ay)
    len2 <- share (ex * ex + ey * ey)
    px <- share (qx - ax)
    py <- share (qy - ay)
    t <- share (select len2 (clampF 0 1 ((px * ex + py * ey) / maxF len2 1e-300)) 0)
    dx <- share (px - t * ex)
    dy <- share (py - t * ey)
    readRef nearest >>= writeRef nearest . minF (sqrt (dx * dx + dy * dy))
    readRef beyond >>= writeRef beyond . maxF (select len2 (sense * (px * ey - py * ex) / sqrt (maxF len2 1e-300)) 0)
  out <- readRef beyond
  d <- readRef nearest
  let inside = minF (negate out) (count - 2.5)
      depth = select inside (radius - out) (radius - d)
  share (select (bfSize f + radius - abs height) depth (-1))

-- | Hold body @i@ at the surface point @q@ (on the side given by @sgn@): the
-- point's polar coordinates in the body are kept, so the body is held where
-- it was grabbed, not at its centre. On a lattice the target may be any
-- image of the point: the solver pulls towards the one nearest the body.
grab :: Imp m => Space -> WorldArrays (Array m) -> Index m -> Scalar m -> V3 (Scalar m)
     -> Scalar m -> Scalar m -> Scalar m -> m ()
grab sp w i sgn q frequency damping maxForce = do
  f <- bodyFrame (spaceMetric sp) w i
  (r, theta) <- polarOf sp f (sgn *^ q)
  writeMouse w MActive 1
  writeMouse w MBody (toScalar i)
  writeMouse w MSign sgn
  writeMouse w MLocalR r
  writeMouse w MLocalTheta theta
  writeMouse w MFrequency frequency
  writeMouse w MDamping damping
  writeMouse w MMaxForce maxForce
  writeMouse w MImpulseU 0
  writeMouse w MImpulseW 0
  dragTo w q

-- | Move the mouse joint's target to surface point @q@.
dragTo :: Imp m => WorldArrays (Array m) -> V3 (Scalar m) -> m ()
dragTo w q = do
  sgn <- readMouse w MSign
  let V3 x y z = sgn *^ q
  writeMouse w MTargetX x
  writeMouse w MTargetY y
  writeMouse w MTargetZ z

-- | Let go: the mouse joint is off until the next 'grab'.
release :: Imp m => WorldArrays (Array m) -> m ()
release w = writeMouse w MActive 0
