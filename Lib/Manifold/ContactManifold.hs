{-# LANGUAGE FlexibleContexts #-}
-- | Contact manifolds: where two convex shapes touch, found in a plane (the
-- tangent frame at a touching pair), as Box2D v3's manifold functions find
-- them: at most two points, each with its separation and a key naming the
-- corner it is at, so that warm starting follows a point from step to
-- step.
--
-- Every shape is a 'Hull': its corners, counter-clockwise, and a radius
-- that rounds them. A circle is one corner (its centre) and its radius, a
-- capsule two (its segment's ends), a polygon three to 'maxHullCorners'
-- (a box four), rounded or not. So two functions cover every pair of
-- shapes: a point against a hull ('collideHulls' when either has one
-- corner), and two hulls by the separating axis (the edge normal of
-- either along which they are farthest apart gives the reference edge; the
-- other's edge most opposed to it, the incident edge, is clipped to the
-- reference edge's side lines, and its two ends are the points).
--
-- Written against the imperative layer, so it runs natively and stages
-- into the page's engine as the rest of the step does.
module Manifold.ContactManifold
  ( Hull (..)
  , maxHullCorners
  , ManifoldPoint (..)
  , ContactManifold (..)
  , collideHulls
  , cornerKey
  , keysPerManifold
  , segmentClosest
  ) where

import Linear.V2 (V2 (..))
import Linear.Vector (Additive, (*^), (^+^), (^-^), negated)

import Manifold.Field
import Manifold.Stage.Imp

-- | A convex shape in the plane: its corners counter-clockwise (one: a
-- circle's centre; two: a capsule's segment; three or more: a polygon),
-- each edge's outward unit normal (edge @k@ runs from corner @k@ to corner
-- @k + 1@, the last back to the first; a segment's two edges are its two
-- sides), and the radius that rounds it.
data Hull m = Hull
  { hullCount :: Scalar m -- ^ corners, 1 to 'maxHullCorners'
  , hullCorner :: Index m -> m (V2 (Scalar m))
  , hullNormal :: Index m -> m (V2 (Scalar m)) -- ^ (not read for one corner)
  , hullRadius :: Scalar m
  }

-- | The most corners a hull has (Box2D's polygons have as many).
maxHullCorners :: Int
maxHullCorners = 8

-- | One point of a contact manifold: where it is (midway between the two
-- shapes' surfaces along the normal), how far apart the shapes are there
-- along the normal (negative: overlapping by that much), and its key: the
-- corner it is at ('cornerKey').
data ManifoldPoint s = ManifoldPoint
  { mpPoint :: V2 s
  , mpSeparation :: s
  , mpKey :: s
  } deriving Show

-- | Where two shapes touch: 0, 1 or 2 points (those closer than the
-- margin), and the unit normal from the first shape to the second that
-- pushes them apart. (Points past the count hold whatever was left there.)
data ContactManifold s = ContactManifold
  { cmCount :: s
  , cmNormal :: V2 s
  , cmFirst :: ManifoldPoint s
  , cmSecond :: ManifoldPoint s
  } deriving Show

-- | The key of a point at corner @k@ of the first shape (@second@ 0) or of
-- the second (@second@ 1): below 'keysPerManifold'. A clipped point is at
-- a corner of the incident edge, or where the reference edge's side line
-- cuts it, beside a corner of the reference edge; a point against a circle
-- or a capsule's end is at that corner; two corners' single point takes
-- the first shape's. The key names that corner, whichever shape gives the
-- reference edge: a box lying level on a slab is clipped against its own
-- face, tilted a little against the slab's, and its two points keep their
-- keys (Box2D's keys pair the reference edge's corner with the incident
-- edge's, and change when the reference flips), so warm starting follows
-- them as the reference edge changes and as one point drops out.
--
-- >>> cornerKey 1 (3 :: Double)
-- 11.0
cornerKey :: Field a => a -> a -> a
cornerKey second k = fromIntegral maxHullCorners * second + k

-- | How many keys a manifold's points may have ('cornerKey').
--
-- >>> keysPerManifold
-- 16
keysPerManifold :: Int
keysPerManifold = 2 * maxHullCorners

-- | The contact manifold of two hulls within @margin@ of each other (rows
-- for points up to that far apart keep bodies from closing a gap faster
-- than the solver resolves it). @tolerance@ (a small length: Box2D takes a
-- tenth of its linear slop) is how much farther apart the second hull's
-- edges must find the two than the first's before the second gives the
-- reference edge, so that the choice does not flicker between nearly
-- equal ones, and how much closer two corners must be than the clipped
-- edges for the single corner-to-corner point to be taken instead.
collideHulls :: Imp m => Scalar m -> Scalar m -> Hull m -> Hull m -> m (ContactManifold (Scalar m))
collideHulls margin tolerance a b = do
  out <- newResult
  ifPositive (1.5 - hullCount a)
    (do ca <- hullCorner a 0
        pointAgainst out margin 1 ca (hullRadius a) b)
    (ifPositive (1.5 - hullCount b)
      (do cb <- hullCorner b 0
          pointAgainst out margin (-1) cb (hullRadius b) a)
      (polygons out margin tolerance a b))
  readResult out

-- The manifold being written: count, normal, and the two points.
data Result m = Result (Ref m) (Ref m) (Ref m) [Ref m] [Ref m]

newResult :: Imp m => m (Result m)
newResult = Result <$> newRef 0 <*> newRef 0 <*> newRef 0 <*> mapM newRef [0, 0, 0, 0] <*> mapM newRef [0, 0, 0, 0]

readResult :: Imp m => Result m -> m (ContactManifold (Scalar m))
readResult (Result count nx ny first second) = do
  let point refs = do
        values <- mapM readRef refs
        case values of
          [x, y, s, k] -> pure (ManifoldPoint (V2 x y) s k)
          _ -> error "readResult: a point is four numbers"
  ContactManifold <$> readRef count <*> (V2 <$> readRef nx <*> readRef ny) <*> point first <*> point second

-- | Write the manifold: its normal and those of its points (at most two)
-- that are closer than the margin.
emit :: Imp m => Result m -> Scalar m -> V2 (Scalar m) -> [ManifoldPoint (Scalar m)] -> m ()
emit (Result count nx ny first second) margin (V2 x y) points = do
  writeRef count 0
  writeRef nx x
  writeRef ny y
  let put refs (ManifoldPoint (V2 px py) s k) = mapM_ (uncurry writeRef) (zip refs [px, py, s, k])
      add p = whenPositive (margin - mpSeparation p) $ do
        n <- readRef count
        ifPositive (n - 0.5) (put second p) (put first p)
        writeRef count (n + 1)
  mapM_ add points

dot2 :: Num a => V2 a -> V2 a -> a
dot2 (V2 a b) (V2 c d) = a * c + b * d

-- | The corner after corner @k@ of a hull of @n@ (the last's is the first).
nextCorner :: Field a => a -> a -> a
nextCorner n k = select (k + 1.5 - n) 0 (k + 1)

-- | A point @c@ of radius @rc@ (a circle) against a hull; @side@ 1 when
-- the point is the first shape, −1 when it is the second (the normal
-- always runs from the first to the second). The hull's edge along which
-- the point is farthest out gives the contact: the edge itself where the
-- point faces it (or is inside), else the corner the point is beyond.
pointAgainst :: Imp m => Result m -> Scalar m -> Scalar m -> V2 (Scalar m) -> Scalar m -> Hull m -> m ()
pointAgainst out margin side c rc h = do
  let radius = rc + hullRadius h
  ifPositive (1.5 - hullCount h)
    -- two circles: along the line between the centres
    (do q <- hullCorner h 0
        d <- share2 (c ^-^ q)
        dist <- share (sqrt (dot2 d d))
        sep <- share (dist - radius)
        whenPositive (margin - sep) $ do
          -- (coincident centres: any direction will do)
          n <- share2 (select dist (recip dist) 0 *^ d ^+^ V2 (select dist 0 1) 0)
          emitPoint n sep)
    (do best <- newRef (-1e300)
        bestEdge <- newRef 0
        forLoop 0 (toIndex (hullCount h)) $ \i -> do
          n <- hullNormal h i
          v <- hullCorner h i
          s <- share (dot2 n (c ^-^ v))
          b0 <- readRef best
          whenPositive (s - b0) (writeRef best s >> writeRef bestEdge (toScalar i))
        s <- readRef best
        whenPositive (margin + radius - s) $ do
          e <- readRef bestEdge
          n <- hullNormal h (toIndex e)
          v1 <- hullCorner h (toIndex e)
          e2 <- share (nextCorner (hullCount h) e)
          v2 <- hullCorner h (toIndex e2)
          -- beyond a corner (only for a point outside: inside, the edge)
          before <- share (dot2 (c ^-^ v1) (v2 ^-^ v1))
          after <- share (dot2 (c ^-^ v2) (v1 ^-^ v2))
          outside <- share s
          ifPositive (minF outside (negate before))
            (corner v1)
            (ifPositive (minF outside (negate after))
              (corner v2)
              (emitPoint n (s - radius))))
  where
    -- (the point is at the circle's centre, the point shape's one corner)
    key = cornerKey (0.5 - 0.5 * side) 0
    corner v = do
      d <- share2 (c ^-^ v)
      dist <- share (sqrt (dot2 d d))
      sep <- share (dist - rc - hullRadius h)
      whenPositive (margin - sep) $ emitPoint (recip dist *^ d) sep
    -- n points from the hull to the point; the contact point lies midway
    -- between the two surfaces
    emitPoint n sep = do
      n' <- share2 n
      p <- share2 (c ^-^ (rc + 0.5 * sep) *^ n')
      emit out margin (negated (side *^ n')) [ManifoldPoint p sep key]

-- | Two hulls of two corners or more, by the separating axis and clipping.
polygons :: Imp m => Result m -> Scalar m -> Scalar m -> Hull m -> Hull m -> m ()
polygons out margin tolerance a b = do
  (sepA, edgeA) <- maxSeparation a b
  (sepB, edgeB) <- maxSeparation b a
  let radius = hullRadius a + hullRadius b
  whenPositive (margin + radius - maxF sepA sepB) $
    -- b's edge gives the reference when it finds them clearly farther apart
    ifPositive (sepB - sepA - tolerance)
      (reference b a edgeB (maxF sepA sepB) True)
      (reference a b edgeA (maxF sepA sepB) False)
  where
    reference ref inc edge separation flipped = do
      nRef <- hullNormal ref (toIndex edge)
      incEdge <- incidentEdge nRef inc
      i12 <- share (nextCorner (hullCount ref) edge)
      i22 <- share (nextCorner (hullCount inc) incEdge)
      v11 <- hullCorner ref (toIndex edge)
      v12 <- hullCorner ref (toIndex i12)
      v21 <- hullCorner inc (toIndex incEdge)
      v22 <- hullCorner inc (toIndex i22)
      let r1 = hullRadius ref
          r2 = hullRadius inc
          radius = r1 + r2
          -- the keys of the reference hull's corners and the incident's
          -- (a is the first shape, b the second)
          refKey = cornerKey (if flipped then 1 else 0)
          incKey = cornerKey (if flipped then 0 else 1)
          orient n = if flipped then negated n else n
          -- the manifold of the clipped incident edge, points in the order
          -- along a's edge
          clipped points = emit out margin (orient nRef) (if flipped then reverse points else points)
      -- the incident edge clipped to the reference edge's side lines
      t <- share2 (let V2 x y = nRef in V2 (negate y) x)
      upper1 <- share (dot2 (v12 ^-^ v11) t)
      -- (the incident edge runs the other way)
      upper2 <- share (dot2 (v21 ^-^ v11) t)
      lower2 <- share (dot2 (v22 ^-^ v11) t)
      span2 <- share (upper2 - lower2)
      overlapping <- share (minF upper2 (upper1 - lower2))
      let lerp p q s = p ^+^ s *^ (q ^-^ p)
          usable = select span2 1 0
      vLower <- share2 (lerp v22 v21 (select (negate lower2) (usable * clampF 0 1 (negate lower2 / maxF span2 1e-300)) 0))
      vUpper <- share2 (lerp v22 v21 (select (upper2 - upper1) (usable * clampF 0 1 ((upper1 - lower2) / maxF span2 1e-300)) 1))
      sepLower <- share (dot2 (vLower ^-^ v11) nRef)
      sepUpper <- share (dot2 (vUpper ^-^ v11) nRef)
      let midway v s = v ^+^ (0.5 * (r1 - r2 - s)) *^ nRef
          -- each point at the incident edge's corner, or clipped beside
          -- the reference edge's
          points =
            [ ManifoldPoint (midway vLower sepLower) (sepLower - radius) (select (negate lower2) (refKey edge) (incKey i22))
            , ManifoldPoint (midway vUpper sepUpper) (sepUpper - radius) (select (upper2 - upper1) (refKey i12) (incKey incEdge)) ]
      -- the edges' least separation as clipped (none: far)
      clippedMin <- share (select overlapping (minF sepLower sepUpper - radius) 1e300)
      -- Apart (the rounded hulls' cores apart by more than the tolerance),
      -- two corners may be much nearer each other than the clipped edges:
      -- then the one point between them, along the line joining them; and
      -- corners farther apart than the margin make no contact at all.
      let (s, tt, gap) = segmentClosest dot2 v11 v12 v21 v22
      sS <- share s
      tS <- share tt
      gapS <- share gap
      apart <- share (separation - tolerance)
      cornerSep <- share (gapS - radius)
      let atEnds = select (sS * (1 - sS) + tS * (1 - tS)) 0 1
          takeCorners = minF apart (minF (clippedMin - cornerSep - tolerance) (atEnds - 0.5))
      ifPositive (minF apart (cornerSep - margin)) (pure ()) $
        ifPositive takeCorners
          (do pRef <- share2 (lerp v11 v12 sS)
              pInc <- share2 (lerp v21 v22 tS)
              n <- share2 (select gapS (recip gapS) 0 *^ (pInc ^-^ pRef))
              let refCorner = select sS i12 edge
                  incCorner = select tS i22 incEdge
                  -- (keyed by the first shape's corner)
                  firstCorner = if flipped then incKey incCorner else refKey refCorner
                  c1 = pRef ^+^ r1 *^ n
                  c2 = pInc ^-^ r2 *^ n
              emit out margin (orient n) [ManifoldPoint (0.5 *^ (c1 ^+^ c2)) cornerSep firstCorner])
          (whenPositive overlapping (clipped points))

-- | Of hull @h1@'s edges, the one along whose normal @h2@ lies farthest
-- out (the least, over h2's corners, of their distance past the edge's
-- line): that distance, and the edge.
maxSeparation :: Imp m => Hull m -> Hull m -> m (Scalar m, Scalar m)
maxSeparation h1 h2 = do
  best <- newRef (-1e300)
  bestEdge <- newRef 0
  forLoop 0 (toIndex (hullCount h1)) $ \i -> do
    n <- hullNormal h1 i
    v <- hullCorner h1 i
    least <- newRef 1e300
    forLoop 0 (toIndex (hullCount h2)) $ \j -> do
      w <- hullCorner h2 j
      s <- share (dot2 n (w ^-^ v))
      modifyRef least (minF s)
    s <- readRef least
    b0 <- readRef best
    whenPositive (s - b0) (writeRef best s >> writeRef bestEdge (toScalar i))
  (,) <$> readRef best <*> readRef bestEdge

-- | The edge of hull @h@ whose normal is most opposed to @n@.
incidentEdge :: Imp m => V2 (Scalar m) -> Hull m -> m (Scalar m)
incidentEdge n h = do
  least <- newRef 1e300
  edge <- newRef 0
  forLoop 0 (toIndex (hullCount h)) $ \i -> do
    m <- hullNormal h i
    d <- share (dot2 n m)
    l0 <- readRef least
    whenPositive (l0 - d) (writeRef least d >> writeRef edge (toScalar i))
  readRef edge

share2 :: Imp m => V2 (Scalar m) -> m (V2 (Scalar m))
share2 (V2 x y) = V2 <$> share x <*> share y

-- | The closest points of two segments @p0p1@ and @q0q1@ under an inner
-- product (in the plane, or in a space's metric: the segments of a body's
-- rays are space-like): their parameters along each (in [0, 1]) and their
-- distance @√|⟨g, g⟩|@ (branches by 'select', so it stages).
--
-- >>> let (s, t, d) = segmentClosest dot2 (V2 0 0) (V2 2 0) (V2 1 1) (V2 1 3) in (s, t, d :: Double)
-- (0.5,0.0,1.0)
segmentClosest :: (Field a, Additive v) => (v a -> v a -> a) -> v a -> v a -> v a -> v a -> (a, a, a)
segmentClosest dot' p0 p1 q0 q1 =
  let d1 = p1 ^-^ p0
      d2 = q1 ^-^ q0
      r = p0 ^-^ q0
      a = d1 `dot'` d1
      e = d2 `dot'` d2
      f = d2 `dot'` r
      c = d1 `dot'` r
      b = d1 `dot'` d2
      denom = a * e - b * b
      clamp01 = clampF 0 1
      safeDiv x y = select (abs y - 1e-300) (x / y) 0
      s0 = select (denom - 1e-12 * a * e) (clamp01 (safeDiv (b * f - c * e) denom)) 0
      t0 = safeDiv (b * s0 + f) e
      s1 = select (negate t0) (clamp01 (safeDiv (negate c) a)) (select (t0 - 1) (clamp01 (safeDiv (b - c) a)) s0)
      t1 = clamp01 t0
      gap = let g = (p0 ^+^ s1 *^ d1) ^-^ (q0 ^+^ t1 *^ d2) in sqrt (abs (g `dot'` g))
  in (s1, t1, gap)
