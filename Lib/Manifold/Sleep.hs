{-# LANGUAGE FlexibleContexts #-}
-- | Islands and sleeping, as Box2D does them: the movable bodies linked by
-- contacts and joints make islands (static bodies and walls do not link);
-- a body's sleep timer runs while it moves slower than the sleep
-- threshold, which is relative to its size (bodies here range from 0.01 to
-- 0.5 units), and is reset when it moves faster; an island whose bodies have
-- all been calm for 'SleepTime' falls asleep together, its velocities
-- zeroed. A sleeping body costs the step next to nothing: it is not moved,
-- walked, collided with other sleeping or static bodies, nor solved.
--
-- An island wakes whole: when an awake body touches one of its bodies (a
-- contact row between them: as the step's contacts are found, before the
-- solve, which then moves the island's bodies with the rest; see
-- 'markTouched'), when a joint joins one of its bodies to an awake one or
-- is added or removed,
-- when one of its bodies is grabbed, when a body near it is removed, and
-- every island when a parameter changes (the wake phase, first in the
-- step, for what happened between steps).
--
-- Islands are found by a union–find over the movable awake bodies, only in
-- steps where some body's timer has run out (a busy scene pays nothing for
-- it). Union by rank keeps every tree at most log₂ of the bodies deep, so
-- that a find is a loop of that many steps (the staged language has no
-- loop that stops on a condition).
module Manifold.Sleep
  ( wakePhase
  , sleepIslands
  , markIsland
  , wakeMarked
  , markTouched
  , wakeNear
  , countIslands
  , setSleeping
  , labelIslands
  ) where

import Control.Monad (forM_, (>=>))
import Linear.V3 (V3 (..))
import Linear.Vector ((^-^))

import Manifold.Field
import Manifold.Metric
import Manifold.Stage.Imp
import Manifold.World

-- | Mark body @i@'s island to wake (nothing for an awake body): the wake
-- phase of the next step, or 'wakeMarked', wakes it.
markIsland :: Imp m => WorldArrays (Array m) -> Index m -> m ()
markIsland w i = do
  asleep <- readSlot w i Asleep
  whenPositive asleep $ do
    label <- readSlot w i Island
    writeIsland w (toIndex label) IslandWake 1
    writeMeta w WakeRequest 1

-- | Wake every body of the islands marked to wake.
wakeMarked :: Imp m => WorldArrays (Array m) -> m ()
wakeMarked w = do
  requested <- readMeta w WakeRequest
  whenPositive requested $ do
    count <- readMeta w BodyCount
    forEach (toIndex count) $ \i -> do
      asleep <- readSlot w i Asleep
      whenPositive asleep $ do
        label <- readSlot w i Island
        marked <- readIsland w (toIndex label) IslandWake
        whenPositive marked $ do
          wakeBody w i
          readMeta w AwakeCount >>= writeMeta w AwakeCount . (+ 1)
    forEach (toIndex count) $ \i -> writeIsland w i IslandWake 0
    writeMeta w WakeRequest 0

