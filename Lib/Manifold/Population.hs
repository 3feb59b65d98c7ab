{-# LANGUAGE LambdaCase #-}
{-# LANGUAGE FlexibleContexts #-}
-- | Adding and removing bodies at run time, written once: the native engine
-- and the page's JavaScript add a body the same way (projected onto the
-- surface, velocity onto the tangent plane, mass and moment of inertia
-- integrated from the outline as in paper §2.4).
module Manifold.Population
  ( BodyArgs (..)
  , addBodyWith
  , removeBody
  , frameMisfit
  ) where

import Linear.Metric (norm)
import Linear.V3 (V3 (..))
import Linear.Vector ((*^), (^-^))

import Control.Monad (forM, forM_)

import Manifold.Body (PolygonParams (..), massIntegrals)
import Manifold.ContactManifold (maxHullCorners)
import Manifold.Field
import Manifold.Hull
import Manifold.Joint (forgetBodyJoints)
import Manifold.Metric
import Manifold.Sleep (wakeMarked, wakeNear)
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
  , baAngle :: s -- ^ from the axis: the reference axis at the position, or 'baAxis' when restoring
  , baOmega :: s
  , baRestore :: s -- ^ 1: restore a saved body, its position, velocity, axis and normal exactly as given; 0: place it
  , baAxis :: V3 s -- ^ the saved axis (restoring only)
  , baNormal :: V3 s -- ^ the saved normal (restoring only)
  , baFriction :: s -- ^ its friction coefficient, or −1: the scene's
  , baRestitution :: s -- ^ its restitution, or −1: the scene's
  , baShape :: s -- ^ the shape's code ("Manifold.Hull": 0 a circle, −1 a box, −2 a capsule, −3 a convex polygon, 3 or more a regular polygon, 'outlineCode' one's own)
  , baShapeP :: s -- ^ the shape's first number (a box's half-extent along its direction, a capsule's half length, a convex polygon's count of corners)
  , baShapeQ :: s -- ^ its second (a box's half-extent across, a capsule's or a polygon's radius)
  }

