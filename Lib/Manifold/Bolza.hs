-- | The Bolza surface's group, the data its quotient is made of: the
-- hyperbolic plane (the hyperboloid of "Manifold.Metric"'s Minkowski space)
-- modulo the group that pairs opposite sides of the regular octagon with
-- interior angles π/4 centred at the vertex @(0, 1, 0)@. Its eight side
-- pairings (Lorentz matrices, nine numbers row by row as in
-- "Manifold.Disc"), the 48 images of the octagon that touch it (eight
-- across its sides, five more at each corner, where eight octagons meet), and
-- the wrap that brings a point back into the octagon with the matrix that
-- did it (to carry a velocity and a frame).
--
-- Side @k@ (0 to 7) faces the direction at angle @kπ/4@ from the x axis
-- towards z, at distance @r@ from the centre, @cosh r = 1 + √2@ (the
-- inradius of the octagon whose angles are π/4: @cos(π/8)/sin(π/8)@); its
-- corners are at distance @R@, @cosh R = cot²(π/8) = 3 + 2√2@. Pairing @k@
-- translates by @2r@ towards side @k@: it carries the opposite side @k + 4@
-- onto side @k@, and pairing @k + 4@ is its inverse.
module Manifold.Bolza
  ( inradius
  , circumradius
  , sideAngle
  , sideExcess
  , pairing
  , pairings
  , corners
  , touchingImages
  , wrapIntoOctagon
  ) where

import Control.Monad (replicateM)
import Data.List (foldl')
import Linear.V3 (V3 (..))

import Manifold.Disc (applyBoost, composeBoosts, translationTo)
import Manifold.Field

-- $setup
-- >>> let close a b = abs (a - b) < (1e-12 :: Double)

-- | The distance from the octagon's centre to its sides: @acosh (1 + √2)@.
--
-- >>> close (cosh inradius) (1 + sqrt 2)
-- True
inradius :: Double
inradius = acosh (1 + sqrt 2)

-- | The distance from the octagon's centre to its corners: @acosh (3 + 2√2)@.
circumradius :: Double
circumradius = acosh (3 + 2 * sqrt 2)

-- | The direction side @k@ faces, as an angle from x towards z.
sideAngle :: Int -> Double
sideAngle k = fromIntegral k * pi / 4

-- | How far beyond side @k@'s geodesic a point is, as the Minkowski inner
-- product of the point with the side's unit normal (positive outside, zero
-- on the side: @sinh@ of the signed distance).
--
-- >>> close (sideExcess 0 (V3 (sinh inradius) (cosh inradius) 0)) 0
-- True
sideExcess :: Field a => Int -> V3 a -> a
sideExcess k (V3 x y z) =
  let c = constant (cos (sideAngle k))
      s = constant (sin (sideAngle k))
  in (c * x + s * z) * constant (cosh inradius) - y * constant (sinh inradius)

-- | Side pairing @k@: the translation by @2r@ towards side @k@.
--
-- >>> let m = pairing 0 in close (sideExcess 0 (applyBoost m (V3 (sinh (-inradius)) (cosh inradius) 0))) 0
-- True
pairing :: Int -> [Double]
pairing k =
  let d = 2 * inradius
      a = sideAngle k
  in translationTo (V3 (sinh d * cos a) (cosh d) (sinh d * sin a))

-- | The eight side pairings, pairing @k@ at index @k@.
pairings :: [[Double]]
pairings = map pairing [0 .. 7]

-- | The octagon's corners, between sides @k@ and @k + 1@ at index @k@.
corners :: [V3 Double]
corners = [ V3 (sinh circumradius * cos a) (cosh circumradius) (sinh circumradius * sin a)
          | k <- [0 .. 7 :: Int], let a = sideAngle k + pi / 8 ]

-- | The elements of the group that move the octagon onto one that touches
-- it (shares a side or a corner): those that map some corner of the octagon
-- onto a corner of it, found among the words of up to four pairings. There
-- are 48: eight across the sides, and at each corner the five of the eight
-- octagons there that share no side with it. The list is closed under
-- inverses.
--
-- >>> length touchingImages
-- 48
touchingImages :: [[Double]]
touchingImages = foldl' add [] (concatMap words' [1 .. 4])
  where
    identity = [1, 0, 0, 0, 1, 0, 0, 0, 1]
    words' :: Int -> [[Double]]
    words' n = map (foldl' composeBoosts identity) (replicateM n pairings)
    same a b = maximum (zipWith (\x y -> abs (x - y)) a b) < 1e-6 * maximum (map abs a)
    near (V3 a b c) (V3 d e f) = abs (a - d) + abs (b - e) + abs (c - f) < 1e-6 * b
    touches g = or [ near (applyBoost g v) w | v <- corners, w <- corners ]
    add found g
      | same g identity || any (same g) found || not (touches g) = found
      | otherwise = found ++ [g]

-- | A point brought back into the octagon by the side pairings (a point
-- beyond side @k@ goes back through side @k + 4@ by pairing @k + 4@; four
-- rounds, each across the side it is farthest beyond: a body's step takes
-- it past one side, or near a corner into any of the seven other octagons
-- there, up to four crossings away), and the product of the pairings
-- used, which carries the point's velocity and frame alike.
--
-- >>> let p0 = V3 (sinh 2.0) (cosh 2.0) (0 :: Double); (p, m) = wrapIntoOctagon p0; V3 x y z = p; V3 x' y' z' = applyBoost m p0
-- >>> (maximum [sideExcess k p | k <- [0 .. 7]] <= 0, close x x' && close y y' && close z z')
-- (True,True)
wrapIntoOctagon :: Field a => V3 a -> (V3 a, [a])
wrapIntoOctagon p0 = foldl' (\(p, m) _ -> round' p m) (p0, map constant [1, 0, 0, 0, 1, 0, 0, 0, 1]) [1 .. wrapRounds]
  where
    wrapRounds = 4 :: Int
    round' p m =
      let excesses = [ (sideExcess k p, map constant (pairing ((k + 4) `mod` 8))) | k <- [0 .. 7] ]
          -- the side the point is farthest beyond, if beyond any: its pairing back, else the identity
          (_, back) = foldl' farther (0, map constant [1, 0, 0, 0, 1, 0, 0, 0, 1]) excesses
          farther (best, g) (e, h) = let beyond = e - best in (select beyond e best, zipWith (select beyond) h g)
      in (applyBoost back p, composeBoosts back m)