-- | Body @i@ awake, its timer from 0.
wakeBody :: Imp m => WorldArrays (Array m) -> Index m -> m ()
{-# INLINE wakeBody #-}
wakeBody w i = do
  writeSlot w i Asleep 0
  writeSlot w i SleepTimer 0
  writeSlot w i Island (-1)

-- | Mark the islands of the bodies whose bounds come within reach of body
-- @i@'s (what removing body @i@ wakes: the bodies resting on it).
wakeNear :: Imp m => Metric -> WorldArrays (Array m) -> Index m -> m ()
wakeNear metric w i = do
  count <- readMeta w BodyCount
  p <- read3 (wPos w) i
  r <- readSlot w i BoundRadius
  forEach (toIndex count) $ \k -> do
    q <- read3 (wPos w) k
    rk <- readSlot w k BoundRadius
    -- a margin of half the larger bound: what lay on body i, not only what touched it
    whenPositive (1.5 * (r + rk) - normIn metric (p ^-^ q)) (markIsland w k)
  markIsland w i

-- | The step's first phase: a parameter changed since the last step, or
-- sleeping is off, and every body wakes; otherwise the islands marked to
-- wake since the last step (joints made or removed) and a grabbed body's
-- wake. Then 'AwakeCount' counts the movable bodies awake.
wakePhase :: Imp m => WorldArrays (Array m) -> m ()
{-# SPECIALIZE wakePhase :: WorldArrays NativeArray -> Native () #-}
wakePhase w = do
  count <- readMeta w BodyCount
  changed <- newRef 0
  forM_ [minBound .. maxBound :: Param] $ \k -> do
    x <- readParam w k
    seen <- readArray (wSeenParams w) (fromIntegral (fromEnum k))
    whenPositive (abs (x - seen)) (writeRef changed 1)
    writeArray (wSeenParams w) (fromIntegral (fromEnum k)) x
  on <- readParam w Sleep
  whenPositive (1 - on) (writeRef changed 1)
  everything <- readRef changed
  ifPositive everything
    (forEach (toIndex count) (wakeBody w)
       >> forEach (toIndex count) (\i -> writeIsland w i IslandWake 0)
       >> writeMeta w WakeRequest 0)
    (do active <- readMouse w MActive
        whenPositive active $ readMouse w MBody >>= markIsland w . toIndex
        wakeMarked w)
  awake <- newRef 0
  forEach (toIndex count) (moving w >=> \m -> modifyRef awake (+ m))
  readRef awake >>= writeMeta w AwakeCount

-- | Mark the sleeping islands that the step's contact rows (or a joint)
-- link to an awake body to wake ('wakeMarked' wakes them). The step's
-- collision phase does this as soon as it has found the contacts, and
-- then wakes them and finds the contacts again, so that the woken bodies
-- are solved in that step with their own contacts (as Box2D wakes an
-- island when a contact with it begins): a body pushed while asleep, not
-- moving and with no row against the ground, would take the whole blow's
-- velocity into the ground the next step.
markTouched :: Imp m => WorldArrays (Array m) -> m ()
markTouched w = do
  on <- readParam w Sleep
  whenPositive on $ linkedPairs w $ \a b -> do
    ma <- moving w a
    mb <- moving w b
    whenPositive ma (markIsland w b)
    whenPositive mb (markIsland w a)

-- | The end of the step: the sleeping islands that this step's contact
-- rows or a joint link to an awake body wake (those the collision phase
-- did not: found by its second pass, or joined); every awake body's sleep
-- timer; where some timer has run out, the islands, and those whose every
-- body's timer has run out fall asleep.
sleepIslands :: Imp m => Metric -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE sleepIslands :: Metric -> WorldArrays NativeArray -> Native () #-}
sleepIslands metric w = do
  on <- readParam w Sleep
  whenPositive on $ do
    markTouched w
    wakeMarked w
    dt <- readParam w Dt
    threshold <- readParam w SleepSpeed
    delay <- readParam w SleepTime
    count <- readMeta w BodyCount
    active <- readMouse w MActive
    held <- readMouse w MBody
    -- a timer counts whole steps: it has run out within half a step of the delay
    let ranOut t = t - delay + 0.5 * dt
    due <- newRef 0
    forEach (toIndex count) $ \i -> do
      m <- moving w i
      whenPositive m $ do
        v <- read3 (wVel w) i
        omega <- readSlot w i Omega
        size <- readSlot w i Size
        reach <- readSlot w i BoundRadius
        t <- readSlot w i SleepTimer
        -- how far the step moved and turned it: a body pushed out of an
        -- overlap moves with no velocity left (the relaxing solve takes the
        -- push's back), and is not calm
        moved <- V3 <$> readSlot w i MovedX <*> readSlot w i MovedY <*> readSlot w i MovedZ
        turned <- readSlot w i Turned
        let calmSpeed = threshold * size
            speed = maxF (normIn metric v) (normIn metric moved / dt)
            spin = maxF (abs omega) (abs turned / dt)
            isHeld = active * select (0.5 - abs (held - toScalar i)) 1 0
            calm = minF (minF (calmSpeed - speed) (calmSpeed - spin * reach)) (0.5 - isHeld)
        t' <- share (select calm (t + dt) 0)
        writeSlot w i SleepTimer t'
        whenPositive (ranOut t') (writeRef due 1)
    anyDue <- readRef due
    whenPositive anyDue $ do
      labelIslands w
      forEach (toIndex count) $ \i -> moving w i >>= \m -> whenPositive m (writeIsland w i IslandCalm 1e300)
      forEach (toIndex count) $ \i -> moving w i >>= \m -> whenPositive m $ do
        root <- toIndex <$> readIsland w i IslandParent
        t <- readSlot w i SleepTimer
        readIsland w root IslandCalm >>= writeIsland w root IslandCalm . minF t
      forEach (toIndex count) $ \i -> moving w i >>= \m -> whenPositive m $ do
        root <- readIsland w i IslandParent
        calm <- readIsland w (toIndex root) IslandCalm
        whenPositive (ranOut calm) $ do
          writeSlot w i Asleep 1
          writeSlot w i Island root
          write3 (wVel w) i 0
          writeSlot w i Omega 0
          readMeta w AwakeCount >>= writeMeta w AwakeCount . subtract 1

-- | Run @visit a b@ for the two bodies of every contact row of the last
-- step and of every joint (not those against a wall or the world): what
-- links bodies into islands.
linkedPairs :: Imp m => WorldArrays (Array m) -> (Index m -> Index m -> m ()) -> m ()
{-# INLINE linkedPairs #-}
linkedPairs w visit = do
  let pairs count fieldA fieldB = forEach (toIndex count) $ \k -> do
        a <- fieldA k
        b <- fieldB k
        whenPositive (b + 0.5) (visit (toIndex a) (toIndex b))
  nc <- readMeta w ContactCount
  pairs nc (\c -> readContact w c CA) (\c -> readContact w c CB)
  nj <- readMeta w JointCount
  pairs nj (\j -> readJoint w j JA) (\j -> readJoint w j JB)

-- | The islands of the movable awake bodies, by union–find over the last
-- step's contacts and the joints: each such body's 'IslandParent' is its
-- island's root (a body of the island) after it.
labelIslands :: Imp m => WorldArrays (Array m) -> m ()
labelIslands w = do
  count <- readMeta w BodyCount
  forEach (toIndex count) $ \i -> do
    writeIsland w i IslandParent (toScalar i)
    writeIsland w i IslandRank 0
  -- a tree of union by rank is at most log₂(bodies) deep: a find walks
  -- that many parents (a root is its own)
  depthRef <- newRef 1
  reachRef <- newRef 2
  forEach 40 $ \_ -> do
    reach <- readRef reachRef
    whenPositive (count + 0.5 - reach) $ do
      modifyRef depthRef (+ 1)
      writeRef reachRef (2 * reach)
  depth <- readRef depthRef
  let find x = do
        r <- newRef (toScalar x)
        forEach (toIndex depth) $ \_ -> readRef r >>= \c -> readIsland w (toIndex c) IslandParent >>= writeRef r
        readRef r >>= share
      link a b = do
        ma <- moving w a
        mb <- moving w b
        whenPositive (minF ma mb) $ do
          ra <- find a
          rb <- find b
          whenPositive (abs (ra - rb) - 0.5) $ do
            ka <- readIsland w (toIndex ra) IslandRank
            kb <- readIsland w (toIndex rb) IslandRank
            ifPositive (kb - ka) (writeIsland w (toIndex ra) IslandParent rb) $ do
              writeIsland w (toIndex rb) IslandParent ra
              whenPositive (0.5 - abs (ka - kb)) (writeIsland w (toIndex ra) IslandRank (ka + 1))
  linkedPairs w link
  forEach (toIndex count) $ \i -> find i >>= writeIsland w i IslandParent

-- | The islands ('IslandCount'): the awake ones ('labelIslands') and the
-- sleeping ones (their names, each counted once), and the movable bodies
-- awake ('AwakeCount'). A static body is no island.
countIslands :: Imp m => WorldArrays (Array m) -> m ()
countIslands w = do
  labelIslands w
  count <- readMeta w BodyCount
  islands <- newRef 0
  awake <- newRef 0
  forEach (toIndex count) $ \i -> do
    m <- moving w i
    modifyRef awake (+ m)
    root <- readIsland w i IslandParent
    whenPositive (m * select (0.5 - abs (root - toScalar i)) 1 0) (modifyRef islands (+ 1))
  readRef awake >>= writeMeta w AwakeCount
  -- the sleeping islands' names, marked as counted in the rank (scratch)
  forEach (toIndex count) $ \i -> writeIsland w i IslandRank 0
  forEach (toIndex count) $ \i -> do
    asleep <- readSlot w i Asleep
    whenPositive asleep $ do
      label <- toIndex <$> readSlot w i Island
      seen <- readIsland w label IslandRank
      whenPositive (0.5 - seen) $ do
        writeIsland w label IslandRank 1
        modifyRef islands (+ 1)
  readRef islands >>= writeMeta w IslandCount

-- | Body @i@'s sleep state as a saved scene restores it: its timer
-- @timer@, and, for a @label@ of 0 or more (a body's index), asleep in the
-- island so named, at rest (nothing for a static body).
--
-- The parameters it sleeps or is calm under count as seen: a world just
-- loaded has not stepped, and its first wake phase would otherwise wake
-- every body and set every timer back to 0, so that a saved run's bodies
-- fell asleep later than the run's own did.
setSleeping :: Imp m => WorldArrays (Array m) -> Index m -> Scalar m -> Scalar m -> m ()
setSleeping w i label timer = do
  invMass <- readSlot w i InvMass
  writeSlot w i SleepTimer timer
  asleep <- share (minF invMass (label + 0.5))
  whenPositive (maxF timer asleep) $
    forM_ [minBound .. maxBound :: Param] $ \k ->
      readParam w k >>= writeArray (wSeenParams w) (fromIntegral (fromEnum k))
  whenPositive asleep $ do
    writeSlot w i Asleep 1
    writeSlot w i Island label
    write3 (wVel w) i 0
    writeSlot w i Omega 0
