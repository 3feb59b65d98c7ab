{-# LANGUAGE FlexibleContexts #-}
-- | A point kept on a body in its own polar coordinates: a geodesic
-- distance from the centre and an angle from the body's direction, so it
-- stays on the body as the body moves and turns. Joints' anchors and the
-- mouse joint's grabbed point are kept so; outline points are traced the
-- same way ("Manifold.Body").
--
-- 'anchorWalk' is the exponential map at the body's centre in
-- 'anchorWalkSteps' geodesic steps, and 'polarOf' is its inverse (the
-- logarithm), found by shooting: a point first taken at its chord's
-- tangent coordinates would come back short by @r − sin r@ on the unit
-- sphere (0.035 for an anchor 0.6 away), and a joint made there would
-- start by pulling its bodies together.
module Manifold.Anchor
  ( anchorWalkSteps
  , anchorWalk
  , anchorPoint
  , AnchorMotion (..)
  , anchorMotion
  , anchorDifference
  , polarOf
  , polarRefinements
  ) where

import Control.Monad (forM_)
import Linear.V3 (V3 (..))
import Linear.Vector ((*^), (^+^), (^-^))

import Manifold.Field
import Manifold.Metric
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.Surface (geodesicStep, tangentProjection, unitNormal)
import Manifold.World

-- | How many geodesic steps walk a body's centre out to an anchor.
anchorWalkSteps :: Int
anchorWalkSteps = 4

-- | Where a body's anchor at polar coordinates @(r, θ)@ is now: the
-- geodesic from its centre, in the direction at angle @θ@ from the body's
-- direction, as long as @r@.
--
-- The same walk as 'anchorWalk', staged as a loop: its geodesic step, with
-- the field's gradient and projection in it, is printed once, not
-- 'anchorWalkSteps' times (a joint's preparation makes eight such walks,
-- and unrolled they were a third of a curved space's compiled step).
anchorPoint :: Imp m => Space -> BodyFrame (Scalar m) -> Scalar m -> Scalar m -> m (V3 (Scalar m))
anchorPoint sp f r theta = walkOut sp r (bfCentre f) (heading f (bfAngle f + theta))

-- | The unit direction at angle @ψ@ from a body's axis.
heading :: Field s => BodyFrame s -> s -> V3 s
heading f psi = cosF psi *^ bfU f ^+^ sinF psi *^ bfW f

-- | The end of the geodesic of length @r@ from @c@ in unit direction @d@,
-- walked in 'anchorWalkSteps' steps of a staged loop.
walkOut :: Imp m => Space -> Scalar m -> V3 (Scalar m) -> V3 (Scalar m) -> m (V3 (Scalar m))
walkOut sp r c dir = do
  let h = r / fromIntegral anchorWalkSteps
  q <- mapM newRef c
  d <- mapM newRef dir
  forEach (fromIntegral anchorWalkSteps) $ \_ -> do
    here <- (,) <$> mapM readRef q <*> mapM readRef d
    let (q1, d1) = geodesicStep (spaceMetric sp) (spaceField sp) h here
    q' <- share3 q1
    d' <- share3 d1
    sequence_ (writeRef <$> q <*> q')
    sequence_ (writeRef <$> d <*> d')
  mapM readRef q

-- | An anchor and how it moves with its body, to first order: per unit of
-- the body's slide along its axis @u@ and along @w@ (the centre moved
-- along the geodesic, the frame carried by projection, as the step moves
-- bodies), and per radian of its turn. On the plane these are @u@, @w@ and
-- the lever turned a quarter (the lever arm of a flat solver); on a curved
-- surface the walk bends them: on the unit sphere an anchor a radian
-- from its body's centre, across the slide's direction, moves only
-- @cos 1@ as far as the centre does, so rows that took the flat lever
-- would see a welded pair turning rigidly about a point between them
-- pulling its anchors apart, and fight the turn.
data AnchorMotion s = AnchorMotion
  { amPoint :: !(V3 s) -- ^ where the anchor is ('anchorPoint')
  , amSlideU :: !(V3 s) -- ^ its move per unit of the body's slide along @u@
  , amSlideW :: !(V3 s) -- ^ along @w@
  , amTurn :: !(V3 s) -- ^ its move per radian of the body's turn
  }

-- | The slide and turn by which 'anchorMotion' differences the walk: small
-- beside the bodies (0.01 to 0.5 units), large beside the rounding of
-- coordinates of order 1 (the differences come out to about 1e-10).
anchorDifference :: Double
anchorDifference = 1e-6

-- | An anchor at polar coordinates @(r, θ)@ of body @f@ and its motion
-- ('AnchorMotion'), by forward differences of the walk: three walks more.
anchorMotion :: Imp m => Space -> BodyFrame (Scalar m) -> Scalar m -> Scalar m -> m (AnchorMotion (Scalar m))
anchorMotion sp f r theta = do
  let metric = spaceMetric sp
      eps = constant anchorDifference
      slid dir = do
        let (c, _) = geodesicStep metric (spaceField sp) eps (bfCentre f, dir)
        c' <- share3 c
        n' <- share3 (unitNormal metric (spaceField sp) c')
        u' <- share3 (normalizeIn metric (tangentProjection metric n' (bfU f)))
        w' <- share3 (perpendicular metric n' u')
        pure f { bfCentre = c', bfNormal = n', bfU = u', bfW = w' }
      rate q p = (/ eps) <$> (q ^-^ p)
  fu <- slid (bfU f)
  fw <- slid (bfW f)
  -- the four walks ('anchorPoint' from the body, from its two slid
  -- frames, and turned by eps) are one staged loop over their starts, so
  -- that the walk is printed once; the loop's counter picks each start
  -- exactly
  let starts = [(f, theta), (fu, theta), (fw, theta), (f, theta + eps)]
  ends <- mapM (const (mapM newRef (bfCentre f))) starts
  forEach (fromIntegral (length starts)) $ \k -> do
    let pick = picked (toScalar k)
        pickV xs = pick <$> sequenceA xs
        frame = f { bfCentre = pickV [bfCentre fr | (fr, _) <- starts]
                  , bfU = pickV [bfU fr | (fr, _) <- starts]
                  , bfW = pickV [bfW fr | (fr, _) <- starts] }
    end <- walkOut sp r (bfCentre frame) (heading frame (pick [bfAngle fr + a | (fr, a) <- starts]))
    forM_ (zip [0 :: Int ..] ends) $ \(j, e) -> do
      old <- mapM readRef e
      sequence_ (writeRef <$> e <*> (select (isIndex (toScalar k) j) <$> end <*> old))
  ps <- mapM (mapM readRef) ends
  let (p, pu, pw, pt) = case ps of
        [a, b, c, d] -> (a, b, c, d)
        _ -> error "anchorMotion: four walks"
  AnchorMotion p <$> share3 (rate pu p) <*> share3 (rate pw p) <*> share3 (rate pt p)

