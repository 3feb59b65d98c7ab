{-# LANGUAGE FlexibleContexts #-}
-- | The built-in shapes that collide by their exact hulls
-- ("Manifold.ContactManifold"): circles, boxes and capsules, as the
-- engine's body placement takes them (a code and two numbers, so that the
-- page's engine chooses a shape at run time), their corners in the
-- body's own frame, their polar outlines (what is drawn, picked and kept
-- off boundaries) and their exact mass and moment of inertia.
--
-- A body's frame: @a@ along its direction (its axis turned by its angle),
-- @b@ along normal × direction, the way a positive angle turns it.
module Manifold.Hull
  ( -- * Shape codes
    circleCode
  , boxCode
  , capsuleCode
  , outlineCode
  , hullCorners
  , hullSize
  , hullThickness
  , hullRounding
  , hullCorner
    -- * Outlines and mass
  , hullOutline
  , boxOutline
  , capsuleOutline
  , hullMass
  ) where

import Manifold.Field

-- | The codes of the shapes with hulls (a regular polygon's code is its
-- number of sides, 3 or more).
circleCode, boxCode, capsuleCode :: Field a => a
circleCode = 0
boxCode = -1
capsuleCode = -2

-- | The code of a shape of one's own, which collides by its sampled
-- outline.
outlineCode :: Field a => a
outlineCode = 1

-- | Whether a code is the given one (1 or 0): codes are whole numbers.
is :: Field a => a -> a -> a
is code k = select (0.5 - abs (code - k)) 1 0

-- | How many corners the hull of the shape with this code has
-- ('Manifold.World.Corners'): 1 for a circle (its centre, rounded by its
-- radius), 2 for a capsule (its segment's ends), 4 for a box, 0 for the
-- shapes that collide by their sampled outlines.
--
-- >>> map hullCorners [0, -1, -2, 4, 1 :: Double]
-- [1.0,4.0,2.0,0.0,0.0]
hullCorners :: Field a => a -> a
hullCorners code = is code circleCode + 4 * is code boxCode + 2 * is code capsuleCode

-- | A body's size (its circumradius: how far its outline reaches from the
-- centre) from its shape's code and numbers @(p, q)@: a box's half-extents
-- give @√(p² + q²)@, a capsule's half length and radius @p + q@; the
-- other shapes are given their size (@size@).
--
-- >>> hullSize (-1) 3 4 (0 :: Double)
-- 5.0
hullSize :: Field a => a -> a -> a -> a -> a
hullSize code p q size =
  select (0.5 - abs (code - boxCode)) (sqrt (p * p + q * q))
    (select (0.5 - abs (code - capsuleCode)) (p + q) size)

-- | What the engine scales a body's slop and contact margins by (its
-- 'Manifold.World.Size'): the given size, but for a box half its least
-- width and for a capsule its radius, so that a thin card keeps margins
-- of its own thickness and not of its length.
--
-- >>> hullThickness (-1) 0.1 0.0005 (0 :: Double)
-- 5.0e-4
hullThickness :: Field a => a -> a -> a -> a -> a
hullThickness code p q size =
  select (0.5 - abs (code - boxCode)) (minF p q)
    (select (0.5 - abs (code - capsuleCode)) q size)

-- | The radius that rounds a hull: a circle's radius (its size), a
-- capsule's, none for a box.
hullRounding :: Field a => a -> a -> a -> a
hullRounding code q size = is code circleCode * size + is code capsuleCode * q

-- | Corner @k@ of a hull in the body's frame @(a, b)@, counter-clockwise: a
-- box's from @(−p, −q)@, a capsule's segment from @(−p, 0)@ to @(p, 0)@, a
-- circle's centre.
--
-- >>> [hullCorner (-1) 2 1 k :: (Double, Double) | k <- [0 .. 3]]
-- [(-2.0,-1.0),(2.0,-1.0),(2.0,1.0),(-2.0,1.0)]
hullCorner :: Field a => a -> a -> a -> Int -> (a, a)
hullCorner code p q k =
  let box = [(-p, -q), (p, -q), (p, q), (-p, q)] !! (k `mod` 4)
      capsule = [(-p, 0), (p, 0)] !! (k `mod` 2)
      pick f = is code boxCode * f box + is code capsuleCode * f capsule
  in (pick fst, pick snd)

-- | The polar outline of a hull shape in direction θ, at its full size
-- (the others' outlines are 'Manifold.Body''s, scaled by their size).
hullOutline :: Field a => a -> a -> a -> a -> a
hullOutline code p q theta =
  select (0.5 - abs (code - boxCode)) (boxOutline p q theta)
    (select (0.5 - abs (code - capsuleCode)) (capsuleOutline p q theta) 0)

-- | Where the ray from a box's centre at angle θ (from its direction)
-- leaves the box of half-extents @p@ and @q@: @min(p/|cos θ|, q/|sin θ|)@.
--
-- >>> boxOutline 2 1 (0 :: Double)
-- 2.0
-- >>> boxOutline 2 1 (pi / 2 :: Double)
-- 1.0
boxOutline :: Field a => a -> a -> a -> a
boxOutline p q theta =
  let c = abs (cosF theta)
      s = abs (sinF theta)
  in minF (p / maxF c 1e-300) (q / maxF s 1e-300)

-- | Where the ray from a capsule's centre at angle θ leaves the capsule of
-- half length @p@ and radius @q@: the farther of where it leaves the
-- rectangle between the caps and where it leaves the cap on its side
-- (both lie in the capsule, which is convex and holds the centre).
--
-- >>> capsuleOutline 2 1 (0 :: Double)
-- 3.0
-- >>> capsuleOutline 2 1 (pi / 2 :: Double)
-- 1.0
capsuleOutline :: Field a => a -> a -> a -> a
capsuleOutline p q theta =
  let c = abs (cosF theta)
      s = abs (sinF theta)
      rectangle = minF (p / maxF c 1e-300) (q / maxF s 1e-300)
      reach = q * q - p * p * s * s
      cap = select reach (p * c + sqrt (maxF reach 0)) 0
  in maxF rectangle cap

-- | The mass and moment of inertia about the centre of a box or a capsule
-- at a density, in the flat tangent plane as the paper measures bodies: a
-- box @4pq·ρ@ and @m(p² + q²)/3@; a capsule its rectangle and its two caps
-- (a disc's mass, each half's moment about its flat side's middle carried
-- to the centre, @L² + 2L·4R/(3π)@ farther).
--
-- >>> hullMass (-1) 1 1 (1 :: Double)
-- (4.0,2.6666666666666665)
hullMass :: Field a => a -> a -> a -> a -> (a, a)
hullMass code p q density =
  let boxM = 4 * p * q * density
      boxI = boxM * (p * p + q * q) / 3
      rectM = 4 * p * q * density
      rectI = rectM * (p * p + q * q) / 3
      discM = pi * q * q * density
      discI = discM * (0.5 * q * q + p * p + p * 8 * q / (3 * pi))
      capM = rectM + discM
      capI = rectI + discI
      pick b c = select (0.5 - abs (code - boxCode)) b c
  in (pick boxM capM, pick boxI capI)