-- | Add a body with the given outline (for size 1). A box or a capsule
-- takes its size from its numbers ('hullSize') and its mass in closed
-- form ('hullMass'); a convex polygon its corners from @cornersIn@ (@a@
-- and @b@ of each, 'maxHullCorners' of them, the first 'baShapeP'
-- counting), counter-clockwise ('orientCorners') and moved so that its
-- centre of mass is the body's centre ('centredCorners'), and its size,
-- mass and outline from them; a square or a regular polygon of up to
-- 'maxHullCorners' sides is the polygon of its corners ('regularCorners')
-- with its mass from them; every body with a hull gets its corners
-- ('hullCorner'). Sets 'LastAdded' to its
-- index, or to −1 when the world is full or the position does not project
-- onto the surface, or to −2 when a restored body's frame does not fit the
-- surface ('frameFits').
--
-- A body placed anew is projected onto the surface, its velocity onto the
-- tangent plane, and it starts from the reference axis there. A restored
-- body (what a saved scene holds) takes its position, velocity, axis and
-- normal as they were saved, bit for bit: projecting them again would move
-- them in the last bits, and a pile would run on differently.
addBodyWith :: Imp m => Space -> Layout -> WorldArrays (Array m) -> Array m -> (Scalar m -> Scalar m -> Scalar m -> Scalar m -> Scalar m) -> BodyArgs (Scalar m) -> m ()
addBodyWith sp l w cornersIn outlineGiven b = do
  count <- readMeta w BodyCount
  cap <- readMeta w Capacity
  let f = spaceField sp
      metric = spaceMetric sp
      restoring = baRestore b
  placed <- share3 (projectToSurface f (baPos b))
  p <- share3 (select restoring <$> baPos b <*> placed)
  surfaceNormal <- share3 (unitNormal metric f p)
  n <- share3 (select restoring <$> baNormal b <*> surfaceNormal)
  -- every condition must hold; a NaN (a vanished gradient) fails it
  let usable = allPositive [cap - count - 0.5, normIn metric n - 0.5, finiteness (toList3 p ++ toList3 n)]
      fits = select restoring (frameFits metric f p surfaceNormal b) 1
  ifPositive usable
    (ifPositive fits
      (do let i = toIndex count
              movable = 1 - baStatic b
              v = movable *^ (select restoring <$> baVel b <*> tangentProjection metric n (baVel b))
              axis = select restoring <$> baAxis b <*> referenceAxis metric n
          write3 (wPos w) i p
          write3 (wVel w) i v
          axis' <- share3 axis
          write3 (wAxis w) i axis'
          write3 (wNormal w) i n
          let code = baShape b
              p = baShapeP b
              q = baShapeQ b
          -- a polygon of its corners: given ones, or a square's or a
          -- small regular polygon's
          vertices <- share (isVertices code)
          regular <- share (isRegularHull code)
          convex <- share (vertices + regular)
          sides <- share (select regular code p)
          radius <- share (select regular 0 q)
          given <- forM (zip [0 .. maxHullCorners - 1] (regularCorners code (baSize b))) $ \(k, (ra, rb)) -> do
            a <- readArray cornersIn (fromIntegral (2 * k))
            c <- readArray cornersIn (fromIntegral (2 * k + 1))
            pure (select regular ra a, select regular rb c)
          oriented <- mapM share2 (orientCorners sides given)
          own <- mapM share2 (centredCorners sides radius oriented)
          size <- share (select vertices (polygonReach sides radius own) (hullSize code p q (baSize b)))
          corners <- share (select convex sides (hullCorners code p))
          let outline theta = select vertices (verticesOutline sides radius own theta / size) (outlineGiven code p q theta)
          -- the outline's mass integrals (a thousand samples) only for a
          -- body without corners, whose mass they give (run for every body
          -- and then not chosen, they made loading a scene of 820 boxes
          -- take 1.7 s in the page), and in a function of their own: the
          -- page's addBody is too big for V8 to optimise, and the loop ran
          -- in its interpreter (3000 circles took 6 s to load). They leave
          -- the mass and inertia in the body's slots, read back below.
          writeSlot w i InvMass 0
          writeSlot w i InvInertia 0
          whenPositive (minF (0.5 - convex) (1.5 - corners)) $
            subroutine "outlineMass" [code, p, q, size, baDensity b, count] $ \case
              [code', p', q', size', density, at] -> do
                (mo, io) <- massIntegrals (outlineGiven code' p' q') size' density
                writeSlot w (toIndex at) InvMass mo
                writeSlot w (toIndex at) InvInertia io
              _ -> error "outlineMass: six arguments"
          mOutline <- readSlot w i InvMass
          iOutline <- readSlot w i InvInertia
          let (mHull, iHull) = hullMass code p q (baDensity b)
              (mPolygon, iPolygon) = polygonMass sides radius own (baDensity b)
          m <- share (select convex mPolygon (select (corners - 1.5) mHull mOutline))
          inertia <- share (select convex iPolygon (select (corners - 1.5) iHull iOutline))
          writeSlot w i Angle (baAngle b)
          writeSlot w i Omega (movable * baOmega b)
          writeSlot w i InvMass (select movable (select m (recip m) 0) 0)
          writeSlot w i InvInertia (select movable (select inertia (recip inertia) 0) 0)
          writeSlot w i Size (select convex (polygonThickness sides radius own) (hullThickness code p q size))
          -- awake (a saved scene's sleeping body is put to sleep after: 'setSleeping')
          writeSlot w i Asleep 0
          writeSlot w i SleepTimer 0
          writeSlot w i Island (-1)
          writeSlot w i BodyFriction (maxF (-1) (baFriction b))
          writeSlot w i BodyRestitution (maxF (-1) (baRestitution b))
          writeSlot w i Corners corners
          let hull = fromIntegral hullStride * i
          writeArray (wHull w) hull (select convex radius (hullRounding code q size))
          forM_ (zip [0 .. maxHullCorners - 1] own) $ \(k, (ownA, ownB)) -> do
            let (a, c) = hullCorner code p q k
            writeArray (wHull w) (hull + hullLocalAt (fromIntegral k)) (select convex ownA a)
            writeArray (wHull w) (hull + hullLocalAt (fromIntegral k) + 1) (select convex ownB c)
          outlineRadiiInto l outline w i size
          let nd = polyDirections (polygon l)
          reach <- newRef 0
          forEach (fromIntegral nd) $ \d -> do
            r <- readArray (wRadii w) (fromIntegral nd * i + d)
            modifyRef reach (maxF r)
          -- (a box's corners between the outline's directions reach farther)
          readRef reach >>= writeSlot w i BoundRadius . (\r -> select (corners - 1.5) (maxF r size) r)
          writeArray (wBodyPrev w) (2 * i + 1) 0
          writeMeta w BodyCount (count + 1)
          writeMeta w LastAdded count
          polygoniseInline sp l w i)
      (writeMeta w LastAdded (-2)))
    (writeMeta w LastAdded (-1))

-- | 1 when a restored body's frame fits the surface at its position @p@
-- (where the surface's unit normal is @surfaceNormal@), else 0: @p@ on the
-- surface as a step leaves it ('onSurfaceTolerance'), and, within
-- 'frameTolerance', the normal the surface's, the axis a unit tangent and
-- the velocity tangent. A saved scene's bodies fit; one edited by hand
-- (moved without its axis and normal) does not.
frameFits :: Field a => Metric -> ScalarFn -> V3 a -> V3 a -> BodyArgs a -> a
frameFits metric f p surfaceNormal b =
  let k = constant frameTolerance
      n = baNormal b
      axis = baAxis b
      v = baVel b
  in allPositive
       [ constant onSurfaceTolerance - abs (evalFn f p)
       , k - norm (n ^-^ surfaceNormal)
       , k - abs (normIn metric axis - 1)
       , k - abs (inner metric axis n)
       , k * (1 + normIn metric v) - abs (inner metric v n) ]

-- | Why a saved body cannot be restored (what both engines say when
-- 'addBodyWith' sets 'LastAdded' to −2).
frameMisfit :: String
frameMisfit = "the saved axis and normal do not fit the surface at p (a saved body lies on the surface, its normal the surface's, its axis a unit tangent and its velocity tangent; to move a body, give p without axis and normal)"

-- | How far a restored body's unit vectors may be from unit, tangent and
-- normal: far above the rounding of a saved scene's numbers, far below any
-- frame of another point.
frameTolerance :: Double
frameTolerance = 1e-6

-- | 1 when every condition is positive, else 0 (NaN counts as not positive).
allPositive :: Field a => [a] -> a
allPositive = foldr (\c rest -> select c rest 0) 1

-- | Remove body @i@: the last body takes its place (so indices above @i@
-- are stable but the last one's becomes @i@). Warm starting is forgotten
-- for one step, and so are the last step's contacts; a mouse joint on the
-- removed body is released; the bodies near it wake.
removeBody :: Imp m => Space -> Layout -> WorldArrays (Array m) -> Index m -> m ()
removeBody sp l w i = do
  count <- readMeta w BodyCount
  whenPositive (minF (toScalar i + 0.5) (count - toScalar i - 0.5)) $ do
    let lastI = toIndex (count - 1)
        move arr (k :: Int) = forEach (fromIntegral k) $ \o ->
          readArray arr (fromIntegral k * lastI + o) >>= writeArray arr (fromIntegral k * i + o)
    -- what rested on the body wakes, and so does the body's own island
    -- (so that no sleeping body names the index that goes); the last
    -- body's island, if asleep, is named by its new index
    wakeNear (spaceMetric sp) w i
    wakeMarked w
    forEach (toIndex count) $ \k -> do
      label <- readSlot w k Island
      whenPositive (0.5 - abs (label - toScalar lastI)) (writeSlot w k Island (toScalar i))
    move (wPos w) 3
    move (wVel w) 3
    move (wAxis w) 3
    move (wNormal w) 3
    move (wScalars w) scalarSlots
    move (wRadii w) (polyDirections (polygon l))
    move (wVerts w) (3 * verticesPerBody l)
    move (wOutline w) (3 * polyDirections (polygon l))
    move (wHull w) hullStride
    writeMeta w BodyCount (count - 1)
    forgetBodyJoints w i lastI
    forEach (toIndex count) $ \k -> writeArray (wBodyPrev w) (2 * k + 1) 0
    -- the last step's contacts name bodies by the old indices: none now
    writeMeta w ContactCount 0
    grabbed <- readMouse w MBody
    active <- readMouse w MActive
    whenPositive (minF active (0.5 - abs (grabbed - toScalar i))) (writeMouse w MActive 0)
    whenPositive (minF active (0.5 - abs (grabbed - (count - 1)))) (writeMouse w MBody (toScalar i))

-- | Share both numbers of a pair.
share2 :: Imp m => (Scalar m, Scalar m) -> m (Scalar m, Scalar m)
share2 (a, b) = (,) <$> share a <*> share b