-- | The element of a list at a whole-number index @k@ (0, 1, ...), by
-- exact selection; the last for any index beyond. Staged, a loop's counter
-- picks an element without a branch.
--
-- >>> picked 2 [10, 20, 30, 40 :: Double]
-- 30.0
-- >>> picked 7 [10, 20 :: Double]
-- 20.0
picked :: Field s => s -> [s] -> s
picked k = go 0
  where
    go _ [x] = x
    go j (x : more) = select (isIndex k j) x (go (j + 1) more)
    go _ [] = error "picked: an empty list"

-- | Positive where a whole-number index @k@ is @j@, negative elsewhere: the
-- test 'picked' selects by.
--
-- >>> map (isIndex (2 :: Double)) [1, 2, 3]
-- [-0.5,0.5,-0.5]
isIndex :: Field s => s -> Int -> s
isIndex k j = 0.5 - abs (k - fromIntegral j)

-- | The points of the walk to an anchor at polar coordinates @(r, θ)@
-- ('anchorPoint'): the centre first, the anchor last, 'anchorWalkSteps'
-- geodesic steps between.
anchorWalk :: Imp m => Space -> BodyFrame (Scalar m) -> Scalar m -> Scalar m -> m [V3 (Scalar m)]
anchorWalk sp f r theta = map fst <$> walkHeading sp f r (bfAngle f + theta)

-- | The walk of 'anchorWalk' in the direction at angle @ψ@ from the body's
-- axis (not from its direction), each point with the walk's unit
-- direction there.
walkHeading :: Imp m => Space -> BodyFrame (Scalar m) -> Scalar m -> Scalar m -> m [(V3 (Scalar m), V3 (Scalar m))]
walkHeading sp f r psi = do
  let dir = cosF psi *^ bfU f ^+^ sinF psi *^ bfW f
      h = r / fromIntegral anchorWalkSteps
      go 0 qd = pure [qd]
      go k (q, d) = do
        let (q1, d1) = geodesicStep (spaceMetric sp) (spaceField sp) h (q, d)
        q' <- share3 q1
        d' <- share3 d1
        ((q, d) :) <$> go (k - 1 :: Int) (q', d')
  go anchorWalkSteps (bfCentre f, dir)

-- | How many shooting corrections 'polarOf' makes. Each shrinks the miss
-- by about the walk's departure from a flat one (@r²/6@ on the unit
-- sphere), so a handful reach the walk's own rounding for anchors as far
-- as a body's size, and an anchor a radian away to 1e-8.
polarRefinements :: Int
polarRefinements = 8

-- | The polar coordinates, in body @f@, of a surface point @q@ near it (of
-- its image nearest the centre, on a quotient): those whose 'anchorWalk'
-- ends at @q@. Starting from the chord's coordinates on the body's
-- tangent plane, each of 'polarRefinements' corrections walks out, splits
-- the miss into its part along the walk's end direction (the distance's
-- correction) and across it (the angle's, over the distance: the
-- geodesic circles' length, which is the flat one to second order).
polarOf :: Imp m => Space -> BodyFrame (Scalar m) -> V3 (Scalar m) -> m (Scalar m, Scalar m)
polarOf sp f q = do
  let metric = spaceMetric sp
  -- (the nearest image: on the lattices, of those near the fundamental
  -- domain; on the antipodal quotients, q or −q)
  let quo = spaceQuotient sp
  target <- share3 (fst (nearestImageWith quo (bfCentre f) (nearestImage quo (bfCentre f) q)))
  d <- share3 (target ^-^ bfCentre f)
  x <- share (inner metric d (bfU f))
  y <- share (inner metric d (bfW f))
  radius <- newRef (sqrt (x * x + y * y))
  heading <- newRef (atan2F y x)
  forEach (fromIntegral polarRefinements) $ \_ -> do
    r <- readRef radius
    psi <- readRef heading
    (e, de) <- last <$> walkHeading sp f r psi
    miss <- share3 (target ^-^ e)
    across <- share3 (perpendicular metric (unitNormal metric (spaceField sp) e) de)
    writeRef radius (r + inner metric miss de)
    writeRef heading (psi + select (abs r - constant 1e-12) (inner metric miss across / r) 0)
  r <- readRef radius
  psi <- readRef heading
  -- (a point behind the centre may come out at a negative distance)
  (,) <$> share (abs r) <*> share (select (negate r) (psi + constant pi) psi - bfAngle f)
