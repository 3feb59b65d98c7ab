-- | Framing a scene: the view a scene opens with when it names no camera.
-- The camera looks along the surface's normal at the bodies, from the side
-- of the surface the space's own camera is on, so that they face it; from
-- the direction that sees the most of them (a clear line of sight, inside
-- the picture), and so far away that they fill a fair part of the picture.
module Manifold.Framing
  ( frameBodies
  , seenFrom
  , framingFill
  , framingAspect
  ) where

import Data.List (maximumBy, sortOn)
import Data.Ord (comparing)
import Linear.Metric (dot, norm, normalize)
import Linear.V3 (V3 (..), cross)
import Linear.Vector ((*^), (^+^), (^-^), (^/))

import Manifold.Space (Camera (..), Space (..), evalField)
import Manifold.Surface (fieldGradient)

-- | The share of the picture's height the framed bodies span (their
-- bounding ball's diameter, from the nearest distance that fits it).
framingFill :: Double
framingFill = 0.6

-- | The picture's width over its height that framing assumes: the page's
-- view is usually wider than high, never much narrower.
framingAspect :: Double
framingAspect = 4 / 3

-- | The camera for a scene's bodies (each its centre on the surface and its
-- size): among the directions of the bodies' normals (every body's, or
-- every k-th of a scene of more than 32), their mean and the means of two
-- (of about 8), the one from which the most bodies are 'seenFrom' (a tie:
-- the one nearer the space's own camera), looking at the centre of those
-- that face it (normals within 60° of it) from the distance at which they
-- fill 'framingFill' of the picture's height, no nearer than a fifth of
-- the space's camera's distance, and farther where that point is on the
-- other side of the surface (up to eight times its bounds). The space's
-- camera when there are no bodies; its up direction (unless the view looks
-- along it) and field of view always.
frameBodies :: Space -> [(V3 Double, Double)] -> Camera
frameBodies sp bodies
  | null bodies = own
  | otherwise = snd (maximumBy (comparing fst) (zip scores views))
  where
    own = spaceCamera sp
    ownDistance = norm (cameraEye own ^-^ cameraTarget own)
    side = if evalField sp (cameraEye own) < 0 then -1 else 1
    normals = [side *^ safeUnit (fieldGradient (spaceField sp) p) | (p, _) <- bodies]
    mean = safeUnit (foldr (^+^) (V3 0 0 0) normals)
    every k = [n | (i, n) <- zip [0 :: Int ..] normals, i `mod` max 1 (length normals `div` k) == 0]
    pairs = [safeUnit (a ^+^ b) | (i, a) <- zip [0 :: Int ..] (every 8), (j, b) <- zip [0 ..] (every 8), i < j]
    directions = filter ((> 0.5) . norm) (mean : every 32 ++ pairs)
    views = map view directions
    -- the most bodies seen; then the nearer the space's own direction, so
    -- that a tie keeps the view people know
    scores = [ (length (filter (seenFrom sp c) bodies), dot d ownDirection) | (c, d) <- zip views directions ]
    ownDirection = safeUnit (cameraEye own ^-^ cameraTarget own)
    halfHeight = tan (cameraFov own * pi / 360)
    view d =
      let facing = [b | (b, n) <- zip bodies normals, dot n d > 0.5]
          chosen = if null facing then bodies else facing
          target = foldr ((^+^) . fst) (V3 0 0 0) chosen ^/ fromIntegral (length chosen)
          reach = maximum [norm (p ^-^ target) + size | (p, size) <- chosen]
          wanted = max (0.2 * ownDistance) (reach / (framingFill * halfHeight))
          distance = head ([ r | r <- takeWhile (<= 8 * spaceBounds sp) (iterate (* 1.25) wanted)
                               , sideOf (target ^+^ r *^ d) == side ] ++ [wanted])
      in Camera (target ^+^ distance *^ d) target (upFor d) (cameraFov own)
    sideOf p = if evalField sp p < 0 then -1 else 1 :: Double
    -- the space's up, unless the view looks nearly along it
    upFor d
      | abs (dot (cameraUp own) d) < 0.9 = cameraUp own
      | otherwise = head (sortOn (\u -> abs (dot u d)) [V3 0 0 (-1), V3 1 0 0, V3 0 1 0])

-- | Whether a body (its centre and size) is in the picture of a camera,
-- faces it and the surface does not hide it there: its centre projects
-- inside the picture ('framingAspect' wide), the surface's normal there
-- (on the eye's side) is within 75° of the way to the eye, and the segment
-- from the eye to within two sizes of the centre stays on the eye's side of
-- the surface.
seenFrom :: Space -> Camera -> (V3 Double, Double) -> Bool
seenFrom sp cam (p, size) = inPicture && facing && clear
  where
    eye = cameraEye cam
    forward = safeUnit (cameraTarget cam ^-^ eye)
    right = safeUnit (cross forward (cameraUp cam))
    up = cross right forward
    rel = p ^-^ eye
    depth = dot rel forward
    halfHeight = tan (cameraFov cam * pi / 360)
    inPicture = depth > 0
      && abs (dot rel right) <= 0.95 * framingAspect * halfHeight * depth
      && abs (dot rel up) <= 0.95 * halfHeight * depth
    len = norm rel
    stop = max 0 (len - 2 * size) / len
    sign x = if x < 0 then -1 else 1 :: Double
    eyeSide = sign (evalField sp eye)
    facing = dot (eyeSide *^ safeUnit (fieldGradient (spaceField sp) p)) (safeUnit (eye ^-^ p)) > cos (75 * pi / 180)
    clear = all (\k -> sign (evalField sp (eye ^+^ (stop * fromIntegral k / fromIntegral samples) *^ rel)) == eyeSide) [0 .. samples :: Int]
    samples = 400

safeUnit :: V3 Double -> V3 Double
safeUnit v = let n = norm v in if n > 0 && not (isNaN n) && not (isInfinite n) then normalize v else V3 0 0 0
