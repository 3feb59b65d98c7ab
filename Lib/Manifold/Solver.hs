{-# OPTIONS_GHC -fllvm #-}
{-# LANGUAGE FlexibleContexts #-}
-- Built with LLVM (as the compiled steps are): the generic native step's
-- solve is a tenth faster so (manifold bench --generic, settled piles).

-- | Sequential impulses (paper §2.5; Catto's Box2D solver): every contact is
-- a normal row (relative normal velocity ≥ 0, Baumgarte bias @β·depth/dt@,
-- restitution, non-negative clamp) and a Coulomb friction row (clamped by
-- @μ·λn@), warm started from the last step's impulses of the same contact.
-- A body's velocity lives in its tangent plane and its angular velocity is
-- about the surface normal, so a row's Jacobian for a body is the contact
-- direction projected to the body's tangent plane and @(r × n)·normal@.
-- The mouse joint is a soft constraint (stiffness and damping as a spring's
-- frequency and damping ratio, a force limit) pulling a point of a body
-- towards a target.
module Manifold.Solver
  ( solve
  , grabPoint
  ) where

import Linear.Metric (dot, quadrance)
import Linear.V3 (V3 (..), cross)
import Linear.Vector ((*^), (^+^), (^-^))

import Manifold.Field
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.Surface (geodesicStep)
import Manifold.World

-- | A body's velocity state.
data Vel s = Vel !(V3 s) !s

readVel :: Imp m => WorldArrays (Array m) -> Index m -> m (Vel (Scalar m))
{-# INLINE readVel #-}
readVel w i = Vel <$> read3 (wVel w) i <*> readSlot w i Omega

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

-- | How fast body a's, and body b's, side of a row moves.
sideA, sideB :: Num s => Row s -> Vel s -> s
{-# INLINE sideA #-}
{-# INLINE sideB #-}
sideA r (Vel v o) = (rowA r `dot` v) + rowAW r * o
sideB r (Vel v o) = (rowB r `dot` v) + rowBW r * o

-- | The relative velocity along a row: body a's minus body b's.
rowVelocity :: Imp m => WorldArrays (Array m) -> Index m -> Scalar m -> Row (Scalar m) -> m (Scalar m)
{-# INLINE rowVelocity #-}
rowVelocity w a b r = do
  va <- readVel w a
  vb <- newRef 0
  whenPositive (b + 0.5) $ readVel w (toIndex b) >>= writeRef vb . sideB r
  vB <- readRef vb
  share (sideA r va - vB)

applyRow :: Imp m => WorldArrays (Array m) -> Index m -> Scalar m -> Row (Scalar m) -> Scalar m -> m ()
{-# INLINE applyRow #-}
applyRow w a b r lambda = do
  push w a lambda (rowA r) (rowAW r)
  whenPositive (b + 0.5) $ push w (toIndex b) (negate lambda) (rowB r) (rowBW r)

-- | The effective mass of a row: @1 / (J M⁻¹ Jᵀ)@.
effectiveMass :: Imp m => WorldArrays (Array m) -> Index m -> Scalar m -> Row (Scalar m) -> m (Scalar m)
{-# INLINE effectiveMass #-}
effectiveMass w a b r = do
  ima <- readSlot w a InvMass
  iia <- readSlot w a InvInertia
  kb <- newRef 0
  whenPositive (b + 0.5) $ do
    imb <- readSlot w (toIndex b) InvMass
    iib <- readSlot w (toIndex b) InvInertia
    writeRef kb (imb * quadrance (rowB r) + iib * rowBW r * rowBW r)
  kB <- readRef kb
  k <- share (ima * quadrance (rowA r) + iia * rowAW r * rowAW r + kB)
  share (select k (recip k) 0)

-- | Where a grabbed body's grabbed point is now: the geodesic from its
-- centre in the grabbed direction, as long as the grabbed distance.
grabPoint :: Imp m => Space -> WorldArrays (Array m) -> Index m -> m (V3 (Scalar m))
grabPoint sp w g = do
  f <- bodyFrame w g
  r <- readMouse w MLocalR
  theta <- readMouse w MLocalTheta
  let phi = bfAngle f + theta
      dir = cos phi *^ bfU f ^+^ sin phi *^ bfW f
      steps = 4 :: Int
      h = r / fromIntegral steps
      go 0 s = pure s
      go k (q, d) = do
        let (q1, d1) = geodesicStep (spaceField sp) h (q, d)
        q' <- share3 q1
        d' <- share3 d1
        go (k - 1 :: Int) (q', d')
  fst <$> go steps (bfCentre f, dir)

-- | The mouse joint's rows along the body's frame vectors.
mouseRows :: Imp m => Space -> WorldArrays (Array m) -> Bool -> m ()
mouseRows sp w warm = do
  active <- readMouse w MActive
  whenPositive active $ do
    gS <- readMouse w MBody
    let g = toIndex gS
    im <- readSlot w g InvMass
    whenPositive im $ do
      ii <- readSlot w g InvInertia
      dt <- readParam w Dt
      f <- bodyFrame w g
      grab <- grabPoint sp w g
      target0 <- V3 <$> readMouse w MTargetX <*> readMouse w MTargetY <*> readMouse w MTargetZ
      -- on a lattice, towards the target's image nearest the grabbed point
      target <- share3 (nearestImage (spaceQuotient sp) grab target0)
      hz <- readMouse w MFrequency
      zeta <- readMouse w MDamping
      maxForce <- readMouse w MMaxForce
      let mass = recip im
          omega0 = 2 * pi * hz
          k = mass * omega0 * omega0
          d = 2 * mass * zeta * omega0
      gamma <- share (recip (dt * (d + dt * k)))
      beta <- share (dt * k * gamma)
      rw <- share3 (grab ^-^ bfCentre f)
      err <- share3 (grab ^-^ target)
      let row e field = do
            let jw = (rw `cross` e) `dot` bfNormal f
            acc <- readMouse w field
            if warm
              then push w g acc e jw
              else do
                Vel v o <- readVel w g
                let cdot = (e `dot` v) + jw * o
                    kk = im * quadrance e + ii * jw * jw + gamma
                    lambda = negate (cdot + beta * (err `dot` e) + gamma * acc) / kk
                    limit = maxForce * dt
                    acc' = finiteOr0 (clampF (negate limit) limit (acc + lambda))
                accS <- share acc'
                writeMouse w field accS
                push w g (accS - acc) e jw
      row (bfU f) MImpulseU
      row (bfW f) MImpulseW

-- | Solve this step's contacts and the mouse joint, and keep the impulses
-- for the next step.
solve :: Imp m => Space -> Layout -> WorldArrays (Array m) -> m ()
{-# SPECIALIZE solve :: Space -> Layout -> WorldArrays NativeArray -> Native () #-}
solve sp _ w = do
  iterations <- readParam w Iterations
  -- The preparation and each sweep over the rows are printed as functions
  -- of their own: V8 optimised the whole solver as one function only
  -- sometimes. In a page that had run a torus of 3000 bodies, Chromium's
  -- optimising compiler gave up on the rectangle's solver as "too big to be
  -- optimized" and never tried again, and the page's solve then took 100 ms
  -- a step instead of 5 (node bench/browser.mjs, the rectangle after the torus).
  subroutine "solvePrepare" [] $ \_ -> prepareRows w
  mouseRows sp w True
  forEach (toIndex iterations) $ \_ -> do
    subroutine "solveSweep" [] $ \_ -> sweepRows w
    mouseRows sp w False
  rememberImpulses w

-- | Each contact row's masses and bias, and its impulses warm started from
-- the last step's row of the same key, applied.
prepareRows :: Imp m => WorldArrays (Array m) -> m ()
{-# INLINE prepareRows #-}
prepareRows w = do
  dt <- readParam w Dt
  restitution <- readParam w Restitution
  beta <- readParam w Baumgarte
  slop <- readParam w Slop
  bounceThreshold <- readParam w BounceThreshold
  warmStart <- readParam w WarmStart
  maxCorrection <- readParam w MaxCorrection
  nc <- readMeta w ContactCount
  forEach (toIndex nc) $ \c -> do
    a <- toIndex <$> readContact w c CA
    b <- readContact w c CB
    owner <- readContact w c COwner
    key <- readContact w c CKey
    normal <- readRow w c JaX JbX
    tangent <- readRow w c TaX TbX
    kn <- effectiveMass w a b normal
    kt <- effectiveMass w a b tangent
    writeContact w c NormalMass kn
    writeContact w c TangentMass kt
    depth <- readContact w c CDepth
    scale <- readContact w c CSelfScale
    vn <- rowVelocity w a b normal
    -- the push out of an overlap is capped, so that a deep overlap found
    -- late does not throw bodies apart (Box2D caps its correction likewise)
    let push' = minF maxCorrection (scale * beta / dt * maxF 0 (depth - slop))
        bounce = select (negate vn - bounceThreshold) (negate restitution * vn) 0
    writeContact w c CBias (maxF push' bounce)
    ln <- newRef 0
    lt <- newRef 0
    start <- readArray (wBodyPrev w) (2 * toIndex owner)
    count <- readArray (wBodyPrev w) (2 * toIndex owner + 1)
    forLoop (toIndex start) (toIndex (start + count)) $ \k -> do
      pk <- readPrev w k PrevKey
      whenPositive (0.5 - abs (pk - key)) $ do
        readPrev w k PrevNormal >>= writeRef ln
        readPrev w k PrevFriction >>= writeRef lt
    lnv <- (warmStart *) <$> readRef ln
    ltv <- (warmStart *) <$> readRef lt
    writeContact w c ImpulseN lnv
    writeContact w c ImpulseT ltv
    applyRow w a b normal lnv
    applyRow w a b tangent ltv

-- | One sequential-impulse sweep over the contact rows: friction, then the
-- normal impulse, each clamped.
sweepRows :: Imp m => WorldArrays (Array m) -> m ()
{-# INLINE sweepRows #-}
sweepRows w = do
  mu <- readParam w Friction
  nc <- readMeta w ContactCount
  forEach (toIndex nc) $ \c -> do
    a <- toIndex <$> readContact w c CA
    b <- readContact w c CB
    tangent <- readRow w c TaX TbX
    normal <- readRow w c JaX JbX
    scale <- readContact w c CSelfScale
    ln <- readContact w c ImpulseN
    lt <- readContact w c ImpulseT
    kt <- readContact w c TangentMass
    kn <- readContact w c NormalMass
    bias <- readContact w c CBias
    -- both bodies' velocities are read once and written once (a row
    -- without body b has zero Jacobians on its side: body 0 stands in);
    -- when a body meets its own image (a = b) each side's change is
    -- added to the other's copy too, so both copies stay the body's
    bIx <- share (maxF 0 b)
    let bi = toIndex bIx
    hasB <- share (b + 0.5)
    same <- share (select (0.5 - abs (toScalar a - b)) 1 0)
    ima <- readSlot w a InvMass
    iia <- readSlot w a InvInertia
    imb <- readSlot w bi InvMass
    iib <- readSlot w bi InvInertia
    va0 <- readVel w a
    vb0 <- readVel w bi
    -- inlined: lifted out as functions of their own, the generic
    -- (native, uncompiled) step boxed every row and velocity it passed
    let along r va vb = share (sideA r va - select hasB (sideB r vb) 0)
        {-# INLINE along #-}
        apply r lambda (Vel va oa) (Vel vb ob) = do
          dva <- share3 ((ima * lambda) *^ rowA r)
          doa <- share (iia * lambda * rowAW r)
          dvb <- share3 ((imb * negate lambda) *^ rowB r)
          dob <- share (iib * negate lambda * rowBW r)
          va' <- share3 (va ^+^ dva ^+^ same *^ dvb)
          oa' <- share (oa + doa + same * dob)
          vb' <- share3 (vb ^+^ dvb ^+^ same *^ dva)
          ob' <- share (ob + dob + same * doa)
          pure (Vel va' oa', Vel vb' ob')
        {-# INLINE apply #-}
    vt <- along tangent va0 vb0
    let limit = mu * ln
    lt' <- share (finiteOr0 (clampF (negate limit) limit (lt - scale * vt * kt)))
    writeContact w c ImpulseT lt'
    (va1, vb1) <- apply tangent (lt' - lt) va0 vb0
    vn <- along normal va1 vb1
    ln' <- share (finiteOr0 (maxF 0 (ln + scale * (bias - vn) * kn)))
    writeContact w c ImpulseN ln'
    (Vel va2 oa2, Vel vb2 ob2) <- apply normal (ln' - ln) va1 vb1
    write3 (wVel w) a va2
    writeSlot w a Omega oa2
    whenPositive hasB $ do
      write3 (wVel w) bi vb2
      writeSlot w bi Omega ob2

-- | The impulses, grouped by owner, for the next step's warm start.
rememberImpulses :: Imp m => WorldArrays (Array m) -> m ()
{-# INLINE rememberImpulses #-}
rememberImpulses w = do
  nc <- readMeta w ContactCount
  bodies <- readMeta w BodyCount
  forEach (toIndex bodies) $ \i -> writeArray (wBodyPrev w) (2 * i + 1) 0
  forEach (toIndex nc) $ \c -> do
    owner <- toIndex <$> readContact w c COwner
    writePrev w c PrevOwner (toScalar owner)
    readContact w c CKey >>= writePrev w c PrevKey
    readContact w c ImpulseN >>= writePrev w c PrevNormal
    readContact w c ImpulseT >>= writePrev w c PrevFriction
    n <- readArray (wBodyPrev w) (2 * owner + 1)
    whenPositive (0.5 - n) $ writeArray (wBodyPrev w) (2 * owner) (toScalar c)
    writeArray (wBodyPrev w) (2 * owner + 1) (n + 1)
