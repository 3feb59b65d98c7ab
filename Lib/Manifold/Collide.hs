{-# OPTIONS_GHC -fllvm #-}
{-# LANGUAGE FlexibleContexts #-}
-- Built with LLVM (as the compiled steps are): the generic native step's
-- narrow phase, one large loop nest, took a third longer from GHC's own code
-- generator (manifold bench --generic, settled piles).

-- | Finding contacts (paper §2.5, §2.6, §3.4, §4.3): a uniform grid over R³
-- for the broad phase, the geodesic polygons for the narrow phase, boundary
-- contacts where an outline leaves @b(p) >= 0@, and, on quotient spaces,
-- contacts with the other bodies' images and a body's own image.
--
-- A body's outline vertex @q@ is inside another body @Y@ when, in Y's tangent
-- frame, it lies inside the star-shaped outline that Y's polygon makes there;
-- the depth is its distance to the outline edge its direction crosses, and
-- the direction that resolves the overlap over the shortest distance is that
-- edge's outward normal. Of a touching pair, the body whose vertex goes
-- deepest into the other is the one pushed out: that vertex's edge is the
-- reference edge, and the two extreme vertices inside, along the edge,
-- clipped where the reference body ends, become the pair's two contact
-- points, so that a box resting on a box has two. Two circles touch as
-- geodesic discs: from the distance between their centres ('circles');
-- two bodies with hulls (circles, boxes, capsules: "Manifold.Hull") by
-- their contact manifold in the tangent plane between them ('hulls').
module Manifold.Collide
  ( collide
  , buildGrid
  , pointInBody
    -- * Contact keys
  , KeyGroup (..)
  , keysPerGroup
  , keysPerBody
  , imageKeyGroup
  ) where

import Control.Monad (foldM_, forM_, unless, when)
import Linear.Metric (dot)
import Linear.V2 (V2 (..))
import Linear.V3 (V3 (..), cross)
import Linear.Vector ((*^), (^-^), (^+^), negated)

import Manifold.Body (PolygonParams (..), Sectors, sectors, directionSector, vertexIndex)
import Manifold.ContactManifold
import Manifold.Field
import Manifold.Joint (listPartners, notJoined)
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.Metric
import Manifold.Surface (geodesicStep, normalOf, tangentProjection)
import Manifold.World

-- | Sort the bodies into the buckets of a spatial hash of grid cells (a
-- counting sort: no allocation). Cells are at least as wide as the largest
-- body no larger than four times the bodies' mean bounding radius, so a
-- body's contacts with those are all in the 27 cells around its own. A
-- larger body (a ground slab, a wall, a boulder among pebbles) is kept out
-- of the grid, listed at the end of 'wItems' (the last of its 'Capacity'
-- slots first, 'LargeCount' of them): every moving body in the grid checks
-- that list as well, and a moving body apart checks every still body of
-- the grid and the others apart. Cells as wide as a slab put a pile's
-- every body in a handful of cells, and each body's neighbours became the
-- pile. With more than 'maxLargeMovable' movable bodies above the mean's
-- four times, the cells are as wide as the largest movable body and only
-- larger static bodies are kept apart. The
-- cells are hashed into eight buckets per body, so clearing and scanning
-- the table costs in proportion to the bodies, whatever the space's size.
-- Each body remembers its exact cell, so bodies of a different cell that
-- share the bucket are skipped. Eight, not two: of the 27 cells around a
-- body on a surface most are empty, and their buckets hold other cells'
-- bodies, which the scan reads and skips: on the benchmark's settled scenes
-- 10 to 64 such bodies per body with two buckets (the most in the
-- rectangle's piles, whose flat lattice of cells collides in the linear
-- hash), 0.2 to 8 with eight.
buildGrid :: Imp m => Space -> WorldArrays (Array m) -> m ()
buildGrid sp w = do
  -- decided once, not at every body (and applied in line: as a function
  -- value the generic step boxed every point it passed)
  let onPlane = planeAlongY sp
      metric = spaceMetric sp
  count <- readMeta w BodyCount
  let n = toIndex count
      bound = constant (spaceBounds sp)
  -- the cells are sized by the bodies no larger than four times the
  -- bodies' mean bounding radius, unless more than 'maxLargeMovable'
  -- movable bodies are larger than that (then by every movable body)
  sumR <- newRef 0
  forEach n $ \i -> readSlot w i BoundRadius >>= \r -> modifyRef sumR (+ r)
  limit <- share . (* 4) . (/ maxF 1 count) =<< readRef sumR
  maxSmall <- newRef 0
  maxAll <- newRef 0
  over <- newRef 0
  forEach n $ \i -> do
    r <- readSlot w i BoundRadius
    movable <- readSlot w i InvMass
    whenPositive movable (modifyRef maxAll (maxF r))
    ifPositive (r - limit) (whenPositive movable (modifyRef over (+ 1))) (modifyRef maxSmall (maxF r))
  tooMany <- (\k -> k - fromIntegral maxLargeMovable - 0.5) <$> readRef over
  rmax <- share =<< (select tooMany <$> readRef maxAll <*> readRef maxSmall)
  -- at most 2^16 cells across the bounds, so that a cell's key is exact
  cell <- share (maxF (2 * rmax) (2 * bound / cellsAcross))
  buckets <- share (clampF 1 (fromIntegral maxBuckets) (8 * count))
  writeMeta w GridBuckets buckets
  writeMeta w CellSize cell
  writeMeta w LargeCount 0
  let starts b = toIndex buckets + b
      -- a body wider than the cells: listed apart (its cell, −1, names
      -- none)
      inGrid i body = do
        r <- readSlot w i BoundRadius
        ifPositive (r - rmax)
          (do writeArray (wCellOf w) i (-1)
              k <- readMeta w LargeCount
              capacity <- readMeta w Capacity
              writeArray (wItems w) (toIndex (capacity - 1 - k)) (toScalar i)
              writeMeta w LargeCount (k + 1))
          body
  forEach (toIndex buckets) $ \b -> writeArray (wGrid w) b 0
  forEach n $ \i -> inGrid i $ do
    p <- spaceGridPoint onPlane metric <$> read3 (wPos w) i
    let V3 cx cy cz = fmap (cellCoord cell) p
    writeArray (wCellOf w) i (cellKey cx cy cz)
    b <- share (bucketOf buckets cx cy cz)
    k <- readArray (wGrid w) (toIndex b)
    writeArray (wGrid w) (toIndex b) (k + 1)
  running <- newRef 0
  forEach (toIndex buckets) $ \b -> do
    k <- readArray (wGrid w) b
    s <- readRef running
    writeArray (wGrid w) (starts b) s
    writeArray (wGrid w) b s -- the fill cursor; it ends at the bucket's end
    writeRef running (s + k)
  forEach n $ \i -> do
    key <- readArray (wCellOf w) i
    whenPositive (key + 0.5) $ do
      p <- spaceGridPoint onPlane metric <$> read3 (wPos w) i
      let V3 cx cy cz = fmap (cellCoord cell) p
      b <- share (bucketOf buckets cx cy cz)
      k <- readArray (wGrid w) (toIndex b)
      writeArray (wItems w) (toIndex k) (toScalar i)
      writeArray (wGrid w) (toIndex b) (k + 1)

cellsAcross :: Field a => a
cellsAcross = 65536

-- | The most movable bodies kept out of the grid for being larger than
-- four times the mean: each of them checks every body that does not move.
maxLargeMovable :: Int
maxLargeMovable = 16

cellCoord :: Field a => a -> a -> a
{-# INLINE cellCoord #-}
cellCoord cell x = floorF (x / cell)

-- | A cell's identity as one exact number (coordinates within ±2^16).
cellKey :: Field a => a -> a -> a -> a
{-# INLINE cellKey #-}
cellKey cx cy cz = ((cx + 131072) * 262144 + (cy + 131072)) * 262144 + (cz + 131072)

-- | The bucket of a cell: a hash of its coordinates modulo the table size
-- (every product stays far below 2^53, so it is exact).
bucketOf :: Field a => a -> a -> a -> a -> a
{-# INLINE bucketOf #-}
bucketOf buckets cx cy cz =
  let h = cx * 73856093 + cy * 19349663 + cz * 83492791
  in h - buckets * floorF (h / buckets)

-- | A point's place in the broad phase's grid: 'gridPoint', and on a
-- plane @y = c@ (given: 'planeAlongY', decided once, not at every point)
-- the point with @y@ set to 0, so that every body's cell is in one layer
-- whatever the rounding of its @y@.
spaceGridPoint :: Field a => Bool -> Metric -> V3 a -> V3 a
{-# INLINE spaceGridPoint #-}
spaceGridPoint onPlane metric p@(V3 x _ z)
  | onPlane = V3 x 0 z
  | otherwise = gridPoint metric p

-- | Whether the space is a plane @y = c@ (its field's gradient a constant
-- along @y@: the plane, the rectangle, the flat torus and Klein bottle).
planeAlongY :: Space -> Bool
planeAlongY sp = case constantGradient (spaceField sp) of
  Just (V3 0 gy 0) -> gy /= 0
  _ -> False

-- | Run @visit j@ for every body @j@ in the 27 cells around point @p@
-- (the cells of its 'spaceGridPoint'); where every grid point has @y@ 0
-- (on a plane @y = c@, and in Minkowski space, whose grid points are the
-- Poincaré disc's), in the 9 cells of that one layer, in the same order
-- (the other 18 are empty: their scan, two reads of the table and a bucket
-- of other cells' bodies each, was half of the broad phase's time on the
-- rectangle's piles).
neighbours :: Imp m => Bool -> Metric -> WorldArrays (Array m) -> V3 (Scalar m) -> (Index m -> m ()) -> m ()
{-# INLINE neighbours #-}
neighbours onPlane metric w p visit = do
  buckets <- readMeta w GridBuckets
  cell <- readMeta w CellSize
  V3 cx cy cz <- share3 (fmap (cellCoord cell) (spaceGridPoint onPlane metric p))
  -- the cells of layer dy (0 to 2) in column dx; the branch on the layers
  -- outside the loops (a function choosing between them made the generic
  -- step allocate a closure a column)
  let column dx dy = forEach 3 $ \dz -> cellAt dx dy dz
      {-# INLINE column #-}
      cellAt dx dy dz = do
        nx <- share (cx + toScalar dx - 1)
        ny <- share (cy + toScalar dy - 1)
        nz <- share (cz + toScalar dz - 1)
        key <- share (cellKey nx ny nz)
        b <- share (bucketOf buckets nx ny nz)
        end <- readArray (wGrid w) (toIndex b)
        start <- readArray (wGrid w) (toIndex buckets + toIndex b)
        forLoop (toIndex start) (toIndex end) $ \s -> do
          j <- readArray (wItems w) s
          cj <- readArray (wCellOf w) (toIndex j)
          whenPositive (0.5 - abs (cj - key)) (visit (toIndex j))
      {-# INLINE cellAt #-}
  if onPlane || metric == Minkowski
    then forEach 3 $ \dx -> column dx 1
    else forEach 3 $ \dx -> forEach 3 $ \dy -> column dx dy

-- | Whether a point (near the surface) is inside body @Y@'s polygon: the
-- depth (positive inside) and the outward direction of the edge it is
-- nearest along its direction from Y's centre. Points far off Y's tangent
-- plane (on another sheet of the surface) are never inside.
pointInBody :: Imp m => Metric -> Layout -> WorldArrays (Array m) -> Index m -> BodyFrame (Scalar m) -> V3 (Scalar m) -> m (Scalar m, V3 (Scalar m))
{-# INLINE pointInBody #-}
pointInBody metric l w j y q = do
  turn <- bodyTurn w j
  e <- edgeFacing metric l (sectors (polyDirections (polygon l))) w j y turn q
  pure (efDepth e, efNormal e)

-- | The cosine and sine of body @j@'s angle as its outline was last walked,
-- which turn a point into its own directions. Read once before a loop over
-- points: read in the loop, GHC floated the read's bounds check out of it
-- as a lazy value, allocated at every pair.
bodyTurn :: Imp m => WorldArrays (Array m) -> Index m -> m (Scalar m, Scalar m)
{-# INLINE bodyTurn #-}
bodyTurn w j = (,) <$> readSlot w j TurnCos <*> readSlot w j TurnSin

-- | The outline edge of body Y that the direction from Y's centre to a
-- point crosses, seen from the point.
data EdgeFacing s = EdgeFacing
  { efDepth :: s -- ^ how far the point is inside, across this edge (negative outside or off the sheet)
  , efNormal :: V3 s -- ^ the edge's outward normal, in Y's tangent plane
  , efVertex :: V3 s -- ^ one end of the edge
  }

edgeFacing :: Imp m => Metric -> Layout -> Sectors -> WorldArrays (Array m) -> Index m -> BodyFrame (Scalar m) -> (Scalar m, Scalar m)
           -> V3 (Scalar m) -> m (EdgeFacing (Scalar m))
{-# INLINE edgeFacing #-}
edgeFacing metric l sec w j y (c0, s0) q = do
  let nd = polyDirections (polygon l)
      c = bfCentre y
      d = q ^-^ c
  qx <- share (inner metric d (bfU y))
  qy <- share (inner metric d (bfW y))
  h <- share (inner metric d (bfNormal y))
  -- the point turned back by the body's angle: in its own directions
  k <- share (directionSector sec (qx * c0 + qy * s0) (qy * c0 - qx * s0))
  let k1 = select (k - fromIntegral nd + 1.5) 0 (k + 1)
  o0 <- outlineVertex l w j (toIndex k)
  o1 <- outlineVertex l w j (toIndex k1)
  let local o = let e = o ^-^ c in (inner metric e (bfU y), inner metric e (bfW y))
      (ax, ay) = local o0
      (bx, by) = local o1
  ex <- share (bx - ax)
  ey <- share (by - ay)
  len <- share (sqrt (ex * ex + ey * ey))
  let crossE = ex * (qy - ay) - ey * (qx - ax)
      depth = select len (crossE / len) (-1)
      -- off the tangent plane by more than the body's size: another sheet
      onSheet = bfSize y - abs h
      depth' = select onSheet depth (-1)
      normal2 = select len (recip len) 0
      m = (ey * normal2) *^ bfU y ^+^ (negate ex * normal2) *^ bfW y
  depthS <- share depth'
  m' <- share3 m
  pure (EdgeFacing depthS m' o0)

-- | A contact row's key names the contact, so that the next step's row
-- for the same contact starts from its impulses (warm starting): keys come
-- in groups of 'keysPerGroup', one key for each point of a contact, and
-- each body's rows have 'keysPerBody' keys of their own. A body's own
-- groups are its boundary contacts and its self-contact; its contacts with
-- body @j@ are @(j + 1) · keysPerBody@ plus the group of the image they meet
-- through (group 0 for none, 'imageKeyGroup' for the quotient's images).
data KeyGroup
  = PairKey -- ^ a pair's contacts, not through an image
  | Unused -- ^ (its keys name no contact)
  | BoundaryKey
  | SelfKey
  | FirstImageKey -- ^ the first image's; the others follow it
  deriving (Show, Eq, Enum, Bounded)

-- | The keys of a group: one for each corner of either hull a point of a
-- contact may be at ('cornerKey').
keysPerGroup :: Int
keysPerGroup = keysPerManifold

-- | The keys of a body's own on a space of this quotient: sixteen groups,
-- or 64 where the images are more than twelve (the Bolza surface's 48).
keysPerBody :: Quotient -> Int
keysPerBody quo
  | fromEnum FirstImageKey + length (quotientImages quo) <= 16 = 16 * keysPerGroup
  | otherwise = 64 * keysPerGroup

-- | The key group of a pair's contacts through the quotient's @k@-th image.
imageKeyGroup :: Int -> Int
imageKeyGroup k = fromEnum FirstImageKey + k

-- | A contact row pair into the contact array: body @a@ at point @ra@ is
-- pushed along @dirA@, body @b@ (if @b >= 0@) at @rb@ against @dirB@.
-- @coupling@ 0 keeps only body a's linear normal row (no friction, no turn).
-- @carry@ takes a direction at body a to body b's side (the linear part of
-- the image's isometry when b meets a's image; the identity otherwise), so
-- that both friction rows act along the same direction.
emitContact :: Imp m => Metric -> WorldArrays (Array m) -> Index m -> Scalar m -> Index m -> Scalar m
            -> V3 (Scalar m) -> V3 (Scalar m) -> V3 (Scalar m) -> V3 (Scalar m) -> Scalar m -> Scalar m -> Scalar m
            -> (V3 (Scalar m) -> V3 (Scalar m)) -> m ()
emitContact metric w owner key a b ra dirA rb dirB depth selfScale coupling carry = do
  count <- readMeta w ContactCount
  cap <- readMeta w Capacity -- the arrays' capacity is the caller's, not the layout's
  ifPositive (fromIntegral contactsPerBody * maxF 1 cap - count - 0.5)
    (do let c = toIndex count
        writeMeta w ContactCount (count + 1)
        fa <- bodyFrame metric w a
        let ta = perpendicular metric (bfNormal fa) dirA
            rA = ra ^-^ bfCentre fa
        writeContact w c CA (toScalar a)
        writeContact w c CB b
        writeContact w c COwner (toScalar owner)
        writeContact w c CKey key
        writeContact3 w c JaX (tangentProjection metric (bfNormal fa) dirA)
        writeContact w c JaW (coupling * ((rA `cross` dirA) `dot` bfNormal fa))
        writeContact3 w c TaX (coupling *^ tangentProjection metric (bfNormal fa) ta)
        writeContact w c TaW (coupling * ((rA `cross` ta) `dot` bfNormal fa))
        writeContact w c CDepth depth
        writeContact w c CSelfScale selfScale
        writeContact3 w c PointX ra
        mapM_ (\f -> writeContact w c f 0) [CKept .. CTurnB]
        ifPositive (b + 0.5)
          (do fb <- bodyFrame metric w (toIndex b)
              let tb = carry ta
                  rB = rb ^-^ bfCentre fb
              writeContact3 w c JbX (tangentProjection metric (bfNormal fb) dirB)
              writeContact w c JbW ((rB `cross` dirB) `dot` bfNormal fb)
              writeContact3 w c TbX (tangentProjection metric (bfNormal fb) tb)
              writeContact w c TbW ((rB `cross` tb) `dot` bfNormal fb))
          (do writeContact3 w c JbX (V3 0 0 0)
              writeContact w c JbW 0
              writeContact3 w c TbX (V3 0 0 0)
              writeContact w c TbW 0))
    (readMeta w DroppedContacts >>= writeMeta w DroppedContacts . (+ 1))

-- | The contact rows of a pair (body @owner@ and body @other@, or −1 for
-- the space's boundary) whose keys are the group from @keyBase@: the
-- last step's, kept, when the pair has hardly moved since they were found
-- and the 'KeepContacts' switch is on; otherwise found anew by @find@
-- (and marked to be kept by the next step).
--
-- Kept, a row stays where it was found, in the bodies' frames as they
-- were then: its points, normal and rows as the sub-steps use them, its
-- depth updated from how far the bodies have since moved along its normal
-- row (as each sub-step updates it). Found anew every step, the points
-- move with every lean of a stack (clipped against its bodies as they
-- lean), and a tall stack of soft contacts leans further each step until
-- it falls; kept, it is a set of springs at fixed points and stands
-- (docs/decisions/kept-contacts.md). Box2D v3's contact recycling keeps a
-- manifold the same way, within the bounds below.
--
-- A pair has hardly moved while its relative motion since its rows were
-- found (body a's motion less body b's, summed over the steps), with its
-- larger bounding radius times the largest of the bodies' turns and its
-- relative turn, is under 'keptDrift' of its smaller bounding radius: as
-- Box2D bounds it, but for each body's own turn, which Box2D bounds by
-- 11.5° alone (its anchors turn with the bodies; the rows kept here do
-- not), and for the turn of the surface under each body (on a curved
-- surface a kept row leaves the tangent plane as its body moves on).
-- Every row of the group must be keepable (a row remembered from a scene
-- without its kept numbers is not) and still near its owner: a body
-- wrapped into the fundamental domain has jumped away from its rows.
keepOr :: Imp m => Metric -> WorldArrays (Array m) -> Index m -> Scalar m -> Scalar m -> m () -> m ()
{-# INLINE keepOr #-}
keepOr metric w owner other keyBase find = do
  before <- readMeta w KeptRows
  -- A subroutine: inlined at both its call sites, the collision phase
  -- outgrew what V8 optimises on the flat torus, with its eight images.
  -- Its pair goes in the narrow phase's scratch, which it reads before
  -- the pair's narrow phase uses it: as the subroutine's arguments, the
  -- compiled native step boxed them (GHC passes a call of some thirty
  -- arguments boxed), 100 KB a step on a settled pile of 300.
  writeArray (wProbe w) 0 (toScalar owner)
  writeArray (wProbe w) 1 other
  writeArray (wProbe w) 2 keyBase
  subroutine "keepContacts" [] $ \_ -> do
    owner' <- readArray (wProbe w) 0
    other' <- readArray (wProbe w) 1
    keyBase' <- readArray (wProbe w) 2
    keepRows metric w (toIndex owner') other' keyBase'
  after <- readMeta w KeptRows
  whenPositive (0.5 - (after - before)) $ do
    first <- readMeta w ContactCount
    find
    end <- readMeta w ContactCount
    forLoop (toIndex first) (toIndex end) $ \c -> writeContact w c CKept 1

-- | 'keepOr''s test, and the rows kept when it passes ('KeptRows' counts
-- them).
keepRows :: Imp m => Metric -> WorldArrays (Array m) -> Index m -> Scalar m -> Scalar m -> m ()
{-# INLINE keepRows #-}
keepRows metric w owner other keyBase = do
  on <- readParam w KeepContacts
  start <- readArray (wBodyPrev w) (2 * owner)
  count <- readArray (wBodyPrev w) (2 * owner + 1)
  centre <- read3 (wPos w) owner
  reachA <- readSlot w owner BoundRadius
  reachB <- readSlot w (toIndex (maxF 0 other)) BoundRadius
  hasB <- share (other + 0.5)
  tolerance <- share (keptDrift * select hasB (minF reachA reachB) reachA)
  extent <- share (select hasB (maxF reachA reachB) reachA)
  let inGroup k act = do
        key <- readPrev w k PrevKey
        whenPositive (minF (key - keyBase + 0.5) (keyBase + fromIntegral keysPerGroup - 0.5 - key)) act
  rows <- newRef 0
  fine <- newRef (on - 0.5)
  forLoop (toIndex start) (toIndex (start + count)) $ \k -> inGroup k $ do
    modifyRef rows (+ 1)
    kept <- readPrev w k PrevKept
    a <- readPrev w k PrevA
    b <- readPrev w k PrevB
    normalA <- read3 (wNormal w) (toIndex a)
    normalB <- read3 (wNormal w) (toIndex (maxF 0 b))
    drift <- V3 <$> readPrev w k PrevDriftX <*> readPrev w k PrevDriftY <*> readPrev w k PrevDriftZ
    turnA <- readPrev w k PrevTurnA
    turnB <- readPrev w k PrevTurnB
    point <- V3 <$> readPrev w k PrevPointX <*> readPrev w k PrevPointY <*> readPrev w k PrevPointZ
    rowA <- V3 <$> readPrev w k PrevJaX <*> readPrev w k PrevJaY <*> readPrev w k PrevJaZ
    rowB <- V3 <$> readPrev w k PrevJbX <*> readPrev w k PrevJbY <*> readPrev w k PrevJbZ
    -- (the rows lie in the tangent planes the bodies had: how far they
    -- stick out of today's is how far the surface has turned under them)
    let tilted = maxF (abs (inner metric rowA normalA)) (select (b + 0.5) (abs (inner metric rowB normalB)) 0)
        turned = maxF (maxF (abs (turnA - turnB)) tilted) (maxF (abs turnA) (abs turnB))
        moved = normIn metric drift + extent * turned
        near = 4 * reachA * reachA - quadranceIn metric (point ^-^ centre)
    modifyRef fine (minF (minF (kept - 0.5) (minF (tolerance - moved) near)))
  n <- readRef rows
  ok <- readRef fine
  whenPositive (minF (n - 0.5) ok) $
    forLoop (toIndex start) (toIndex (start + count)) $ \k -> inGroup k (emitKept w k owner)

-- | How far a pair may drift while it keeps its contact rows, as a
-- fraction of its smaller bounding radius: Box2D v3's bound (ten linear
-- slops, 0.05 m, for its 1 m boxes, whose bounding radius is 0.71 m).
keptDrift :: Field a => a
keptDrift = 0.07

-- | Remembered row @k@ kept as this step's contact row of its owner.
emitKept :: Imp m => WorldArrays (Array m) -> Index m -> Index m -> m ()
{-# INLINE emitKept #-}
emitKept w k owner = do
  count <- readMeta w ContactCount
  cap <- readMeta w Capacity
  ifPositive (fromIntegral contactsPerBody * maxF 1 cap - count - 0.5)
    (do let c = toIndex count
        writeMeta w ContactCount (count + 1)
        readMeta w KeptRows >>= writeMeta w KeptRows . (+ 1)
        writeContact w c COwner (toScalar owner)
        readPrev w k PrevKey >>= writeContact w c CKey
        writeContact w c CSelfScale 1
        writeContact w c CKept 1
        forM_ keptFields $ \(cf, pf) -> readPrev w k pf >>= writeContact w c cf)
    (readMeta w DroppedContacts >>= writeMeta w DroppedContacts . (+ 1))

-- | Run the test only for a point within body @y@'s bounding radius of its
-- centre (no point farther out can be inside it).
whenNear :: Imp m => Metric -> BodyFrame (Scalar m) -> V3 (Scalar m) -> m () -> m ()
{-# INLINE whenNear #-}
whenNear metric fy q = whenPositive (bfSize fy * bfSize fy - quadranceIn metric (q ^-^ bfCentre fy))

-- | The contacts of a touching pair: body @x@, mapped by the isometry @g@
-- (the identity, or the image of @x@ that @y@ meets), and body @y@; up to
-- two rows in all.
--
-- Both ways round are probed (x's outline vertices inside y, and y's inside
-- x); the way whose deepest vertex goes deeper (by a tenth, so that the
-- choice does not flicker between nearly equal ways; x's vertices in y when
-- equal) gives the contact: the edge its deepest vertex crosses is the
-- reference edge, whose outward normal pushes both contact points, and of
-- the vertices inside, the two extremes along that edge are the points,
-- each as deep as it lies behind the edge's line, and each moved along
-- the mover's outline edge to where the reference body ends when that
-- edge touches beyond it (a box overhanging the corner of the one below). One normal for both
-- points keeps a box on a box level: a vertex near a corner, measured
-- across the side edge it happens to face, would push the box sideways.
-- Both ways' rows (four for a box on a box, which mostly say the same
-- thing twice) made the solver's work grow faster than the bodies.
--
-- Printed as a JavaScript subroutine for each kind of pair (two circles,
-- two hulls, the others), called for every pair and image (the image by
-- its index in the probe array's table, 'imageTableAt', 0 for the
-- identity): inlined at each of its call sites, the collision phase
-- outgrew what V8 optimises on the quotient spaces, and one subroutine of
-- all three kinds, taking any isometry, outgrew it too.
pairContacts :: Imp m => Metric -> Layout -> Sectors -> WorldArrays (Array m) -> Scalar m
             -> Index m -> Index m -> Scalar m -> m ()
-- (Inlined natively, where a subroutine is its body: called, the generic
-- step built its arguments' list for every candidate pair.)
{-# INLINE pairContacts #-}
pairContacts metric l sec w keyBase x y image = do
  cornersX <- readSlot w x Corners
  cornersY <- readSlot w y Corners
  let kind name contacts = subroutine name [keyBase, toScalar x, toScalar y, image] $ \case
        [keyBase', x', y', image'] -> do
          g <- readImage l w image'
          margin <- speculativeMargin w (toIndex x') (toIndex y')
          contacts keyBase' (toIndex x') (toIndex y') g margin
        _ -> error (name ++ ": four arguments")
  -- two circles: from the distance between their centres; two hulls
  -- (a circle, a box, a capsule): by their manifold in the plane between
  -- them; any other pair by the sampled outlines
  ifPositive (0.5 - maxF (abs (cornersX - 1)) (abs (cornersY - 1)))
    (kind "pairCircles" (circles metric w))
    (ifPositive (minF cornersX cornersY - 0.5)
      (kind "pairHulls" (hulls metric w))
      (kind "pairOutlines" (outlines metric l sec w)))

-- | The image of this index in the probe array's table ('imageTableAt').
readImage :: Imp m => Layout -> WorldArrays (Array m) -> Scalar m -> m (IsometryOf (Scalar m))
{-# INLINE readImage #-}
readImage l w image = do
  let at = fromIntegral (imageTableAt l) + fromIntegral imageStride * toIndex image
  isoFromCoefficients <$> mapM (\c -> readArray (wProbe w) (at + fromIntegral c)) [0 .. 11 :: Int]

-- | The table of the quotient's isometries ('imageTableAt'): the identity,
-- then each image with whether a body may meet itself through it.
writeImageTable :: Imp m => Space -> Layout -> WorldArrays (Array m) -> m ()
writeImageTable sp l w =
  forM_ (zip [0 :: Int ..] ((identityIso, False) : [ (g, selfImage quo g) | g <- quotientImages quo ])) $ \(k, (g, self)) ->
    forM_ (zip [0 :: Int ..] (isoCoefficients g ++ [if self then 1 else 0])) $ \(c, v) ->
      writeArray (wProbe w) (fromIntegral (imageTableAt l + imageStride * k + c)) (constant v)
  where quo = spaceQuotient sp

-- | The contact of two circles (body @x@ mapped by the isometry @g@, and
-- body @y@): one point, midway between their rims on the line between
-- their centres, as deep as their radii overlap the geodesic distance
-- between the centres. That distance is the chord's, lengthened by the
-- surface's bend along it: a curve of normal curvature κ is longer than
-- its chord @c@ by @κ²c³/24@, and κc² is the normals' turn along the
-- chord, @⟨n_y − n_x, c⟩@ (negative squares in Minkowski space, whose
-- normals are time-like: there the geodesic is the shorter). On the unit
-- sphere this is @2 asin (c/2)@ to within @3c⁵/640@: 2.4e-4 of a radius
-- for two circles of 0.2, 1.2e-7 for the sandbox's 0.03 (the chord alone
-- falls short by @c³/24@: 1.3e-2 and 3e-4).
circles :: Imp m => Metric -> WorldArrays (Array m) -> Scalar m -> Index m -> Index m -> IsometryOf (Scalar m) -> Scalar m -> m ()
{-# INLINE circles #-}
circles metric w keyBase x y g margin = do
  cx <- read3 (wPos w) x
  nx <- read3 (wNormal w) x
  fy <- bodyFrame metric w y
  rx <- readSlot w x Size
  ry <- readSlot w y Size
  let image = applyIso g
      linear = applyLinear g
      back = applyLinear (inverseIso metric g)
  gx <- share3 (image cx)
  gn <- share3 (linear nx)
  d <- share3 (bfCentre fy ^-^ gx)
  chord <- share (normIn metric d)
  bend <- share (inner metric (bfNormal fy ^-^ gn) d)
  arc <- share (chord + select chord (inner metric (bfNormal fy) (bfNormal fy) * bend * bend / (24 * chord)) 0)
  depth <- share (rx + ry - arc)
  whenPositive (depth + margin) $ do
    u <- share3 (select chord (recip chord) 0 *^ d)
    -- pushed along the line between the centres as the tangent plane
    -- midway between the bodies sees it (as 'outlines' pushes)
    mid <- share3 (normalizeIn metric (gn ^+^ bfNormal fy))
    m0 <- share3 (normalizeIn metric (tangentProjection metric mid (negated u)))
    rb <- share3 (gx ^+^ (rx - 0.5 * depth) *^ u)
    ra <- share3 (back (rb ^-^ isoShift g))
    emitContact metric w x keyBase x (toScalar y) ra (back m0) rb m0 depth 1 1 linear

-- | The contacts of two hulls (body @x@ mapped by the isometry @g@, and
-- body @y@), at most two points, by 'collideHulls' in the tangent
-- plane midway between the bodies: its origin midway between their
-- centres, its first axis along the line from x's to y's, its normal the
-- mean of theirs. Each body's corners, walked onto the surface
-- ('walkCorners'), are projected onto that plane; an image that mirrors x
-- reverses its corners' order, which is read backwards so that they stay
-- counter-clockwise. Each point pushes along the manifold's normal (in
-- that plane, so that each body's row is the other's mirror, as
-- 'outlines' pushes); its key names the corner it is at ('cornerKey'; a
-- mirroring image's corners by their places as read).
hulls :: Imp m => Metric -> WorldArrays (Array m) -> Scalar m -> Index m -> Index m -> IsometryOf (Scalar m) -> Scalar m -> m ()
{-# INLINE hulls #-}
hulls metric w keyBase x y g margin = do
  cx <- read3 (wPos w) x
  nx <- read3 (wNormal w) x
  fy <- bodyFrame metric w y
  let image = applyIso g
      linear = applyLinear g
      back = applyLinear (inverseIso metric g)
  gx <- share3 (image cx)
  gn <- share3 (linear nx)
  mid <- share3 (normalizeIn metric (gn ^+^ bfNormal fy))
  origin <- share3 (0.5 *^ (gx ^+^ bfCentre fy))
  along <- share3 (tangentProjection metric mid (bfCentre fy ^-^ gx))
  len <- share (normIn metric along)
  -- (coincident centres: y's axis will do)
  u <- share3 (select len <$> (recip (maxF len 1e-300) *^ along) <*> normalizeIn metric (tangentProjection metric mid (bfU fy)))
  v <- share3 (perpendicular metric mid u)
  mirrored <- share (determinant (isoLinear g))
  let scratch = wProbe w
      half = fromIntegral (2 * maxHullCorners)
      -- a body's corners in the plane, then its edges' outward normals
      project slot body mapPoint reversed = do
        count <- readSlot w body Corners
        let base = fromIntegral hullStride * body
        forLoop 0 (toIndex count) $ \k -> do
          from <- share (select reversed (count - 1 - toScalar k) (toScalar k))
          q <- share3 . mapPoint =<< readAt3' (wHull w) (base + hullWorldAt (toIndex from))
          let d = q ^-^ origin
          writeArray scratch (slot + 2 * k) (inner metric d u)
          writeArray scratch (slot + 2 * k + 1) (inner metric d v)
        forLoop 0 (toIndex count) $ \k -> do
          k1 <- share (select (toScalar k + 1.5 - count) 0 (toScalar k + 1))
          ax <- readArray scratch (slot + 2 * k)
          ay <- readArray scratch (slot + 2 * k + 1)
          bx <- readArray scratch (slot + 2 * toIndex k1)
          by <- readArray scratch (slot + 2 * toIndex k1 + 1)
          ex <- share (bx - ax)
          ey <- share (by - ay)
          l <- share (sqrt (ex * ex + ey * ey))
          writeArray scratch (slot + half + 2 * k) (select l (ey / l) 0)
          writeArray scratch (slot + half + 2 * k + 1) (select l (negate ex / l) 0)
        radius <- readArray (wHull w) base
        pure (Hull count (point slot) (point (slot + half)) radius)
      point at k = V2 <$> readArray scratch (at + 2 * k) <*> readArray scratch (at + 2 * k + 1)
  hx <- project 0 x image (negate mirrored)
  hy <- project (2 * half) y id 0
  tolerance <- share (0.025 * margin)
  manifold <- collideHulls margin tolerance hx hy
  let V2 mx my = cmNormal manifold
  -- x is pushed away from y
  push <- share3 (normalizeIn metric (negated (mx *^ u ^+^ my *^ v)))
  forM_ (zip [0 :: Int ..] [cmFirst manifold, cmSecond manifold]) $ \(k, pt) ->
    whenPositive (cmCount manifold - fromIntegral k - 0.5) $ do
      let V2 px py = mpPoint pt
      rb <- share3 (origin ^+^ px *^ u ^+^ py *^ v)
      ra <- share3 (back (rb ^-^ isoShift g))
      emitContact metric w x (keyBase + mpKey pt) x (toScalar y) ra (back push) rb push (negate (mpSeparation pt)) 1 1 linear
  where
    readAt3' a o = V3 <$> readArray a o <*> readArray a (o + 1) <*> readArray a (o + 2)

-- | The contacts of a pair that is not two hulls, from their sampled
-- outlines ('pairContacts').
outlines :: Imp m => Metric -> Layout -> Sectors -> WorldArrays (Array m) -> Scalar m
         -> Index m -> Index m -> IsometryOf (Scalar m) -> Scalar m -> m ()
{-# INLINE outlines #-}
outlines metric l sec w keyBase x y g margin = do
  let nd = fromIntegral (polyDirections (polygon l))
      gInv0 = inverseIso metric g
  backShift <- share3 (isoShift gInv0)
  let gInv = gInv0 { isoShift = backShift }
  (deepXY, normalXY, edgeXY) <- deepestInside metric l sec w margin 0 x y g
  (deepYX, normalYX, edgeYX) <- deepestInside metric l sec w margin nd y x gInv
  -- (depths counted from −margin, so that a way with no vertex near is 0)
  yInX <- share ((deepYX + margin) - 1.1 * (deepXY + margin))
  let pick a b = select yInX b a
      pick3 (V3 a b c) (V3 u v s) = V3 (pick a u) (pick b v) (pick c s)
  best <- share (maxF deepXY deepYX)
  whenPositive (best + margin) $ do
    -- the mover's vertices are inside the reference body
    mover <- share (pick (toScalar x) (toScalar y))
    reference <- share (pick (toScalar y) (toScalar x))
    moverShift <- share3 (pick3 (isoShift g) backShift)
    -- where deepestInside left the mover's vertices' depths
    moverProbe <- share (pick 0 (fromIntegral (polyDirections (polygon l))))
    edgeNormal <- share3 (pick3 normalXY normalYX)
    o0 <- share3 (pick3 edgeXY edgeYX)
    -- the mover's isometry (x's, or the inverse for y's vertices in x)
    -- and its inverse, which takes the push back to the mover
    let moverLinear = pickLinear (isoLinear g) (isoLinear gInv)
        pickLinear a b = pick3 <$> a <*> b
        image q = linearMap moverLinear q + moverShift
        linear = linearMap moverLinear
        back = linearMap (pickLinear (isoLinear gInv) (isoLinear g))
        mv = toIndex mover
        rf = toIndex reference
    fr <- bodyFrame metric w rf
    -- a vertex pushed past the reference body's centre faces its far edge,
    -- whose normal would push the mover further in: then the push is
    -- turned round, and its depth is the deepest vertex's
    moverCentre <- read3 (wPos w) mv
    facing <- share (inner metric (image moverCentre ^-^ bfCentre fr) edgeNormal)
    -- The edge's normal lies in the reference body's tangent plane; the
    -- push is along it as the tangent plane midway between the bodies
    -- sees it, so that each body's row (the push projected to its own
    -- plane) is the other's mirror: the pair's pushes then cancel on the
    -- surface as they do on a plane (along the reference body's plane, on
    -- a sphere they would drive the pair sideways, from nothing).
    moverNormal <- read3 (wNormal w) mv
    mid <- share3 (normalizeIn metric (linear moverNormal ^+^ bfNormal fr))
    m0 <- share3 (normalizeIn metric (tangentProjection metric mid (fmap (\v -> select facing v (negate v)) edgeNormal)))
    t <- share3 (perpendicular metric (bfNormal fr) m0)
    (dLo, dHi) <- extremesAlong margin nd $ \d -> do
      q <- outlineVertex l w mv d
      depth <- readArray (wProbe w) (toIndex moverProbe + d)
      pure (depth, inner metric (image q ^-^ bfCentre fr) t)
    -- Where the touching ends along the edge: at the reference body's
    -- ends (its vertices on the reference edge's line), unless the
    -- mover's outline ends first. A mover that overhangs the reference
    -- body's corner has its own corner outside it; the touching then ends
    -- at the reference's corner, between the mover's last vertex inside
    -- and its next one, and that is where the contact point goes (as
    -- Box2D clips the incident edge at the reference edge's side planes).
    -- Left at the last vertex inside, the support narrowed by a whole
    -- outline edge the moment the mover's corner cleared the margin, and
    -- tall stacks rocked over.
    let along q = inner metric (q ^-^ bfCentre fr) t
    (refLo, refHi) <- referenceEnds metric l w rf margin o0 edgeNormal along
    let behind q = inner metric (o0 ^-^ q) m0
        ndS = fromIntegral (polyDirections (polygon l))
        nextOf k = select (k - ndS + 1.5) 0 (k + 1)
        prevOf k = select (0.5 - k) (ndS - 1) (k - 1)
        clipAt dv end = do
          q <- outlineVertex l w mv (toIndex dv)
          query <- share3 (image q)
          pos <- share (along query)
          depth <- share (behind query)
          -- how far to go towards the end (none where the push is
          -- turned round: the reference's far side is no end)
          gap <- share (select facing (end - pos) 0)
          -- of the vertex's two outline neighbours, the one towards the
          -- end along a touching edge (within the margin), and the share
          -- of the way to it that reaches the end
          let reach k = do
                n <- outlineVertex l w mv (toIndex k)
                nq <- share3 (image n)
                step <- share (along nq - pos)
                dn <- share (behind nq)
                s <- share (select (gap * step) (select (dn + margin) (clampF 0 1 (gap / step)) 0) 0)
                pure (s, n, nq, dn)
          (sUp, nUp, qUp, dUp) <- reach (nextOf dv)
          (sDown, nDown, qDown, dDown) <- reach (prevOf dv)
          up <- share (sUp - sDown)
          s <- share (maxF sUp sDown)
          let toward a b = select up a b
              toward3 (V3 a b c) (V3 u v z) = V3 (toward a u) (toward b v) (toward c z)
              lerp3 a b = a ^+^ s *^ (b ^-^ a)
          ra <- share3 (lerp3 q (toward3 nUp nDown))
          rb <- share3 (lerp3 query (toward3 qUp qDown))
          d <- share (depth + s * (toward dUp dDown - depth))
          pure (ra, rb, select facing d best, s)
        emitAt slot (ra, rb, d, _) = emitContact metric w x (keyBase + slot) mv reference ra (back m0) rb m0 d 1 1 linear
    lo <- clipAt dLo refLo
    hi <- clipAt dHi refHi
    emitAt 0 lo
    -- a second point where there are two vertices, or where one vertex's
    -- edge runs on along the reference (then the vertex and the edge's
    -- clipped end are the two)
    let moved (_, _, _, s) = s
    whenPositive (abs (dHi - dLo) + moved lo + moved hi) (emitAt 1 hi)

-- | Where body @rf@'s outline ends along a line: the least and the greatest
-- position ('along') of its outline vertices within @margin@ of the line
-- through its vertex @o0@ with outward normal @normal@ (@o0@'s own when no
-- other is).
referenceEnds :: Imp m => Metric -> Layout -> WorldArrays (Array m) -> Index m -> Scalar m -> V3 (Scalar m) -> V3 (Scalar m)
              -> (V3 (Scalar m) -> Scalar m) -> m (Scalar m, Scalar m)
{-# INLINE referenceEnds #-}
referenceEnds metric l w rf margin o0 normal along = do
  start <- share (along o0)
  lo <- newRef start
  hi <- newRef start
  forEach (fromIntegral (polyDirections (polygon l))) $ \d -> do
    v <- outlineVertex l w rf d
    whenPositive (inner metric (v ^-^ o0) normal + margin) $ do
      s <- share (along v)
      readRef lo >>= writeRef lo . minF s
      readRef hi >>= writeRef hi . maxF s
  (,) <$> readRef lo <*> readRef hi

-- | How far apart two bodies' outlines may be and still make contact rows
-- (speculative ones, which keep the bodies from closing the gap faster than
-- the sub-steps resolve): the 'Speculative' parameter times the smaller
-- body's size. A box tilting on a box keeps its lifted corner as a contact
-- point so, and the pair's rows exist before the bodies touch.
speculativeMargin :: Imp m => WorldArrays (Array m) -> Index m -> Index m -> m (Scalar m)
{-# INLINE speculativeMargin #-}
speculativeMargin w x y = do
  f <- readParam w Speculative
  sx <- readSlot w x Size
  sy <- readSlot w y Size
  share (f * minF sx sy)

-- | Of body @x@'s outline vertices, mapped by the isometry @g@, the
-- one deepest inside body @y@ or nearest to it within @margin@: its depth
-- (negative outside; @−margin@ when none is so near), and the
-- outward normal and a vertex of the edge of y it lies behind. Each
-- vertex's depth (−1 when it is not near y) is left in the probe array from
-- @slot@ on, so that the pair's contact points are chosen without testing
-- the vertices again.
deepestInside :: Imp m => Metric -> Layout -> Sectors -> WorldArrays (Array m) -> Scalar m -> Index m -> Index m -> Index m
              -> IsometryOf (Scalar m) -> m (Scalar m, V3 (Scalar m), V3 (Scalar m))
{-# INLINE deepestInside #-}
deepestInside metric l sec w margin slot x y g = do
  let nd = fromIntegral (polyDirections (polygon l))
      image = applyIso g
  fy <- bodyFrame metric w y
  turn <- bodyTurn w y
  deepest <- newRef (negate margin)
  mx <- newRef 0
  my <- newRef 0
  mz <- newRef 0
  ox <- newRef 0
  oy <- newRef 0
  oz <- newRef 0
  forEach nd $ \d -> do
    q <- outlineVertex l w x d
    writeArray (wProbe w) (slot + d) (-1)
    whenNear metric fy (image q) $ do
      e <- edgeFacing metric l sec w y fy turn (image q)
      writeArray (wProbe w) (slot + d) (efDepth e)
      best <- readRef deepest
      whenPositive (efDepth e - best) $ do
        writeRef deepest (efDepth e)
        let V3 a b c = efNormal e in writeRef mx a >> writeRef my b >> writeRef mz c
        let V3 u v s = efVertex e in writeRef ox u >> writeRef oy v >> writeRef oz s
  (,,) <$> readRef deepest
       <*> (V3 <$> readRef mx <*> readRef my <*> readRef mz)
       <*> (V3 <$> readRef ox <*> readRef oy <*> readRef oz)

-- | Of the outline vertices @d@ whose probe gives a depth above @−margin@,
-- the two with the least and the greatest position along the contact line
-- (−1 when none): a contact manifold's two points.
extremesAlong :: Imp m => Scalar m -> Index m -> (Index m -> m (Scalar m, Scalar m)) -> m (Scalar m, Scalar m)
{-# INLINE extremesAlong #-}
extremesAlong margin nd probe = do
  lo <- newRef 1e300
  hi <- newRef (-1e300)
  loD <- newRef (-1)
  hiD <- newRef (-1)
  forEach nd $ \d -> do
    (depth, position) <- probe d
    whenPositive (depth + margin) $ do
      s <- share position
      l0 <- readRef lo
      whenPositive (l0 - s) (writeRef lo s >> writeRef loD (toScalar d))
      h0 <- readRef hi
      whenPositive (s - h0) (writeRef hi s >> writeRef hiD (toScalar d))
  (,) <$> readRef loD <*> readRef hiD

-- | Where the outline of body @i@ leaves the allowed region @b >= 0@; a
-- box's or a capsule's hull by its corners ('hullBoundary').
boundaryContacts :: Imp m => Space -> Layout -> WorldArrays (Array m) -> Index m -> m ()
boundaryContacts sp l w i = case spaceBoundary sp of
  Nothing -> pure ()
  Just bf -> do
    corners <- readSlot w i Corners
    ifPositive (corners - 1.5) (hullBoundary sp bf w i corners) (outlineBoundary sp l bf w i)

-- | Where body @i@'s hull (two corners or more) leaves the allowed region
-- @b >= 0@: each corner as deep as the region's edge lies inside its
-- rounding, @r − b/|∇b|@; the deepest corner, and of those within the
-- margin the two extremes along the edge (a box lying on it has two),
-- each pushed where its rounding meets the edge.
hullBoundary :: Imp m => Space -> ScalarFn -> WorldArrays (Array m) -> Index m -> Scalar m -> m ()
{-# INLINE hullBoundary #-}
hullBoundary sp bf w i corners = do
  let metric = spaceMetric sp
      key = fromIntegral (fromEnum BoundaryKey) * fromIntegral keysPerGroup
      base = fromIntegral hullStride * i
      corner k = readAt3' (base + hullWorldAt k)
      readAt3' o = V3 <$> readArray (wHull w) o <*> readArray (wHull w) (o + 1) <*> readArray (wHull w) (o + 2)
      -- how far a corner lies past the region's edge (negative: inside),
      -- and the direction back into the region there
      depthAt q = do
        g <- share3 (gradFn bf q)
        gl <- share (normIn metric (raise metric g))
        bv <- share (evalFn bf q)
        pure (negate (select gl (bv / maxF gl 1e-300) 0), normalOf metric g)
  rounding <- readArray (wHull w) base
  n <- read3 (wNormal w) i
  margin <- speculativeMargin w i i
  deepest <- newRef (negate margin)
  kDeep <- newRef (-1)
  forLoop 0 (toIndex corners) $ \k -> do
    (d, _) <- depthAt =<< corner k
    best <- readRef deepest
    whenPositive (rounding + d - best) (writeRef deepest (rounding + d) >> writeRef kDeep (toScalar k))
  kd <- readRef kDeep
  whenPositive (kd + 0.5) $ do
    (_, dir0) <- depthAt =<< corner (toIndex kd)
    t <- share3 (perpendicular metric n dir0)
    (kLo, kHi) <- extremesAlong margin (toIndex corners) $ \k -> do
      q <- corner k
      (d, _) <- depthAt q
      pure (rounding + d, inner metric q t)
    -- (each row keyed by its corner, as a pair's rows are)
    let emitAt k = do
          q <- corner (toIndex k)
          (d, dir) <- depthAt q
          -- where the rounding meets the edge: the corner moved out along the edge's normal
          p <- share3 (q ^-^ rounding *^ dir)
          emitContact metric w i (key + k) i (-1) p dir p dir (rounding + d) 1 1 id
    emitAt kLo
    whenPositive (abs (kHi - kLo)) (emitAt kHi)

-- | Where the outline of body @i@ leaves the allowed region @b >= 0@.
outlineBoundary :: Imp m => Space -> Layout -> ScalarFn -> WorldArrays (Array m) -> Index m -> m ()
outlineBoundary sp l bf w i = do
    let b = evalFn bf
        metric = spaceMetric sp
    let nd = fromIntegral (polyDirections (polygon l))
        key = fromIntegral (fromEnum BoundaryKey) * fromIntegral keysPerGroup
    n <- read3 (wNormal w) i
    margin <- speculativeMargin w i i
    deepest <- newRef (negate margin)
    dDeep <- newRef (-1)
    forEach nd $ \d -> do
      q <- outlineVertex l w i d
      bv <- share (b q)
      best <- readRef deepest
      whenPositive (negate bv - best) (writeRef deepest (negate bv) >> writeRef dDeep (toScalar d))
    dd <- readRef dDeep
    whenPositive (dd + 0.5) $ do
      q0 <- outlineVertex l w i (toIndex dd)
      dir0 <- share3 (normalOf metric (gradFn bf q0))
      t <- share3 (perpendicular metric n dir0)
      (dLo, dHi) <- extremesAlong margin nd $ \d -> do
        q <- outlineVertex l w i d
        pure (negate (b q), inner metric q t)
      let emitAt slot dv = do
            q <- outlineVertex l w i (toIndex dv)
            g <- share3 (gradFn bf q)
            gl <- share (normIn metric (raise metric g))
            bv <- share (b q)
            let dir = normalOf metric g
                depth = select gl (negate bv / maxF gl 1e-300) 0
            emitContact metric w i (key + slot) i (-1) q dir q dir depth 1 1 id
      emitAt 0 dLo
      whenPositive (abs (dHi - dLo)) (emitAt 1 dHi)

-- | The paper's self-contact (§4.2): a body as large as the space around it
-- (wrapped round the neck of the trumpet) overlaps itself where two of its
-- rays cross. The ordinary contact direction there is along the rays and
-- useless (it acts on both ends of one body), so the row is turned
-- perpendicular to it: the body is pushed against the mean of the two rays'
-- starting directions. Rays that head into the narrow part are the ones that
-- wrap round and cross, so that mean points into the narrowing and the push
-- goes back to where the body just covers the space. (Rays exactly opposite
-- have no mean and are not paired.) Scaled by 0.6 as in the paper; the depth
-- is half the length by which the two rays overrun their crossing. The row
-- acts on the body's position only: a body rubbing on itself has no
-- friction, and turning it does not undo the wrap (with the angular part,
-- the jam slowly spun itself loose).
--
-- The row's direction is every crossing's push, weighted by its depth, in
-- the body's own tangent plane; its depth the deepest crossing's. (The
-- deepest crossing's push alone, pressed deeper by a pile, sometimes came
-- from two rays heading up and sideways and pushed the body further into
-- the neck; taken in the tangent plane at the crossing, on the far side of
-- the neck, it turned with the crossing, and a circle jammed at rest crept
-- round the neck from round-off: docs/decisions/self-contact-push.md.)
--
-- Only a body whose rays turn (the chord from the centre to some outline
-- vertex is under 'selfContactChord' of the ray's length) is tested, which
-- flat and gently curved places never trigger; a flat space's step leaves
-- the test out.
--
-- A subroutine of its own in the staged step: in line, its loops made the
-- collision phase of the spaces with self-contact too big for V8 to
-- optimise.
selfContacts :: Imp m => Space -> Layout -> WorldArrays (Array m) -> Index m -> m ()
{-# INLINE selfContacts #-}
selfContacts sp l w i = subroutine "selfContacts" [toScalar i] $ \case
  [i'] -> selfContactsOf sp l w (toIndex i')
  _ -> error "selfContacts: one argument"

-- | How far a body's rays must turn (the shortest chord from its centre to
-- its outline over its ray's length) before it is tested for self-contact.
-- At 0.8 a square sinking into the trumpet's neck crossed itself before
-- the test began, its rays overrunning each other by a fiftieth of its
-- size when they were first seen: the row that appeared pushed it out of
-- the test's reach and it fell back, every seven steps for ever. At 0.95
-- the crossing is seen from its start and the square rests (it sits at a
-- chord of 0.81).
selfContactChord :: Field a => a
selfContactChord = 0.95

-- | 'selfContacts''s test.
selfContactsOf :: Imp m => Space -> Layout -> WorldArrays (Array m) -> Index m -> m ()
{-# INLINE selfContactsOf #-}
selfContactsOf sp l w i = do
  let metric = spaceMetric sp
      nd = polyDirections (polygon l)
      ns = polySteps (polygon l)
      vpb = fromIntegral (verticesPerBody l)
      vertex d k = read3 (wVerts w) (vpb * i + vertexIndex (polygon l) d k) -- step k along d
      -- (inlined: as a function of its own, the generic step boxed every vertex it read)
      {-# INLINE vertex #-}
      centreIx = vpb * i
      hullBase = fromIntegral hullStride * i
      shareBoth (q, d) = (,) <$> share3 q <*> share3 d
  c <- read3 (wVerts w) centreIx
  turn <- newRef 1
  forEach (fromIntegral nd) $ \d -> do
    o <- outlineVertex l w i d
    r <- readArray (wRadii w) (fromIntegral nd * i + d)
    modifyRef turn (minF (select r (normIn metric (o ^-^ c) / r) 1))
  straightness <- readRef turn
  whenPositive (selfContactChord - straightness) $ do
    deepest <- newRef 0
    px <- newRef 0
    py <- newRef 0
    pz <- newRef 0
    mx <- newRef 0
    my <- newRef 0
    mz <- newRef 0
    -- a crossing found: its push (the negated mean of its rays' starting
    -- directions) added in, weighted by its depth; the row's depth and
    -- point are the deepest crossing's
    let crossing depth (V3 x y z) (V3 u v q) = do
          modifyRef mx (+ depth * u)
          modifyRef my (+ depth * v)
          modifyRef mz (+ depth * q)
          best <- readRef deepest
          whenPositive (depth - best) $ do
            writeRef deepest depth
            writeRef px x >> writeRef py y >> writeRef pz z
    -- the longest of the body's ray segments: two segments whose midpoints
    -- lie farther apart than that plus 0.3 h are more than 0.3 h apart
    -- everywhere, and most of the pairs below are (a wrapped body's rays
    -- cross in a few places), so they are passed over before the closest
    -- points are solved for (an exact bound: the same rows)
    longest <- newRef 0
    forEach (fromIntegral nd) $ \d -> forLoop 1 (fromIntegral ns) $ \k -> do
      a0 <- vertex d k
      a1 <- vertex d (k + 1)
      modifyRef longest (maxF (quadranceIn metric (a1 ^-^ a0)))
    segment <- share . sqrt =<< readRef longest
    forEach (fromIntegral nd) $ \d -> do
      rd <- readArray (wRadii w) (fromIntegral nd * i + d)
      forLoop (fromIntegral (nd `div` 4)) (fromIntegral (nd `div` 2)) $ \off -> do
        let d' = toIndex (let x = toScalar d + toScalar off in x - fromIntegral nd * floorF (x / fromIntegral nd))
        rd' <- readArray (wRadii w) (fromIntegral nd * i + d')
        h <- share (minF rd rd' / fromIntegral ns)
        -- (with a relative margin, so that rounding never passes over a
        -- pair the closest-point test would take)
        reach <- share (let x = 0.3 * h + segment in x * x * 1.000001)
        forLoop 1 (fromIntegral ns) $ \k -> do
          a0 <- vertex d k
          a1 <- vertex d (k + 1)
          forLoop 1 (fromIntegral ns) $ \k' -> do
            b0 <- vertex d' k'
            b1 <- vertex d' (k' + 1)
            let midpoints = 0.5 *^ ((a0 ^+^ a1) ^-^ (b0 ^+^ b1))
            whenPositive (reach - quadranceIn metric midpoints) $ do
              let (s, t, gap) = segmentClosest (inner metric) a0 a1 b0 b1
                  arc = rd * (toScalar k + s) / fromIntegral ns
                  arc' = rd' * (toScalar k' + t) / fromIntegral ns
                  depth = 0.5 * ((rd - arc) + (rd' - arc'))
              whenPositive (minF (0.3 * h - gap) depth) $ do
                first <- vertex d 1
                first' <- vertex d' 1
                crossing (nearing h gap depth) (a0 ^+^ s *^ (a1 ^-^ a0))
                  (negated (normalizeIn metric (first ^-^ c) ^+^ normalizeIn metric (first' ^-^ c)))
    -- A hull's corners make rays of their own (a capsule's: its segment's
    -- ends on either side, at its radius). A card or a capsule wrapped
    -- round the neck has only two long outline rays, exactly opposite (no
    -- mean: not paired), so its outline never finds the jam; its corners'
    -- rays come in pairs on either side of it, each pair's mean across
    -- it, and the pair heading into the narrowing crosses deeper, as the
    -- outline's rays do.
    corners <- readSlot w i Corners
    whenPositive (corners - 1.5) $ do
      (d1, d2) <- bodyAxes metric w i
      rounding <- readArray (wHull w) hullBase
      let steps = fromIntegral cornerWalkSteps
          rays = select (corners - 2.5) corners 4
          -- ray j's length and direction from the centre
          rayOf j = do
            k <- share (select (corners - 2.5) (toScalar j) (toScalar j - 2 * floorF (toScalar j / 2)))
            a <- readArray (wHull w) (hullBase + hullLocalAt (toIndex k))
            b0 <- readArray (wHull w) (hullBase + hullLocalAt (toIndex k) + 1)
            b <- share (select (corners - 2.5) b0 (select (toScalar j - 1.5) (negate rounding) rounding))
            len0 <- share (sqrt (a * a + b * b))
            len <- share (len0 + select (corners - 2.5) rounding 0)
            dir <- share3 ((a / len0) *^ d1 ^+^ (b / len0) *^ d2)
            pure (len, dir)
          -- step k (1 to the steps) along ray j, walked below
          point j k = read3 (wProbe w) (fromIntegral cornerWalkSteps * j + k - 1)
      forLoop 0 (toIndex rays) $ \j -> do
        (len, dir) <- rayOf j
        foldM_ (\qd k -> do
                  (q, d) <- shareBoth (geodesicStep metric (spaceField sp) (len / steps) qd)
                  write3 (wProbe w) (fromIntegral cornerWalkSteps * j + fromIntegral k - 1) q
                  pure (q, d))
               (c, dir) [1 .. cornerWalkSteps]
      forLoop 0 (toIndex rays) $ \j -> forLoop 0 (toIndex rays) $ \j' -> do
        (lenJ, dirJ) <- rayOf j
        (lenJ', dirJ') <- rayOf j'
        mean <- share3 (dirJ ^+^ dirJ')
        -- each pair once, a right angle apart or more, not opposite (a
        -- square's neighbouring corners are a right angle apart exactly,
        -- so the test takes a little more: by the sign of the product's
        -- rounding alone, their pair came and went as a square sank into
        -- its jam, and its row with it)
        whenPositive (minF (toScalar j' - toScalar j - 0.5) (minF (1e-9 - inner metric dirJ dirJ') (normIn metric mean - 1e-6))) $ do
          h <- share (minF lenJ lenJ' / steps)
          forLoop 1 (fromIntegral cornerWalkSteps) $ \k -> forLoop 1 (fromIntegral cornerWalkSteps) $ \k' -> do
            a0 <- point j k
            a1 <- point j (k + 1)
            b0 <- point j' k'
            b1 <- point j' (k' + 1)
            let (s, t, gap) = segmentClosest (inner metric) a0 a1 b0 b1
                arc = lenJ * (toScalar k + s) / steps
                arc' = lenJ' * (toScalar k' + t) / steps
                depth = 0.5 * ((lenJ - arc) + (lenJ' - arc'))
            whenPositive (minF (0.3 * h - gap) depth) $
              crossing (nearing h gap depth) (a0 ^+^ s *^ (a1 ^-^ a0)) (negated mean)
    best <- readRef deepest
    whenPositive best $ do
      point <- V3 <$> readRef px <*> readRef py <*> readRef pz
      push <- V3 <$> readRef mx <*> readRef my <*> readRef mz
      n <- read3 (wNormal w) i
      dir <- share3 (normalizeIn metric (tangentProjection metric n push))
      emitContact metric w i selfKey i (-1) point dir point dir best 0.6 0 id
  where
    selfKey = fromIntegral (fromEnum SelfKey) * fromIntegral keysPerGroup
    -- A crossing's depth, from 0 where two rays come within the 0.3 h that
    -- makes them a crossing, up to their overrun: the overrun alone starts
    -- at whatever the rays overrun each other by when they first come that
    -- close, so a row would appear at a depth instead of growing from
    -- nothing (docs/decisions/self-contact-seen-from-its-start.md).
    nearing h gap depth = minF depth (0.3 * h - gap)

-- | Every contact of this step, owned by the lower-numbered body of each
-- pair of moving bodies, by the moving one of a pair with a still (static
-- or sleeping) body, in body order (warm starting relies on the order).
-- Where no body is awake there is nothing to find.
collide :: Imp m => Space -> Layout -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE collide :: Space -> Layout -> WorldArrays NativeArray -> Native () #-}
collide sp l w = do
  writeMeta w ContactCount 0
  writeMeta w KeptRows 0
  awake <- readMeta w AwakeCount
  whenPositive awake (collideAwake sp l w)

-- | 'collide' where some body is awake: each awake movable body finds its
-- contacts with the bodies after it that move and with every body that
-- does not (static or sleeping), so that every pair with a moving body is
-- found once and no pair of two still bodies is.
collideAwake :: Imp m => Space -> Layout -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE collideAwake :: Space -> Layout -> WorldArrays NativeArray -> Native () #-}
collideAwake sp l w = do
  buildGrid sp w
  count <- readMeta w BodyCount
  joints <- readMeta w JointCount
  whenPositive joints $ listPartners w
  writeImageTable sp l w
  -- what the field's symbolic gradient says, decided once, not at every body
  let images = length (quotientImages (spaceQuotient sp))
      metric = spaceMetric sp
      onPlane = planeAlongY sp
      flat = hasConstantGradient (spaceField sp)
  forEach (toIndex count) $ \i -> moving w i >>= \movingI -> whenPositive movingI $ do
    nearPairs sp l w onPlane i 0 True
    -- through each image, a loop over the table: the Bolza surface's 48
    -- images unrolled would be 48 copies of the search
    when (images > 0) $ forEach (fromIntegral images) $ \k -> nearPairs sp l w onPlane i (toScalar k + 1) False
    keepOr metric w i (-1) (fromIntegral (fromEnum BoundaryKey * keysPerGroup)) (boundaryContacts sp l w i)
    -- (on a plane every ray is straight, so no body's rays ever turn and
    -- the test below never passes: it is left out of a flat space's step)
    unless flat (selfContacts sp l w i)

-- | Body @i@'s contacts with the bodies near its image under the table's
-- isometry @image@ (0, the identity, for its contacts in place, @direct@,
-- which keeps a pair's rows while it hardly moves): the near bodies listed
-- from the grid first and their pairs made after (compiled natively, a
-- loop that calls out keeps its numbers on the stack, and the cell scan is
-- the broad phase's whole cost). Each unordered pair once: @j > i@
-- (@j >= i@ through an image through which the body may meet itself), or
-- @j@ still; a pair of a body in the grid and one apart is the grid body's
-- while it moves (the one apart takes it from a still grid body). Its keys
-- are @j@'s group of the image ('imageKeyGroup'). @onPlane@: the space is a
-- plane @y = c@ ('planeAlongY').
nearPairs :: Imp m => Space -> Layout -> WorldArrays (Array m) -> Bool -> Index m -> Scalar m -> Bool -> m ()
{-# INLINE nearPairs #-}
nearPairs sp l w onPlane i image direct = do
  g <- readImage l w image
  self <- readArray (wProbe w) (fromIntegral (imageTableAt l + imageStride - 1) + fromIntegral imageStride * toIndex image)
  let keyOffset = if direct then 0 else fromIntegral keysPerGroup * (image - 1 + fromIntegral (fromEnum FirstImageKey))
  count <- readMeta w BodyCount
  joints <- readMeta w JointCount
  let metric = spaceMetric sp
      sec = sectors (polyDirections (polygon l))
      -- where the quotient has a fundamental domain, only images that
      -- come within reach of it
      nearDomain = case domainDistance (spaceQuotient sp) of
        Just distance -> \q reach -> whenPositive (reach - distance q)
        Nothing -> \_ _ act -> act
  p <- read3 (wPos w) i
  ri <- readSlot w i BoundRadius
  invMi <- readSlot w i InvMass
  -- the bodies joined to this one, which it does not collide with
  partners <- mapM (\s -> readArray (wPartners w) (fromIntegral partnersPerBody * i + fromIntegral s)) [0 .. partnersPerBody - 1]
  cell <- readMeta w CellSize -- at least twice the bounding radius of every body in the grid
  cellI <- readArray (wCellOf w) i -- −1: kept apart from the grid
  found <- newRef 0
  gp <- share3 (applyIso g p)
  let ordered movingJ j = select movingJ (toScalar j - toScalar i + 0.5 * self) 1
      consider orderOf j = do
        movingJ <- moving w j
        whenPositive (orderOf movingJ j) $ do
          pj <- read3 (wPos w) j
          rj <- readSlot w j BoundRadius
          invMj <- readSlot w j InvMass
          let gap = ri + rj - normIn metric (gp ^-^ pj)
          whenPositive (minF gap (minF (invMi + invMj) (select joints (notJoined partners (toScalar j)) 1))) $ do
            -- a body is in one cell or in the large list, so listed at most once
            k <- readRef found
            writeArray (wNear w) (toIndex k) (toScalar j)
            writeRef found (k + 1)
  -- the bodies kept apart, at the end of the items
  large <- readMeta w LargeCount
  capacity <- readMeta w Capacity
  let apart orderOf = forEach (toIndex large) $ \k -> readArray (wItems w) (toIndex capacity - 1 - k) >>= consider orderOf . toIndex
  ifPositive (cellI + 0.5)
    (do nearDomain gp (ri + cell) $ neighbours onPlane metric w gp (consider ordered)
        apart (\_ _ -> 1))
    -- a body apart: every still body of the grid, then the others apart
    (do nearDomain gp (ri + cell) $ forEach (toIndex count) $ \j -> do
          cellJ <- readArray (wCellOf w) j
          whenPositive (cellJ + 0.5) (consider (\movingJ _ -> 0.5 - movingJ) j)
        apart ordered)
  nearCount <- readRef found
  forEach (toIndex nearCount) $ \k -> do
    j <- toIndex <$> readArray (wNear w) k
    let keyBase = (toScalar j + 1) * fromIntegral (keysPerBody (spaceQuotient sp)) + keyOffset
    -- (a pair through an image is found anew each step: the image's
    -- isometry moves the rows with the wraps)
    let contacts = pairContacts metric l sec w keyBase i j image
    if direct then keepOr metric w i (toScalar j) keyBase contacts else contacts
