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

-- | The body whose polygon holds the point (the deepest, if several), into
-- 'Picked' (−1 for none) and whether it was found through its antipodal
-- image into 'PickedSign' (1 or −1).
pickBody :: Imp m => Space -> Layout -> WorldArrays (Array m) -> V3 (Scalar m) -> m ()
pickBody sp l w q = do
  writeMeta w Picked (-1)
  writeMeta w PickedSign 1
  count <- readMeta w BodyCount
  best <- newRef 0
  let signs = map constant (pickSigns (spaceQuotient sp))
  forEach (toIndex count) $ \i -> do
    f <- bodyFrame (spaceMetric sp) w i
    mapM_ (\sgn -> do
      -- on a lattice, the image of the point nearest the body
      q' <- share3 (nearestImage (spaceQuotient sp) (bfCentre f) (sgn *^ q))
      whenPositive (bfSize f - normIn (spaceMetric sp) (q' ^-^ bfCentre f)) $ do
        (depth, _) <- pointInBody (spaceMetric sp) l w i f q'
        -- the centre itself counts as inside (its depth is its distance to
        -- the outline, which pointInBody measures too)
        b <- readRef best
        whenPositive (depth - b) $ do
          writeRef best depth
          writeMeta w Picked (toScalar i)
          writeMeta w PickedSign sgn) signs

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
