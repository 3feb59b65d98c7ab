{-# LANGUAGE FlexibleContexts, LambdaCase #-}
-- | Joints between bodies on a curved surface, as soft rows on the solver's
-- sub-steps (Box2D v3's revolute, distance and weld joints, done on the
-- surface):
--
-- * each anchor is kept in its body's own polar coordinates, a geodesic
--   distance from the centre and an angle from the body's direction (as
--   the mouse joint keeps its grabbed point), so it stays on the body as
--   the body moves and turns; against the world, an anchor is a surface
--   point;
-- * once a step ('prepareJoints') each anchor is walked out along its
--   geodesic and the rows are set up in R³: a pin (revolute, weld) makes
--   the two anchors coincide along body a's two frame directions, a
--   distance joint holds the chord between them along its own direction;
--   a row's Jacobian takes how each anchor moves as its body slides and
--   turns, differenced from the walk ('anchorMotion': on a curved surface
--   not the flat lever arm's, by a part in @r²@ of the curvature);
--   across the sub-steps a row's error is updated from the bodies' moves
--   along its Jacobian, as a contact's depth is;
-- * angles: body b's direction is carried to body a's tangent plane by
--   projection (the paper's transport) and the relative angle is measured
--   there, about a's normal; a weld holds it, a revolute joint's motor
--   drives its rate and its limits bound it;
-- * on a quotient, body b is met through the image whose anchor is
--   nearest body a's ('nearestImageWith'), so a chain may run across the
--   flat torus's edge or the projective plane's antipode; through a
--   mirroring image body b's spin counts reversed ('JSigma'), and when a
--   body is wrapped mirrored into the fundamental domain its anchor angles
--   (and, for body a, the angles the joint is set with) change sign
--   ('wrapJoints').
--
-- Rigid rows are springs of 'JointHertz' (at most a quarter of the sub-step rate)
-- and 'JointDampingRatio' with the bias in the biased solves only; a
-- distance joint's spring and a weld's angular spring have the joint's
-- own frequency and damping ratio and act in every solve.
module Manifold.Joint
  ( addJoint
  , removeJoint
  , forgetBodyJoints
  , prepareJoints
  , warmStartJoints
  , solveJoints
  , wrapJoints
  , jointAnchors
  , jointPaths
  , jointPathPoints
  , chordSegments
  , listPartners
  , notJoined
  , jointProblem
  ) where

import Control.Monad (zipWithM_)
import Linear.Metric (dot)
import Linear.V3 (V3 (..), cross)
import Linear.Vector ((*^), (^+^), (^-^))

import Manifold.Anchor
import Manifold.Field
import Manifold.Metric
import Manifold.Sleep (markIsland)
import Manifold.Soft
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.Surface (projectToSurface, referenceAxis, tangentProjection)
import Manifold.World

-- | A body's direction: its axis turned by its angle about the normal.
direction :: Field s => BodyFrame s -> V3 s
direction f = cosF (bfAngle f) *^ bfU f ^+^ sinF (bfAngle f) *^ bfW f

-- | An angle brought into @(−π, π]@.
wrapAngle :: Field s => s -> s
wrapAngle x = x - constant (2 * pi) * floorF ((x + constant pi) / constant (2 * pi))

-- | What the page and the native engine say when 'addJoint' refuses a
-- joint ('LastJoint' −1, −2, −3), by that code.
jointProblem :: Int -> String
jointProblem = \case
  -1 -> "the world holds as many joints as it can (two a body)"
  -2 -> "an anchor does not project onto the surface (the field's gradient vanishes there)"
  _ -> "a joint joins two different bodies of the world, or a body and the world (b = -1)"

-- | Add a joint of kind @kind@ ('JointKind') between body @a@ and body @b@
-- (−1: the world) with anchors at the surface points @qa@ (on body a) and
-- @qb@ (on body b, or of the world), both projected onto the surface. Its
-- length is the anchors' distance (the chord), its minimum and maximum
-- the same, its reference angle the bodies' relative angle now; the rest
-- is off, and its impulses 0: the caller sets what the joint's
-- description gives ('Manifold.Engine.addJointAt', the page's world).
-- Sets 'LastJoint' to the joint's index, or to −1 (the world is full), −2
-- (an anchor does not project) or −3 (no such bodies, the same body twice,
-- no such kind).
addJoint :: Imp m => Space -> WorldArrays (Array m) -> Scalar m -> Scalar m -> Scalar m
         -> V3 (Scalar m) -> V3 (Scalar m) -> m ()
addJoint sp w kind a b qa qb = do
  count <- readMeta w JointCount
  cap <- readMeta w Capacity
  bodies <- readMeta w BodyCount
  let f = spaceField sp
      whole x = 0.5 - abs (x - floorF (x + 0.5))
      kinds = fromIntegral (fromEnum (maxBound :: JointKind))
      bodiesOk = allPositive'
        [ whole kind, kind + 0.5, kinds + 0.5 - kind
        , whole a, a + 0.5, bodies - a - 0.5
        , whole b, b + 1.5, bodies - b - 0.5
        , abs (a - b) - 0.5 ]
  pa <- share3 (projectToSurface f qa)
  pb <- share3 (projectToSurface f qb)
  ifPositive (fromIntegral (2 :: Int) * maxF 1 cap - count - 0.5)
    (ifPositive bodiesOk
      (ifPositive (minF (finiteness (toList3 pa ++ toList3 pb))
                        (constant onSurfaceTolerance - maxF (abs (evalFn f pa)) (abs (evalFn f pb))))
        (do let j = toIndex count
            mapM_ (\k -> writeJoint w j k 0) [minBound .. maxBound]
            writeJoint w j JKind kind
            writeJoint w j JA a
            writeJoint w j JB b
            fa <- bodyFrame (spaceMetric sp) w (toIndex a)
            (ra, ta) <- polarOf sp fa pa
            writeJoint w j JRadiusA ra
            writeJoint w j JThetaA ta
            writeJoint3 w j JWorldX pb
            whenPositive (b + 0.5) $ do
              fb <- bodyFrame (spaceMetric sp) w (toIndex b)
              (rb, tb) <- polarOf sp fb pb
              writeJoint w j JRadiusB rb
              writeJoint w j JThetaB tb
            writeMeta w JointCount (count + 1)
            writeMeta w LastJoint count
            wakeJoined w j
            -- the length and the reference angle from where the bodies are
            prepareJoint sp w j
            len <- readJoint w j JChord
            isDistance <- share (0.5 - abs (kind - fromIntegral (fromEnum Distance)))
            lenS <- share (select isDistance len 0)
            mapM_ (\k -> writeJoint w j k lenS) [JLength, JMinLength, JMaxLength]
            -- (a distance joint has no angle to hold)
            readJoint w j JAngleError >>= writeJoint w j JReference . select isDistance 0)
        (writeMeta w LastJoint (-2)))
      (writeMeta w LastJoint (-3)))
    (writeMeta w LastJoint (-1))
  where
    allPositive' = foldr (\c rest -> select c rest 0) 1

-- | Run @act@ for joint @j@ when one of its bodies moves: a sleeping
-- island's joints (whose bodies are all asleep, or against the world or a
-- static body) cost nothing.
whenMoving :: Imp m => WorldArrays (Array m) -> Index m -> m () -> m ()
{-# INLINE whenMoving #-}
whenMoving w j act = do
  a <- readJoint w j JA
  b <- readJoint w j JB
  ma <- moving w (toIndex a)
  mb <- moving w (toIndex (maxF 0 b))
  whenPositive (maxF ma (select (b + 0.5) mb 0)) act

-- | Mark the islands of joint @j@'s bodies to wake: a joint made or
-- removed changes what they hold.
wakeJoined :: Imp m => WorldArrays (Array m) -> Index m -> m ()
wakeJoined w j = do
  a <- readJoint w j JA
  b <- readJoint w j JB
  markIsland w (toIndex a)
  whenPositive (b + 0.5) (markIsland w (toIndex b))

-- | Remove joint @j@: the last joint takes its place; its bodies' islands
-- wake.
removeJoint :: Imp m => WorldArrays (Array m) -> Index m -> m ()
removeJoint w j = do
  count <- readMeta w JointCount
  whenPositive (minF (toScalar j + 0.5) (count - toScalar j - 0.5)) $ do
    wakeJoined w j
    let lastJ = toIndex (count - 1)
    mapM_ (\k -> readJoint w lastJ k >>= writeJoint w j k) [minBound .. maxBound]
    writeMeta w JointCount (count - 1)

-- | Body @i@ is removed and the last body, @lastI@, takes its index: the
-- joints of body @i@ go (the others keep their order), and those of the
-- last body follow it.
forgetBodyJoints :: Imp m => WorldArrays (Array m) -> Index m -> Index m -> m ()
forgetBodyJoints w i lastI = do
  count <- readMeta w JointCount
  kept <- newRef 0
  let iS = toScalar i
      lastS = toScalar lastI
      isBody x y = 0.5 - abs (x - y)
  forEach (toIndex count) $ \j -> do
    a <- readJoint w j JA
    b <- readJoint w j JB
    whenPositive (minF (abs (a - iS) - 0.5) (abs (b - iS) - 0.5)) $ do
      k <- readRef kept
      let to = toIndex k
      mapM_ (\field -> readJoint w j field >>= writeJoint w to field) [minBound .. maxBound]
      writeJoint w to JA (select (isBody a lastS) iS a)
      writeJoint w to JB (select (isBody b lastS) iS b)
      writeRef kept (k + 1)
  readRef kept >>= writeMeta w JointCount

-- | Each body's partners ('wPartners'): the bodies it is joined to by a
-- joint that does not let them collide ('JCollide' 0, as Box2D's
-- joints are made), up to 'partnersPerBody' of them.
listPartners :: Imp m => WorldArrays (Array m) -> m ()
listPartners w = do
  bodies <- readMeta w BodyCount
  count <- readMeta w JointCount
  let k = fromIntegral partnersPerBody
  forEach (toIndex bodies * k) $ \s -> writeArray (wPartners w) s (-1)
  forEach (toIndex count) $ \j -> do
    a <- readJoint w j JA
    b <- readJoint w j JB
    collides <- readJoint w j JCollide
    whenPositive (minF (b + 0.5) (0.5 - collides)) $ do
      let add i other = do
            free <- newRef (-1)
            forEach k $ \s -> do
              q <- readArray (wPartners w) (k * i + s)
              f <- readRef free
              whenPositive (minF (negate q) (negate f)) $ writeRef free (toScalar s)
            f <- readRef free
            whenPositive (f + 0.5) $ writeArray (wPartners w) (k * i + toIndex f) other
      add (toIndex a) b
      add (toIndex b) a

-- | 1 unless body @j@ is among the partners @qs@ of a body (then 0).
notJoined :: Field s => [s] -> s -> s
notJoined qs j = foldr (\q rest -> select (abs (q - j) - 0.5) rest 0) 1 qs

-- | Every joint's anchors, rows, errors and masses for this step's
-- sub-steps ('prepareJoint'), and its impulses kept for the warm start
-- (or forgotten, without 'WarmStart').
prepareJoints :: Imp m => Space -> WorldArrays (Array m) -> m ()
prepareJoints sp w = do
  count <- readMeta w JointCount
  warm <- readParam w WarmStart
  forEach (toIndex count) $ \j -> whenMoving w j $ do
    -- a subroutine of its own: the anchors' eight walks over a curved
    -- space's field, inlined into the preparation, made it a function V8
    -- would not optimise, and the contacts' preparation ran unoptimised
    -- with it (half a kilobyte to 200 KB a step on node's heap)
    subroutine "prepareJoint" [toScalar j] $ \case
      [j'] -> prepareJoint sp w (toIndex j')
      _ -> error "prepareJoint: one argument"
    mapM_ (\k -> readJoint w j k >>= writeJoint w j k . (warm *)) impulseFields

impulseFields :: [JointField]
impulseFields = [JImpulse1, JImpulse2, JImpulseAxial, JImpulseLower, JImpulseUpper, JImpulseMotor, JImpulseAngle]

-- | One joint's anchors, levers and rows' directions from where its
-- bodies are now, and its relative angle's error.
prepareJoint :: Imp m => Space -> WorldArrays (Array m) -> Index m -> m ()
prepareJoint sp w j = do
  a <- toIndex <$> readJoint w j JA
  b <- readJoint w j JB
  hasB <- share (select (b + 0.5) 1 0)
  let bi = toIndex (maxF 0 b)
      metric = spaceMetric sp
  fa <- bodyFrame metric w a
  fb <- bodyFrame metric w bi
  ma <- readJoint w j JRadiusA >>= \r -> readJoint w j JThetaA >>= anchorMotion sp fa r
  mb <- readJoint w j JRadiusB >>= \r -> readJoint w j JThetaB >>= anchorMotion sp fb r
  let pA = amPoint ma
  world <- readJoint3 w j JWorldX
  own <- share3 (select hasB <$> amPoint mb <*> world)
  -- (the joints take an image's signs: the quotients with joints map by
  -- diagonal isometries, "Manifold.Scene" refuses joints on the others)
  let (image, linear) = nearestImageWith (spaceQuotient sp) pA own
      V3 (V3 sx _ _) (V3 _ sy _) (V3 _ _ sz) = linear
  pB <- share3 image
  sg <- share3 (V3 sx sy sz)
  writeJoint3 w j JAnchorAX pA
  writeJoint3 w j JAnchorBX pB
  writeJoint3 w j JSlideUAX (amSlideU ma)
  writeJoint3 w j JSlideWAX (amSlideW ma)
  writeJoint3 w j JTurnAX (amTurn ma)
  writeJoint3 w j JSlideUBX (hasB *^ amSlideU mb)
  writeJoint3 w j JSlideWBX (hasB *^ amSlideW mb)
  writeJoint3 w j JTurnBX (hasB *^ amTurn mb)
  writeJoint3 w j JUBX (bfU fb)
  writeJoint3 w j JWBX (bfW fb)
  writeJoint3 w j JSignX sg
  writeJoint3 w j JE1X (bfU fa)
  writeJoint3 w j JE2X (bfW fa)
  writeJoint w j JChord (normIn metric (pB ^-^ pA))
  -- the relative angle: b's direction (through the image) on a's tangent
  -- plane, measured from a's direction about a's normal; against the
  -- world, the surface's reference axis at a stands for b's
  let V3 sx sy sz = sg
  sigma <- share (hasB * sx * sy * sz)
  writeJoint w j JSigma sigma
  dA <- share3 (direction fa)
  t <- share3 (tangentProjection metric (bfNormal fa) (select hasB <$> (sg * direction fb) <*> referenceAxis metric (bfNormal fa)))
  -- (the triple product is the metric's 2-D cross product: 'perpendicular')
  phi <- share (atan2F ((dA `cross` t) `dot` bfNormal fa) (inner metric dA t))
  ref <- readJoint w j JReference
  writeJoint w j JAngleError (wrapAngle (phi - ref))
  iia <- readSlot w a InvInertia
  iib <- (hasB *) <$> readSlot w bi InvInertia
  ka <- share (iia + sigma * sigma * iib)
  writeJoint w j JAngularMass (select ka (recip ka) 0)

-- | A body's velocity and spin, or how far it has moved and turned in this
-- step's sub-steps so far.
data Motion s = Motion !(V3 s) !s

velocityOf, movedOf :: Imp m => WorldArrays (Array m) -> Index m -> m (Motion (Scalar m))
velocityOf w i = Motion <$> read3 (wVel w) i <*> readSlot w i Omega
movedOf w i = Motion <$> (V3 <$> readSlot w i MovedX <*> readSlot w i MovedY <*> readSlot w i MovedZ)
                     <*> readSlot w i Turned

-- | A row's Jacobian: body a's linear and angular part, then body b's.
data Row s = Row !(V3 s) !s !(V3 s) !s

-- | The angular row: the relative angle's rate is σ·ω_b − ω_a.
angularRow :: Num s => s -> Row s
angularRow sigma = Row (V3 0 0 0) (-1) (V3 0 0 0) sigma

-- | How fast a row's error grows (or, given the bodies' moves, how much it
-- has grown).
along :: Field s => Metric -> Row s -> Motion s -> Motion s -> s
along metric (Row la wa lb wb) (Motion va oa) (Motion vb ob) = inner metric la va + wa * oa + inner metric lb vb + wb * ob

-- | The joint's two bodies as the rows need them.
data Pair m = Pair
  { pairA :: Index m
  , pairB :: Index m -- ^ body 0 standing in for the world
  , pairHasB :: Scalar m -- ^ 1 for a body, 0 for the world
  , pairMasses :: (Scalar m, Scalar m, Scalar m, Scalar m) -- ^ inverse masses and inertias: a's, then b's (0 for the world)
  , pairMetric :: Metric -- ^ the space's
  }

pairOf :: Imp m => Metric -> WorldArrays (Array m) -> Index m -> m (Pair m)
pairOf metric w j = do
  a <- toIndex <$> readJoint w j JA
  b <- readJoint w j JB
  hasB <- share (select (b + 0.5) 1 0)
  let bi = toIndex (maxF 0 b)
  ima <- readSlot w a InvMass
  iia <- readSlot w a InvInertia
  imb <- share . (hasB *) =<< readSlot w bi InvMass
  iib <- share . (hasB *) =<< readSlot w bi InvInertia
  pure (Pair a bi hasB (ima, iia, imb, iib) metric)

-- | The mass a row moves: @1 / (J M⁻¹ Jᵀ)@ (0 for a row that moves nothing).
rowMass :: Field s => Metric -> (s, s, s, s) -> Row s -> s
rowMass metric (ima, iia, imb, iib) (Row la wa lb wb) =
  let k = ima * quadranceIn metric la + iia * wa * wa + imb * quadranceIn metric lb + iib * wb * wb
  in select k (recip k) 0

-- | How an anchor moves with its body, as the step's preparation found it
-- ('anchorMotion'), with the body's frame then.
data Mover s = Mover
  { slideU :: !(V3 s), slideW :: !(V3 s), turnBy :: !(V3 s), frameU :: !(V3 s), frameW :: !(V3 s) }

-- | Where a joint's anchors are in the sub-steps: as the step found them,
-- each moved with its body by its 'Mover' (the turn as a rotation about
-- the body's normal of the lever that turns so, so that a fast turn does
-- not leave the anchor behind its linearised move); the vector from a's
-- anchor to b's (b's through the image), the movers with their turning
-- moves turned so too (what the rows take), and the image's signs.
data Geometry s = Geometry
  { gapNow :: !(V3 s), moverA :: !(Mover s), moverB :: !(Mover s), imageSigns :: !(V3 s) }

geometryNow :: Imp m => WorldArrays (Array m) -> Index m -> Pair m -> m (Geometry (Scalar m))
geometryNow w j p = do
  pA0 <- readJoint3 w j JAnchorAX
  pB0 <- readJoint3 w j JAnchorBX
  sg <- readJoint3 w j JSignX
  a <- Mover <$> readJoint3 w j JSlideUAX <*> readJoint3 w j JSlideWAX <*> readJoint3 w j JTurnAX
             <*> readJoint3 w j JE1X <*> readJoint3 w j JE2X
  b <- Mover <$> readJoint3 w j JSlideUBX <*> readJoint3 w j JSlideWBX <*> readJoint3 w j JTurnBX
             <*> readJoint3 w j JUBX <*> readJoint3 w j JWBX
  nA <- read3 (wNormal w) (pairA p)
  nB <- read3 (wNormal w) (pairB p)
  Motion mA tA <- movedOf w (pairA p)
  Motion mB tB <- movedOf w (pairB p)
  (dA, a') <- displacement a nA mA tA
  (dB, b') <- displacement b nB mB tB
  d <- share3 ((pB0 ^+^ pairHasB p *^ (sg * dB)) ^-^ (pA0 ^+^ dA))
  pure (Geometry d a' b' sg)
  where
    metric = pairMetric p
    -- the slide along the frame, and the turn: the tangent part of the
    -- anchor's turning move is a lever turned a quarter, rotated here;
    -- the rest (out of the tangent plane) taken linearly
    displacement mv@(Mover su sw tu u wv) n m t = do
      tangentTurn <- share3 (tangentProjection metric n tu)
      lever <- share3 (negate <$> perpendicular metric n tangentTurn)
      turned <- turn n t lever
      outward <- share3 (tu ^-^ tangentTurn)
      moved <- share3 (inner metric m u *^ su ^+^ inner metric m wv *^ sw ^+^ (turned ^-^ lever) ^+^ t *^ outward)
      turnNow <- share3 (perpendicular metric n turned ^+^ outward)
      pure (moved, mv { turnBy = turnNow })
    -- Rodrigues' rotation about the normal (under the metric: the part
    -- along the normal is kept, the tangent part turned a quarter by
    -- 'perpendicular')
    turn n theta r = do
      c <- share (cosF theta)
      s <- share (sinF theta)
      share3 (c *^ r ^+^ s *^ perpendicular metric n r ^+^ ((1 - c) * constant (normalSign metric) * inner metric n r) *^ n)

-- | The row that moves the anchors apart along direction @e@ (at body a;
-- body b's side through the image): each body's velocity and spin as they
-- move its anchor ('Mover').
rowAlong :: Field s => Metric -> s -> Geometry s -> V3 s -> Row s
rowAlong metric hasB g e =
  let eb = imageSigns g * e
      push m x = inner metric x (slideU m) *^ frameU m ^+^ inner metric x (slideW m) *^ frameW m
  in Row (negate <$> push (moverA g) e) (negate (inner metric e (turnBy (moverA g))))
         (hasB *^ push (moverB g) eb) (hasB * inner metric eb (turnBy (moverB g)))

-- | A distance joint's row (along the anchors' chord) and the chord's length.
chordRow :: Imp m => WorldArrays (Array m) -> Index m -> Pair m -> Geometry (Scalar m) -> m (Row (Scalar m), Scalar m)
chordRow w j p g = do
  len <- share (normIn (pairMetric p) (gapNow g))
  e1 <- readJoint3 w j JE1X
  e <- share3 (select len <$> fmap (/ len) (gapNow g) <*> e1)
  pure (rowAlong (pairMetric p) (pairHasB p) g e, len)

-- | A pin's two rows (along body a's frame) and their errors.
pinRows :: Imp m => WorldArrays (Array m) -> Index m -> Pair m -> Geometry (Scalar m) -> m ((Row (Scalar m), Scalar m), (Row (Scalar m), Scalar m))
pinRows w j p g = do
  e1 <- readJoint3 w j JE1X
  e2 <- readJoint3 w j JE2X
  let row e = (rowAlong (pairMetric p) (pairHasB p) g e, inner (pairMetric p) e (gapNow g))
  pure (row e1, row e2)

-- | The rows' velocity now.
rate :: Imp m => WorldArrays (Array m) -> Pair m -> Row (Scalar m) -> m (Scalar m)
rate w p r = do
  va <- velocityOf w (pairA p)
  vb <- velocityOf w (pairB p)
  share (along (pairMetric p) r va vb)

-- | Apply impulse @lambda@ along a row.
applyImpulse :: Imp m => WorldArrays (Array m) -> Pair m -> Row (Scalar m) -> Scalar m -> m ()
applyImpulse w p (Row la wa lb wb) lambda = do
  let (ima, iia, imb, iib) = pairMasses p
      body i im ii l a = do
        Motion v o <- velocityOf w i
        write3 (wVel w) i (v ^+^ (im * lambda) *^ l)
        writeSlot w i Omega (o + ii * lambda * a)
  body (pairA p) ima iia la wa
  whenPositive (pairHasB p) $ body (pairB p) imb iib lb wb

-- | Every joint's impulses applied again, as a sub-step starts.
warmStartJoints :: Imp m => Metric -> WorldArrays (Array m) -> m ()
warmStartJoints metric w = do
  count <- readMeta w JointCount
  forEach (toIndex count) $ \j -> whenMoving w j $ do
    p <- pairOf metric w j
    g <- geometryNow w j p
    sigma <- readJoint w j JSigma
    kind <- readJoint w j JKind
    isDistance <- share (0.5 - abs (kind - fromIntegral (fromEnum Distance)))
    let impulse = readJoint w j
    i1 <- impulse JImpulse1
    i2 <- impulse JImpulse2
    iAxial <- impulse JImpulseAxial
    iLower <- impulse JImpulseLower
    iUpper <- impulse JImpulseUpper
    iMotor <- impulse JImpulseMotor
    iAngle <- impulse JImpulseAngle
    -- a distance joint's rows all lie along its chord (its limits' too); a
    -- pin's limits and motor are angular
    ifPositive isDistance
      (do (row, _) <- chordRow w j p g
          applyImpulse w p row (iAxial + iLower - iUpper))
      (do ((r1, _), (r2, _)) <- pinRows w j p g
          applyImpulse w p r1 i1
          applyImpulse w p r2 i2
          applyImpulse w p (angularRow sigma) (iMotor + iLower - iUpper + iAngle))

-- | One solve of every joint's rows: with the bias (@useBias@), rigid rows
-- push their error out softly; without it (the relaxing solve), they only
-- hold the velocities. Springs and limits act in both.
solveJoints :: Imp m => Bool -> Metric -> WorldArrays (Array m) -> m ()
solveJoints useBias metric w = do
  count <- readMeta w JointCount
  h <- substepLength w
  invH <- share (recip h)
  hz <- readParam w JointHertz
  zeta <- readParam w JointDampingRatio
  -- no stiffer than a quarter of the sub-step rate, as contacts: a
  -- 50-link chain hanging on the sphere at 200 Hz rang on at four
  -- sub-steps of 1/400 s and settled at eight
  rigid <- softness (minF hz (0.25 * invH)) zeta h
  forEach (toIndex count) $ \j -> whenMoving w j $ do
    p <- pairOf metric w j
    kind <- readJoint w j JKind
    let is k = 0.5 - abs (kind - fromIntegral (fromEnum k))
        -- the coefficients of a rigid row: soft in the biased solve, none in the relaxing one
        (rBias, rMass, rImpulse) = if useBias then (biasRate rigid, massScale rigid, impulseScale rigid) else (0, 1, 0)
        -- a one-sided row (a limit) of error c ≥ 0 wanted: a gap closes
        -- within the sub-step, an overlap is pushed out as a rigid row
        limitRow row mass c field sign = do
          cdot <- (sign *) <$> rate w p row
          gap <- share (select c 1 0)
          bias <- share (select gap (c * invH) (rBias * c))
          ms <- share (select gap 1 rMass)
          is' <- share (select gap 0 rImpulse)
          acc <- readJoint w j field
          new <- share (finiteOr0 (maxF 0 (acc - ms * mass * (cdot + bias) - is' * acc)))
          writeJoint w j field new
          applyImpulse w p row (sign * (new - acc))
        -- a two-sided row of error c with coefficients (bias rate, mass scale, impulse scale)
        softRow row mass c field (b', ms, is') = do
          cdot <- rate w p row
          acc <- readJoint w j field
          lambda <- share (finiteOr0 (negate (ms * mass * (cdot + b' * c)) - is' * acc))
          writeJoint w j field (acc + lambda)
          applyImpulse w p row lambda
        angleNow = do
          Motion _ tA <- movedOf w (pairA p)
          Motion _ tB <- movedOf w (pairB p)
          sigma <- readJoint w j JSigma
          readJoint w j JAngleError >>= \e0 -> share (e0 + sigma * tB - tA)
    sigma <- readJoint w j JSigma
    let angular = angularRow sigma
    angularMass <- readJoint w j JAngularMass
    hzJ <- readJoint w j JHertz
    zetaJ <- readJoint w j JDamping
    spring <- softness hzJ zetaJ h
    springOn <- share (select hzJ 1 0)
    -- revolute: the motor, then the limits (angular rows)
    whenPositive (is Revolute) $ do
      motorOn <- readJoint w j JMotorOn
      whenPositive motorOn $ do
        speed <- readJoint w j JMotorSpeed
        maxImpulse <- (h *) <$> readJoint w j JMaxTorque
        cdot <- rate w p angular
        acc <- readJoint w j JImpulseMotor
        new <- share (finiteOr0 (clampF (negate maxImpulse) maxImpulse (acc - angularMass * (cdot - speed))))
        writeJoint w j JImpulseMotor new
        applyImpulse w p angular (new - acc)
      limitOn <- readJoint w j JLimitOn
      whenPositive limitOn $ do
        angle <- angleNow
        lower <- readJoint w j JLower
        upper <- readJoint w j JUpper
        limitRow angular angularMass (angle - lower) JImpulseLower 1
        limitRow angular angularMass (upper - angle) JImpulseUpper (-1)
    -- weld: the relative angle held (by the joint's spring, if it has one)
    whenPositive (is Weld) $ do
      angle <- angleNow
      ifPositive springOn
        (softRow angular angularMass angle JImpulseAngle (biasRate spring, massScale spring, impulseScale spring))
        (softRow angular angularMass angle JImpulseAngle (rBias, rMass, rImpulse))
    -- revolute and weld: the anchors coincide (the two rows as a 2×2 block)
    whenPositive (maxF (is Revolute) (is Weld)) $ do
      g <- geometryNow w j p
      ((r1, c1), (r2, c2)) <- pinRows w j p g
      let (ima, iia, imb, iib) = pairMasses p
          kOf (Row la wa lb wb) (Row la' wa' lb' wb') =
            ima * inner metric la la' + iia * wa * wa' + imb * inner metric lb lb' + iib * wb * wb'
      k11 <- share (kOf r1 r1)
      k12 <- share (kOf r1 r2)
      k22 <- share (kOf r2 r2)
      det <- share (k11 * k22 - k12 * k12)
      invDet <- share (select det (recip det) 0)
      v1 <- rate w p r1
      v2 <- rate w p r2
      acc1 <- readJoint w j JImpulse1
      acc2 <- readJoint w j JImpulse2
      b1 <- share (v1 + rBias * c1)
      b2 <- share (v2 + rBias * c2)
      l1 <- share (finiteOr0 (negate (rMass * invDet * (k22 * b1 - k12 * b2)) - rImpulse * acc1))
      l2 <- share (finiteOr0 (negate (rMass * invDet * (k11 * b2 - k12 * b1)) - rImpulse * acc2))
      writeJoint w j JImpulse1 (acc1 + l1)
      writeJoint w j JImpulse2 (acc2 + l2)
      applyImpulse w p r1 l1
      applyImpulse w p r2 l2
    -- distance: the spring or the rigid length, then the two limits
    whenPositive (is Distance) $ do
      g <- geometryNow w j p
      (row, len) <- chordRow w j p g
      mass <- share (rowMass metric (pairMasses p) row)
      target <- readJoint w j JLength
      lo <- readJoint w j JMinLength
      hi <- readJoint w j JMaxLength
      ifPositive springOn
        (softRow row mass (len - target) JImpulseAxial (biasRate spring, massScale spring, impulseScale spring))
        (whenPositive (lo - hi + 0.5e-12 * (1 + hi)) $
           softRow row mass (len - target) JImpulseAxial (rBias, rMass, rImpulse))
      whenPositive (hi - lo) $ do
        limitRow row mass (len - lo) JImpulseLower 1
        limitRow row mass (hi - len) JImpulseUpper (-1)

-- | After the bodies were wrapped into the fundamental domain: a body
-- that came back mirrored ('wFlip' −1) has its anchor's angle mirrored; a
-- mirrored body a measures the relative angle the other way round, so the
-- joint's angles (reference, limits, motor speed) and angular impulses
-- change sign with it, and so does the impulse of the row along a's
-- second frame direction (normal × axis, which the mirror reverses).
wrapJoints :: Imp m => Space -> WorldArrays (Array m) -> m ()
wrapJoints sp w = case quotientWrap (spaceQuotient sp) :: Maybe (V3 Double -> Wrapped Double) of
  Nothing -> pure ()
  Just _ -> do
    count <- readMeta w JointCount
    forEach (toIndex count) $ \j -> do
      a <- toIndex <$> readJoint w j JA
      b <- readJoint w j JB
      sA <- readArray (wFlip w) a
      sB <- readArray (wFlip w) (toIndex (maxF 0 b))
      let scale field s = readJoint w j field >>= writeJoint w j field . (s *)
      scale JThetaA sA
      whenPositive (b + 0.5) $ scale JThetaB sB
      whenPositive (negate sA) $ do
        mapM_ (\k -> scale k (-1)) [JReference, JMotorSpeed, JImpulseMotor, JImpulseAngle, JImpulse2]
        lower <- readJoint w j JLower
        upper <- readJoint w j JUpper
        writeJoint w j JLower (negate upper)
        writeJoint w j JUpper (negate lower)
        iLower <- readJoint w j JImpulseLower
        iUpper <- readJoint w j JImpulseUpper
        writeJoint w j JImpulseLower iUpper
        writeJoint w j JImpulseUpper iLower

-- | Where every joint's two anchors are now (body b's through the image
-- nearest body a's anchor), into @out@: six numbers a joint.
jointAnchors :: Imp m => Space -> WorldArrays (Array m) -> Array m -> m ()
jointAnchors sp w out = do
  count <- readMeta w JointCount
  forEach (toIndex count) $ \j -> do
    (_, _, pa, pb) <- walksOf sp w j
    writePoints out (6 * j) [pa, pb]

-- | How many segments draw a distance joint's chord ('jointPaths').
chordSegments :: Int
chordSegments = 8

-- | The points 'jointPaths' gives a joint: each anchor's walk, then the chord.
jointPathPoints :: Int
jointPathPoints = 2 * (anchorWalkSteps + 1) + chordSegments + 1

-- | Every joint as curves on the surface, for drawing, into @out@ (3 ×
-- 'jointPathPoints' numbers a joint): the geodesic walk from body a's
-- centre to its anchor, body b's (in its own place; against the world,
-- the world point repeated), and the chord from a's anchor to b's (through
-- the image nearest a's) projected onto the surface, which on the sphere
-- is the great circle's arc between them. A pin is drawn by the walks, a
-- distance joint by its chord.
jointPaths :: Imp m => Space -> WorldArrays (Array m) -> Array m -> m ()
jointPaths sp w out = do
  count <- readMeta w JointCount
  forEach (toIndex count) $ \j -> do
    (walkA, walkB, pa, pb) <- walksOf sp w j
    let chord = [ projectToSurface (spaceField sp) (pa ^+^ (fromIntegral k / fromIntegral chordSegments) *^ (pb ^-^ pa))
                | k <- [0 .. chordSegments] ]
    writePoints out (fromIntegral (3 * jointPathPoints) * j) (walkA ++ walkB ++ chord)

-- | Joint @j@'s two anchor walks (body b's in its own place, or the world
-- point) and its anchors, body b's through the image nearest body a's.
walksOf :: Imp m => Space -> WorldArrays (Array m) -> Index m -> m ([V3 (Scalar m)], [V3 (Scalar m)], V3 (Scalar m), V3 (Scalar m))
walksOf sp w j = do
  a <- toIndex <$> readJoint w j JA
  b <- readJoint w j JB
  hasB <- share (select (b + 0.5) 1 0)
  fa <- bodyFrame (spaceMetric sp) w a
  fb <- bodyFrame (spaceMetric sp) w (toIndex (maxF 0 b))
  walkA <- readJoint w j JRadiusA >>= \r -> readJoint w j JThetaA >>= anchorWalk sp fa r
  walkBody <- readJoint w j JRadiusB >>= \r -> readJoint w j JThetaB >>= anchorWalk sp fb r
  world <- readJoint3 w j JWorldX
  walkB <- mapM (\q -> share3 (select hasB <$> q <*> world)) walkBody
  let pa = last walkA
      (image, _) = nearestImageWith (spaceQuotient sp) pa (last walkB)
  pb <- share3 image
  pure (walkA, walkB, pa, pb)

-- | Points into @out@ from index @at@ on, three numbers each.
writePoints :: Imp m => Array m -> Index m -> [V3 (Scalar m)] -> m ()
writePoints out at ps =
  zipWithM_ (\k x -> writeArray out (at + fromIntegral k) x) [0 :: Int ..] (concatMap (\(V3 x y z) -> [x, y, z]) ps)
