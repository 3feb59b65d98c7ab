-- | A geodesic walked into an array: the page's geodesic tool draws it. It
-- is the walk 'geodesicPath' makes (RATTLE steps of unit speed, so the
-- curve's length is the time walked), written as an imperative program so
-- that the page gets it generated, with the two things a drawn curve needs
-- on top: the quotient's wrap (on the flat torus the curve winds through
-- the fundamental square, and the drawing must not join a point to the
-- next across the edge) and the boundary (the walk stops where the surface
-- ends, at a disc's rim).
module Manifold.GeodesicPath
  ( PathSlot (..)
  , pathStride
  , pathLength
  , walkGeodesic
  ) where

import Control.Monad (forM_)
import Linear.Metric (quadrance)
import Linear.V3 (V3 (..))
import Linear.Vector ((^-^))

import Manifold.Field
import Manifold.Metric
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.Surface

-- | What a point of a walked path holds, in this order: its coordinates,
-- and whether the curve breaks before it (1 where the walk wrapped into
-- the fundamental domain on the way to it, else 0).
data PathSlot = PathX | PathY | PathZ | PathBreak
  deriving (Show, Eq, Enum, Bounded)

-- | Numbers per point of a path.
--
-- >>> pathStride
-- 4
pathStride :: Int
pathStride = length [minBound .. maxBound :: PathSlot]

-- | How many numbers a path of @n@ steps takes: the count of points walked
-- first, then the start and the @n@ points after it.
--
-- >>> pathLength 10
-- 45
pathLength :: Int -> Int
pathLength n = 1 + pathStride * (n + 1)

-- | @walkGeodesic sp path p d len n@: the geodesic from the surface point
-- @p@ in the tangent direction of @d@, for a length @len@ in @n@ equal
-- steps, into @path@: @path[0]@ the number of points walked (the start
-- included, so @n + 1@ unless the walk left the surface's boundary first:
-- it stops before the first point outside), then each point's 'PathSlot's.
-- Through a flipping edge the walk goes on mirrored, as a body does.
walkGeodesic :: Imp m => Space -> Array m -> V3 (Scalar m) -> V3 (Scalar m) -> Scalar m -> Index m -> m ()
{-# SPECIALIZE walkGeodesic :: Space -> NativeArray -> V3 Double -> V3 Double -> Double -> Int -> Native () #-}
walkGeodesic sp path p0 d0 len n = do
  let f = spaceField sp
      metric = spaceMetric sp
  n0 <- shareAll (unitNormal metric f p0)
  v0 <- shareAll (normalizeIn metric (tangentProjection metric n0 d0))
  h <- share (len / maxF 1 (toScalar n))
  let refs3 (V3 x y z) = V3 <$> newRef x <*> newRef y <*> newRef z
      get3 (V3 a b c) = V3 <$> readRef a <*> readRef b <*> readRef c
      set3 (V3 a b c) (V3 x y z) = writeRef a x >> writeRef b y >> writeRef c z
      point k q broken = forM_ (zip [PathX ..] (toList3 q ++ [broken])) $ \(slot, x) ->
        writeArray path (1 + fromIntegral pathStride * k + fromIntegral (fromEnum slot)) x
  pR <- refs3 p0
  vR <- refs3 v0
  nR <- refs3 n0
  walked <- newRef 1
  point 0 p0 0
  forEach n $ \k -> do
    alive <- readRef walked
    -- once the walk has stopped, nothing more is written
    whenPositive (alive - toScalar k) $ do
      p <- get3 pR
      v <- get3 vR
      nrm <- get3 nR
      let (p1, v1, n1) = geodesicStepFrom metric f h nrm (p, v)
      p1s <- shareAll p1
      let Wrapped p2 carry _ = case quotientWrap (spaceQuotient sp) of
            Nothing -> Wrapped p1s (V3 (V3 1 0 0) (V3 0 1 0) (V3 0 0 1)) 1
            Just wrap -> wrap p1s
      p2s <- shareAll p2
      carryS <- mapM shareAll carry
      let mirror = linearMap carryS
      broken <- share (select (quadrance (p2s ^-^ p1s)) 1 0)
      ifPositive (evalBoundary sp p2s)
        (do set3 pR p2s
            set3 vR (mirror v1)
            set3 nR (mirror n1)
            point (k + 1) p2s broken
            writeRef walked (alive + 1))
        (pure ())
  readRef walked >>= writeArray path 0
  where
    toList3 (V3 x y z) = [x, y, z]
