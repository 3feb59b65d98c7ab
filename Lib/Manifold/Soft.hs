{-# LANGUAGE FlexibleContexts #-}
-- | Soft constraints (Catto, "Solver2D"; Box2D v3's @b2MakeSoft@): a row
-- that is a spring of frequency @f@ and damping ratio @ζ@ over a sub-step
-- of length @h@ rather than a rigid constraint. With @ω = 2πf@,
-- @a₁ = 2ζ + hω@, @a₂ = hω·a₁@, @a₃ = 1/(1 + a₂)@, a row of error @C@ and
-- velocity @Ċ@ takes the impulse @−a₂a₃·m·(Ċ + (ω/a₁)·C) − a₃·λ@, where @m@
-- is its effective mass and @λ@ the impulse it has applied so far. The
-- contacts ("Manifold.Solver") and the joints ("Manifold.Joint") are such
-- rows.
module Manifold.Soft
  ( Softness (..)
  , softness
  ) where

import Manifold.Stage.Imp

-- | A soft constraint's coefficients: the bias rate (@ω/a₁@), the mass
-- scale (@a₂a₃@) and the impulse scale (@a₃@).
data Softness s = Softness { biasRate :: !s, massScale :: !s, impulseScale :: !s }

-- | The coefficients for a spring of frequency @hz@ and damping ratio
-- @zeta@ over a sub-step of length @h@.
softness :: Imp m => Scalar m -> Scalar m -> Scalar m -> m (Softness (Scalar m))
{-# INLINE softness #-}
softness hz zeta h = do
  omega <- share (2 * pi * hz)
  a1 <- share (2 * zeta + h * omega)
  a2 <- share (h * omega * a1)
  a3 <- share (recip (1 + a2))
  Softness <$> share (omega / a1) <*> share (a2 * a3) <*> pure a3
