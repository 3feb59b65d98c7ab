{-# OPTIONS_GHC -fllvm #-}
{-# LANGUAGE FlexibleContexts #-}
{-# LANGUAGE LambdaCase #-}
-- Built with LLVM (as the compiled steps are): the generic native step's
-- solve is a tenth faster so (manifold bench --generic, settled piles).

-- | The soft step (paper §2.5, done as Box2D v3 and Rapier do it): the
-- contacts are found once a step; then each of the step's sub-steps applies
-- gravity, warm starts every contact row with its impulses, solves the rows
-- with a soft bias that pushes overlapping bodies apart, moves the bodies
-- along the surface, and relaxes (solves the rows again without the bias,
-- so that the push-out leaves no velocity behind). Restitution is applied
-- once, after the sub-steps.
--
-- Every contact is a normal row (relative normal velocity ≥ 0, clamped
-- non-negative) and a Coulomb friction row (clamped by @μ·λn@). A body's
-- velocity lives in its tangent plane and its angular velocity is about the
-- surface normal, so a row's Jacobian for a body is the contact direction
-- projected to the body's tangent plane and @(r × n)·normal@. Across the
-- sub-steps a contact's depth is updated from its bodies' moves (their
-- velocities times time, 'MovedX' … 'Turned', along its Jacobian) without
-- finding the contacts again.
--
-- Softness (Catto, "Solver2D"): a contact is a spring of frequency
-- 'ContactHertz' and damping ratio 'DampingRatio' (twice the frequency
-- against a static body or a wall), with @ω = 2πf@, @a₁ = 2ζ + hω@,
-- @a₂ = hω·a₁@, @a₃ = 1/(1 + a₂)@: the bias is @ω/a₁@ times the depth
-- beyond the slop (at most 'Pushout'), and an impulse is scaled by @a₂a₃@
-- with @a₃@ of the accumulated impulse taken back. A depth short of the
-- slop is a hard row that lets the bodies approach by what is left of it
-- within the sub-step; from the slop to twice the slop the row turns from
-- hard to soft gradually, so that nothing it does jumps with the depth.
-- The slop is 'Slop' times the smaller body's size, so that small bodies
-- overlap as little, for their size, as large ones.
--
-- The mouse joint is a soft constraint too (its own frequency and damping
-- ratio, a force limit), pulling a point of a body towards a target, solved
-- with the contacts in every sub-step.
module Manifold.Solver
  ( prepareContacts
  , substeps
  , finishStep
  , grabPoint
  ) where

import Control.Monad (forM_)
import Linear.Metric (dot)
import Linear.V3 (V3 (..), cross)
import Linear.Vector ((*^), (^+^), (^-^))

import Manifold.Anchor (anchorPoint)
import Manifold.Field
import Manifold.Joint
import Manifold.Metric
import Manifold.Soft
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.World

-- | A body's velocity state.
data Vel s = Vel !(V3 s) !s

readVel :: Imp m => WorldArrays (Array m) -> Index m -> m (Vel (Scalar m))
{-# INLINE readVel #-}
readVel w i = Vel <$> read3 (wVel w) i <*> readSlot w i Omega

-- | How far a body has moved and turned in this step's sub-steps so far.
readMoved :: Imp m => WorldArrays (Array m) -> Index m -> m (Vel (Scalar m))
{-# INLINE readMoved #-}
readMoved w i = Vel <$> (V3 <$> readSlot w i MovedX <*> readSlot w i MovedY <*> readSlot w i MovedZ)
                    <*> readSlot w i Turned

-- | Push body @i@ with impulse @lambda@ along a Jacobian (linear part,
-- angular part).
push :: Imp m => WorldArrays (Array m) -> Index m -> Scalar m -> V3 (Scalar m) -> Scalar m -> m ()
{-# INLINE push #-}
push w i lambda j jw = do
  im <- readSlot w i InvMass
  ii <- readSlot w i InvInertia
  Vel v om <- readVel w i
  write3 (wVel w) i (v ^+^ (im * lambda) *^ j)
  writeSlot w i Omega (om + ii * lambda * jw)

-- | The two sides of a row of contact @c@ starting at field @lin@ (Ja or Ta)
-- and @linB@ (Jb or Tb).
data Row s = Row { rowA :: !(V3 s), rowAW :: !s, rowB :: !(V3 s), rowBW :: !s }

readRow :: Imp m => WorldArrays (Array m) -> Index m -> ContactField -> ContactField -> m (Row (Scalar m))
{-# INLINE readRow #-}
readRow w c linA linB = do
  a <- readContact3 w c linA
  aw <- readContact w c (succ (succ (succ linA)))
  b <- readContact3 w c linB
  bw <- readContact w c (succ (succ (succ linB)))
  pure (Row a aw b bw)

-- | How fast body a's, and body b's, side of a row moves (or, given how far
-- the body moved, how far it went along the row).
sideA, sideB :: Field s => Metric -> Row s -> Vel s -> s
{-# INLINE sideA #-}
{-# INLINE sideB #-}
sideA metric r (Vel v o) = inner metric (rowA r) v + rowAW r * o
sideB metric r (Vel v o) = inner metric (rowB r) v + rowBW r * o

-- | The relative velocity along a row: body a's minus body b's.
rowVelocity :: Imp m => Metric -> WorldArrays (Array m) -> Index m -> Scalar m -> Row (Scalar m) -> m (Scalar m)
{-# INLINE rowVelocity #-}
rowVelocity metric w a b r = do
  va <- readVel w a
  vb <- newRef 0
  whenPositive (b + 0.5) $ readVel w (toIndex b) >>= writeRef vb . sideB metric r
  vB <- readRef vb
  share (sideA metric r va - vB)

applyRow :: Imp m => WorldArrays (Array m) -> Index m -> Scalar m -> Row (Scalar m) -> Scalar m -> m ()
{-# INLINE applyRow #-}
applyRow w a b r lambda = do
  push w a lambda (rowA r) (rowAW r)
  whenPositive (b + 0.5) $ push w (toIndex b) (negate lambda) (rowB r) (rowBW r)

-- | The effective mass of a row: @1 / (J M⁻¹ Jᵀ)@.
effectiveMass :: Imp m => Metric -> WorldArrays (Array m) -> Index m -> Scalar m -> Row (Scalar m) -> m (Scalar m)
{-# INLINE effectiveMass #-}
effectiveMass metric w a b r = do
  ima <- readSlot w a InvMass
  iia <- readSlot w a InvInertia
  kb <- newRef 0
  whenPositive (b + 0.5) $ do
    imb <- readSlot w (toIndex b) InvMass
    iib <- readSlot w (toIndex b) InvInertia
    writeRef kb (imb * quadranceIn metric (rowB r) + iib * rowBW r * rowBW r)
  kB <- readRef kb
  k <- share (ima * quadranceIn metric (rowA r) + iia * rowAW r * rowAW r + kB)
  share (select k (recip k) 0)

-- | Where a grabbed body's grabbed point is now: the geodesic from its
-- centre in the grabbed direction, as long as the grabbed distance.
grabPoint :: Imp m => Space -> WorldArrays (Array m) -> Index m -> m (V3 (Scalar m))
grabPoint sp w g = do
  f <- bodyFrame (spaceMetric sp) w g
  r <- readMouse w MLocalR
  theta <- readMouse w MLocalTheta
  anchorPoint sp f r theta

-- | The mouse joint's rows along the body's frame vectors: with @warm@,
-- its impulses applied again (the warm start of a sub-step); otherwise one
-- soft solve of each row.
mouseRows :: Imp m => Space -> WorldArrays (Array m) -> Bool -> m ()
-- A subroutine of its own: inlined at its three calls a sub-step, with the
-- grabbed point's geodesic walk over the cube's field, it made the
-- sub-steps a function V8 would not optimise (224 bytes a step on node's
-- heap, the allocation guard).
mouseRows sp w warm =
  subroutine "mouseJoint" [if warm then 1 else 0] $ \case
    [warmS] -> mouseJoint sp w warmS
    _ -> error "mouseJoint: one argument"

-- | 'mouseRows' with the warm start as a number (above 0: warm start).
mouseJoint :: Imp m => Space -> WorldArrays (Array m) -> Scalar m -> m ()
mouseJoint sp w warm = do
  active <- readMouse w MActive
  whenPositive active $ do
    gS <- readMouse w MBody
    let g = toIndex gS
    im <- readSlot w g InvMass
    whenPositive im $ do
      ii <- readSlot w g InvInertia
      h <- substepLength w
      let metric = spaceMetric sp
      f <- bodyFrame metric w g
      grab <- grabPoint sp w g
      target0 <- V3 <$> readMouse w MTargetX <*> readMouse w MTargetY <*> readMouse w MTargetZ
      -- on a lattice, towards the target's image nearest the grabbed point
      target <- share3 (nearestImage (spaceQuotient sp) grab target0)
      hz <- readMouse w MFrequency
      zeta <- readMouse w MDamping
      maxForce <- readMouse w MMaxForce
      soft <- softness hz zeta h
      rw <- share3 (grab ^-^ bfCentre f)
      err <- share3 (grab ^-^ target)
      let row e field = do
            let jw = (rw `cross` e) `dot` bfNormal f
            acc <- readMouse w field
            ifPositive warm (push w g acc e jw) $ do
                Vel v o <- readVel w g
                let cdot = inner metric e v + jw * o
                    k = im * quadranceIn metric e + ii * jw * jw
                    lambda = negate (massScale soft * (cdot + biasRate soft * inner metric err e) / k)
                             - impulseScale soft * acc
                    limit = maxForce * h
                    acc' = finiteOr0 (clampF (negate limit) limit (acc + lambda))
                accS <- share acc'
                writeMouse w field accS
                push w g (accS - acc) e jw
      row (bfU f) MImpulseU
      row (bfW f) MImpulseW

-- | Each contact row's masses, softness, depth beyond the slop and normal
-- velocity, and its impulses warm started from the last step's row of the
-- same key (applied by each sub-step's 'warmStart'); every body's moves
-- since the contacts were found set to none.
prepareContacts :: Imp m => Metric -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE prepareContacts :: Metric -> WorldArrays NativeArray -> Native () #-}
prepareContacts metric w = do
  h <- substepLength w
  hz <- readParam w ContactHertz
  zeta <- readParam w DampingRatio
  slop <- readParam w Slop
  warm <- readParam w WarmStart
  -- no stiffer than a quarter of the sub-step rate (Box2D's limit: stiffer
  -- springs are not resolved by the sub-steps and ring)
  hzC <- share (minF hz (0.25 / h))
  moving <- softness hzC zeta h
  static <- softness (2 * hzC) zeta h
  sceneMu <- readParam w Friction
  sceneE <- readParam w Restitution
  bodies <- readMeta w BodyCount
  forEach (toIndex bodies) $ \i -> mapM_ (\s -> writeSlot w i s 0) [MovedX, MovedY, MovedZ, Turned]
  nc <- readMeta w ContactCount
  forEach (toIndex nc) $ \c -> do
    a <- toIndex <$> readContact w c CA
    b <- readContact w c CB
    owner <- readContact w c COwner
    key <- readContact w c CKey
    normal <- readRow w c JaX JbX
    tangent <- readRow w c TaX TbX
    kn <- effectiveMass metric w a b normal
    kt <- effectiveMass metric w a b tangent
    writeContact w c NormalMass kn
    writeContact w c TangentMass kt
    -- against a wall, a static body or itself (b = -1) the stiffer spring
    bIx <- share (maxF 0 b)
    ima <- readSlot w a InvMass
    imb <- readSlot w (toIndex bIx) InvMass
    sizeA <- readSlot w a Size
    sizeB <- readSlot w (toIndex bIx) Size
    dynamicPair <- share (select (b + 0.5) (ima * imb) 0)
    let pick field f = writeContact w c field (select dynamicPair (f moving) (f static))
    pick CBiasRate biasRate
    pick CMassScale massScale
    pick CImpulseScale impulseScale
    -- the pair's material, mixed as Box2D mixes it (a wall, or a body
    -- that does not say, has the scene's)
    let material slot sceneValue body = do
          x <- readSlot w body slot
          share (select (x + 0.5) x sceneValue)
    muA <- material BodyFriction sceneMu a
    muB <- material BodyFriction sceneMu (toIndex bIx)
    eA <- material BodyRestitution sceneE a
    eB <- material BodyRestitution sceneE (toIndex bIx)
    hasB <- share (b + 0.5)
    writeContact w c CFriction (sqrt (muA * select hasB muB sceneMu))
    writeContact w c CRestitution (maxF eA (select hasB eB sceneE))
    depth <- readContact w c CDepth
    writeContact w c CPenetration (depth - slop * select (b + 0.5) (minF sizeA sizeB) sizeA)
    rowVelocity metric w a b normal >>= writeContact w c CApproach
    writeContact w c CTotalImpulse 0
    ln <- newRef 0
    lt <- newRef 0
    start <- readArray (wBodyPrev w) (2 * toIndex owner)
    count <- readArray (wBodyPrev w) (2 * toIndex owner + 1)
    forLoop (toIndex start) (toIndex (start + count)) $ \k -> do
      pk <- readPrev w k PrevKey
      whenPositive (0.5 - abs (pk - key)) $ do
        readPrev w k PrevNormal >>= writeRef ln
        readPrev w k PrevFriction >>= writeRef lt
    readRef ln >>= writeContact w c ImpulseN . (warm *)
    readRef lt >>= writeContact w c ImpulseT . (warm *)

-- | The step's sub-steps (their number is the 'Substeps' parameter), each:
-- gravity, the warm start, 'Iterations' solves with the bias, the move
-- along the surface, one relaxing solve without it.
substeps :: Imp m => Space -> Layout -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE substeps :: Space -> Layout -> WorldArrays NativeArray -> Native () #-}
substeps sp _ w = do
  n <- readParam w Substeps
  iterations <- readParam w Iterations
  -- decided once a step (it differentiates the field symbolically), not
  -- in every sweep of the generic step
  let shape = rowShape sp
  -- Each stage is printed as a function of its own: V8 optimised the
  -- whole solver as one function only sometimes. In a page that had run a
  -- torus of 3000 bodies, Chromium's optimising compiler gave up on the
  -- rectangle's solver as "too big to be optimized" and never tried again,
  -- and the page's solve then took 100 ms a step instead of 5 (node
  -- bench/browser.mjs, the rectangle after the torus).
  -- the joints before the contacts in each pass (as Box2D orders them)
  forEach (toIndex n) $ \_ -> do
    subroutine "substepGravity" [] $ \_ -> substepLength w >>= applyGravity sp w
    subroutine "warmStartJoints" [] $ \_ -> warmStartJoints (spaceMetric sp) w
    subroutine "warmStart" [] $ \_ -> warmStart shape w
    mouseRows sp w True
    forEach (toIndex iterations) $ \_ -> do
      subroutine "solveJoints" [] $ \_ -> solveJoints True (spaceMetric sp) w
      subroutine "solveSweep" [] $ \_ -> sweepRows True shape w
      mouseRows sp w False
    subroutine "substepMove" [] $ \_ -> substepLength w >>= integrate sp w
    subroutine "relaxJoints" [] $ \_ -> solveJoints False (spaceMetric sp) w
    subroutine "relaxSweep" [] $ \_ -> sweepRows False shape w
    mouseRows sp w False

-- | Every contact's impulses applied again, as the sub-step starts.
--
-- Where a row's two sides cannot be one body ('rsSelfImages'), each body's
-- velocity is read once and written once for both rows (the same sums in
-- the same order as row by row through memory).
warmStart :: Imp m => RowShape -> WorldArrays (Array m) -> m ()
{-# INLINE warmStart #-}
warmStart shape w = do
  nc <- readMeta w ContactCount
  forEach (toIndex nc) $ \c -> do
    a <- toIndex <$> readContact w c CA
    b <- readContact w c CB
    normal <- readRow w c JaX JbX
    tangent <- readRow w c TaX TbX
    ln <- readContact w c ImpulseN
    lt <- readContact w c ImpulseT
    if rsSelfImages shape
      then do
        applyRow w a b normal ln
        applyRow w a b tangent lt
      else do
        -- one body's side of both rows: its velocity read, pushed along
        -- the normal row by @n@ and then along the friction row by @t@
        let both i n t side sideW = do
              im <- readSlot w i InvMass
              ii <- readSlot w i InvInertia
              vel0 <- readVel w i
              let pushed (Vel v om) row l = Vel (v ^+^ (im * l) *^ side row) (om + ii * l * sideW row)
                  {-# INLINE pushed #-}
              case pushed (pushed vel0 normal n) tangent t of
                Vel v2 om2 -> write3 (wVel w) i v2 >> writeSlot w i Omega om2
            {-# INLINE both #-}
        both a ln lt rowA rowAW
        whenPositive (b + 0.5) $ both (toIndex b) (negate ln) (negate lt) rowB rowBW
    readContact w c CTotalImpulse >>= writeContact w c CTotalImpulse . (+ ln)

-- | What a space's rows can be, known before the step is staged: its
-- metric; whether a body can meet its own image (only in a quotient), so
-- that a row's two sides are one body; whether every row is a unit long
-- (a space whose field has a constant gradient, a flat one: a row is a
-- direction in the plane).
data RowShape = RowShape { rsMetric :: Metric, rsSelfImages :: Bool, rsUnitRows :: Bool }

-- | The rows' shape on a space.
rowShape :: Space -> RowShape
rowShape sp = RowShape
  { rsMetric = spaceMetric sp
  , rsSelfImages = not (null (quotientImages (spaceQuotient sp)))
  , rsUnitRows = hasConstantGradient (spaceField sp) }

-- | One sequential-impulse sweep over the contact rows, each clamped: with
-- the bias, the normal impulses (the solve); without it, the normal
-- impulse and then friction, bounded by the normal impulse just found (the
-- relaxing solve). What can never happen on the space is left out of the
-- staged sweep ('RowShape'): the page's relaxing sweep on the rectangle is
-- an eighth quicker without the self-image sums.
sweepRows :: Imp m => Bool -> RowShape -> WorldArrays (Array m) -> m ()
{-# INLINE sweepRows #-}
sweepRows useBias (RowShape metric selfImages unitRows) w = do
  pushout <- readParam w Pushout
  h <- substepLength w
  invH <- share (recip h)
  nc <- readMeta w ContactCount
  forEach (toIndex nc) $ \c -> do
    a <- toIndex <$> readContact w c CA
    b <- readContact w c CB
    normal <- readRow w c JaX JbX
    scale <- readContact w c CSelfScale
    ln <- readContact w c ImpulseN
    kn <- readContact w c NormalMass
    penetration <- readContact w c CPenetration
    -- both bodies' velocities are read once and written once (a row
    -- without body b has zero Jacobians on its side: body 0 stands in);
    -- when a body meets its own image (a = b) each side's change is
    -- added to the other's copy too, so both copies stay the body's
    bIx <- share (maxF 0 b)
    let bi = toIndex bIx
    hasB <- share (b + 0.5)
    same <- if selfImages then share (select (0.5 - abs (toScalar a - b)) 1 0) else pure 0
    ima <- readSlot w a InvMass
    iia <- readSlot w a InvInertia
    imb <- readSlot w bi InvMass
    iib <- readSlot w bi InvInertia
    va0 <- readVel w a
    vb0 <- readVel w bi
    -- inlined: lifted out as functions of their own, the generic
    -- (native, uncompiled) step boxed every row and velocity it passed
    let along r va vb = share (sideA metric r va - select hasB (sideB metric r vb) 0)
        {-# INLINE along #-}
        apply r lambda (Vel va oa) (Vel vb ob) = do
          dva <- share3 ((ima * lambda) *^ rowA r)
          doa <- share (iia * lambda * rowAW r)
          dvb <- share3 ((imb * negate lambda) *^ rowB r)
          dob <- share (iib * negate lambda * rowBW r)
          let mixed x own other = if selfImages then x + own + same * other else x + own
              {-# INLINE mixed #-}
          va' <- share3 (mixed <$> va <*> dva <*> dvb)
          oa' <- share (mixed oa doa dob)
          vb' <- share3 (mixed <$> vb <*> dvb <*> dva)
          ob' <- share (mixed ob dob doa)
          pure (Vel va' oa', Vel vb' ob')
        {-# INLINE apply #-}
    -- the depth now: as found, less how far the bodies have since moved
    -- apart along the normal row
    movedA <- readMoved w a
    movedB <- readMoved w bi
    apart <- along normal movedA movedB
    separation <- share (apart - penetration)
    (bias, ms, is) <- if useBias
      then do
        biasRateC <- readContact w c CBiasRate
        msC <- readContact w c CMassScale
        isC <- readContact w c CImpulseScale
        -- push-out is a speed of the bodies, and a row shorter than a unit
        -- moves them by more than its own speed: its push lies far from a
        -- body's tangent plane (two bodies on either side of a neck narrower
        -- than they are wide, whose line runs through the neck), and at
        -- the push-out of its own units it threw both bodies up the neck
        -- at 1.4 a second, pumping a jammed pile; rows within a percent of
        -- a unit, every row on a flat space, are left as they were
        reachScale <- if unitRows then pure 1 else do
          reach <- share (maxF (quadranceIn metric (rowA normal)) (quadranceIn metric (rowB normal)))
          pure (select (reach - 0.99) 1 (sqrt reach))
        soft <- share (maxF (biasRateC * separation) (negate pushout * reachScale))
        -- A gap is a hard row, an overlap beyond the slop a soft one; in
        -- between, over the slop's width, the row turns soft gradually.
        -- (Switched at 0, as Box2D does, a resting contact, which sits at
        -- 0, was kicked between the two by its last bits: the native and
        -- the emitted step parted by 1e-4 within 60 steps of a pile.)
        depth <- readContact w c CDepth
        slopC <- share (depth - penetration)
        softer <- share (clampF 0 1 (select slopC (negate separation / slopC) 1))
        pure ( select separation (separation * invH) soft
             , 1 - softer * (1 - msC)
             , softer * isC )
      else pure (select separation (separation * invH) 0, 1, 0)
    vn <- along normal va0 vb0
    -- a self-contact's row is scaled (0.6, the paper's) when it pushes, not
    -- when it relaxes: a relaxing sweep scaled so kept 0.4 of the push-out
    -- speed, and a square jammed alone bounced off its own jam
    let scaleN = if useBias then scale else 1
    ln' <- share (finiteOr0 (maxF 0 (ln + scaleN * (negate (kn * ms * (vn + bias)) - is * ln))))
    writeContact w c ImpulseN ln'
    readContact w c CTotalImpulse >>= writeContact w c CTotalImpulse . (+ (ln' - ln))
    (va1, vb1) <- apply normal (ln' - ln) va0 vb0
    -- friction in the relaxing solve only (as Box2D v3 does now): the
    -- biased solve's normal impulse still holds the push-out (its friction
    -- row is left as it is, not applied as a change of zero)
    (Vel va2 oa2, Vel vb2 ob2) <- if useBias then pure (va1, vb1) else do
      tangent <- readRow w c TaX TbX
      lt <- readContact w c ImpulseT
      kt <- readContact w c TangentMass
      vt <- along tangent va1 vb1
      mu <- readContact w c CFriction
      let limit = mu * ln'
      lt' <- share (finiteOr0 (clampF (negate limit) limit (lt - scale * vt * kt)))
      writeContact w c ImpulseT lt'
      apply tangent (lt' - lt) va1 vb1
    write3 (wVel w) a va2
    writeSlot w a Omega oa2
    whenPositive hasB $ do
      write3 (wVel w) bi vb2
      writeSlot w bi Omega ob2

-- | The end of the step's solve: restitution (once, for the contacts that
-- approached faster than 'BounceThreshold' before the step and pushed),
-- the impulses kept for the next step's warm start, every velocity back in
-- its tangent plane ('tangentVelocities') and every body back into the
-- fundamental domain.
finishStep :: Imp m => Space -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE finishStep :: Space -> WorldArrays NativeArray -> Native () #-}
finishStep sp w = do
  subroutine "restitution" [] $ \_ -> restitute (spaceMetric sp) w
  rememberImpulses (spaceMetric sp) w
  tangentVelocities sp w
  wrapIntoDomain sp w
  wrapJoints sp w

-- | The restitution impulses: a contact that approached at @v < -threshold@
-- leaves at @−e·v@, @e@ the pair's restitution (none where it is 0).
restitute :: Imp m => Metric -> WorldArrays (Array m) -> m ()
{-# INLINE restitute #-}
restitute metric w = do
  threshold <- readParam w BounceThreshold
  nc <- readMeta w ContactCount
  forEach (toIndex nc) $ \c -> do
    approach <- readContact w c CApproach
    total <- readContact w c CTotalImpulse
    e <- readContact w c CRestitution
    whenPositive (minF e (minF (negate approach - threshold) total)) $ do
      a <- toIndex <$> readContact w c CA
      b <- readContact w c CB
      normal <- readRow w c JaX JbX
      kn <- readContact w c NormalMass
      scale <- readContact w c CSelfScale
      ln <- readContact w c ImpulseN
      vn <- rowVelocity metric w a b normal
      ln' <- share (finiteOr0 (maxF 0 (ln - scale * kn * (vn + e * approach))))
      writeContact w c ImpulseN ln'
      applyRow w a b normal (ln' - ln)

-- | The impulses, grouped by owner, for the next step's warm start; and
-- of a row the next step may keep ("Manifold.Collide"), its depth at the
-- step's end (as found, less how far the bodies moved apart along its
-- normal row: what a next sub-step would see), the pair's drift and its
-- bodies' turns with this step's added, and its point and rows.
rememberImpulses :: Imp m => Metric -> WorldArrays (Array m) -> m ()
{-# INLINE rememberImpulses #-}
rememberImpulses metric w = do
  nc <- readMeta w ContactCount
  bodies <- readMeta w BodyCount
  forEach (toIndex bodies) $ \i -> writeArray (wBodyPrev w) (2 * i + 1) 0
  forEach (toIndex nc) $ \c -> do
    owner <- toIndex <$> readContact w c COwner
    writePrev w c PrevOwner (toScalar owner)
    readContact w c CKey >>= writePrev w c PrevKey
    readContact w c ImpulseN >>= writePrev w c PrevNormal
    readContact w c ImpulseT >>= writePrev w c PrevFriction
    kept <- readContact w c CKept
    writePrev w c PrevKept kept
    whenPositive kept $ do
      a <- toIndex <$> readContact w c CA
      b <- readContact w c CB
      hasB <- share (b + 0.5)
      movedA <- readMoved w a
      movedB <- readMoved w (toIndex (maxF 0 b))
      normal <- readRow w c JaX JbX
      apart <- share (sideA metric normal movedA - select hasB (sideB metric normal movedB) 0)
      readContact w c CDepth >>= writePrev w c PrevDepth . subtract apart
      let Vel la ta = movedA
          Vel lb tb = movedB
          V3 dx dy dz = la ^-^ (select hasB <$> lb <*> pure 0)
      forM_ (zip3 [CDriftX .. CTurnB] [PrevDriftX .. PrevTurnB] [dx, dy, dz, ta, select hasB tb 0]) $ \(cf, pf, d) ->
        readContact w c cf >>= writePrev w c pf . (+ d)
      forM_ [ fields | fields@(cf, _) <- keptFields, cf `notElem` CDepth : [CDriftX .. CTurnB] ] $ \(cf, pf) ->
        readContact w c cf >>= writePrev w c pf
    n <- readArray (wBodyPrev w) (2 * owner + 1)
    whenPositive (0.5 - n) $ writeArray (wBodyPrev w) (2 * owner) (toScalar c)
    writeArray (wBodyPrev w) (2 * owner + 1) (n + 1)
