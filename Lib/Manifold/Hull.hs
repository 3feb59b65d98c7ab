{-# LANGUAGE FlexibleContexts #-}
-- | The built-in shapes that collide by their exact hulls
-- ("Manifold.ContactManifold"): circles, boxes, capsules and convex
-- polygons of three to eight corners, rounded or not, as the engine's
-- body placement takes them (a code, two numbers and, for a polygon, its
-- corners, so that the page's engine chooses a shape at run time), their
-- corners in the body's own frame, their polar outlines (what is drawn,
-- picked and kept off boundaries) and their exact mass and moment of
-- inertia.
--
-- A body's frame: @a@ along its direction (its axis turned by its angle),
-- @b@ along normal × direction, the way a positive angle turns it.
module Manifold.Hull
  ( -- * Shape codes
    circleCode
  , boxCode
  , capsuleCode
  , verticesCode
  , outlineCode
  , isVertices
  , isRegularHull
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
    -- * Convex polygons
  , regularCorners
  , convexRound
  , orientCorners
  , polygonMoments
  , centredCorners
  , polygonMass
  , polygonReach
  , polygonThickness
  , verticesOutline
  ) where

import Manifold.Field

-- | The codes of the shapes with hulls (a regular polygon's code is its
-- number of sides, 3 or more).
circleCode, boxCode, capsuleCode, verticesCode :: Field a => a
circleCode = 0
boxCode = -1
capsuleCode = -2
verticesCode = -3

-- | The code of a shape of one's own, which collides by its sampled
-- outline.
outlineCode :: Field a => a
outlineCode = 1

-- | Whether a code is the given one (1 or 0): codes are whole numbers.
is :: Field a => a -> a -> a
is code k = select (0.5 - abs (code - k)) 1 0

-- | 1 for a convex polygon's code ('verticesCode'), else 0.
isVertices :: Field a => a -> a
isVertices code = is code verticesCode

-- | 1 for a square's or a regular polygon's code of 3 to
-- 'Manifold.ContactManifold.maxHullCorners' sides (a polygon of its
-- corners: 'regularCorners'), else 0.
--
-- >>> map isRegularHull [2, 3, 4, 8, 9, -1 :: Double]
-- [0.0,1.0,1.0,1.0,0.0,0.0]
isRegularHull :: Field a => a -> a
isRegularHull code = select (code - 2.5) (select (8.5 - code) 1 0) 0

-- | How many corners the hull of the shape with this code and first
-- number has ('Manifold.World.Corners'): 1 for a circle (its centre,
-- rounded by its radius), 2 for a capsule (its segment's ends), 4 for a
-- box, a polygon's count (its first number), 0 for the shapes that
-- collide by their sampled outlines.
--
-- >>> [hullCorners c 5 | c <- [0, -1, -2, -3, 4, 1 :: Double]]
-- [1.0,4.0,2.0,5.0,0.0,0.0]
hullCorners :: Field a => a -> a -> a
hullCorners code p = is code circleCode + 4 * is code boxCode + 2 * is code capsuleCode + p * is code verticesCode

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
-- capsule's or a polygon's (its second number), none for a box.
hullRounding :: Field a => a -> a -> a -> a
hullRounding code q size = is code circleCode * size + (is code capsuleCode + is code verticesCode) * q

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

-- Convex polygons ---------------------------------------------------------
--
-- A polygon's corners come as a list of 'Manifold.ContactManifold.maxHullCorners'
-- points of which the first @n@ count (@n@ a scalar, so that the page's
-- engine takes any count at run time); its radius @r@ rounds it (the points
-- within @r@ of it, as Box2D's rounded polygons).

-- | A regular polygon's corners, @n@ of them (then 0 up to
-- 'Manifold.ContactManifold.maxHullCorners'), at distance @r@ from its
-- centre and at the angles @(2k − 1)π/n@: a side faces the body's
-- direction, as 'Manifold.Body.polygonOutline''s.
--
-- >>> [(round a, round b) | (a, b) <- take 4 (regularCorners 4 (sqrt 2 :: Double))] :: [(Int, Int)]
-- [(1,-1),(1,1),(-1,1),(-1,-1)]
regularCorners :: Field a => a -> a -> [(a, a)]
regularCorners n r =
  [ (select (n - fromIntegral k - 0.5) (r * cosF t) 0, select (n - fromIntegral k - 0.5) (r * sinF t) 0)
  | k <- [0 .. 7 :: Int], let t = (2 * fromIntegral k - 1) * pi / n ]

-- | 1 when corner @k@ is one of the first @n@, else 0.
counted :: Field a => a -> Int -> a
counted n k = select (n - fromIntegral k - 0.5) 1 0

-- | Corner @j@ of the list, @j@ a scalar (0 when no corner has that index).
cornerAt :: Field a => [(a, a)] -> a -> (a, a)
cornerAt cs j =
  let pick f = sum [is j (fromIntegral k) * f c | (k, c) <- zip [0 :: Int ..] cs]
  in (pick fst, pick snd)

-- | The corner after corner @k@ of the first @n@ (the first after the last).
nextOf :: Field a => a -> [(a, a)] -> Int -> (a, a)
nextOf n cs k =
  let (a, b) = if k + 1 < length cs then cs !! (k + 1) else head cs
      (a0, b0) = head cs
      within = n - fromIntegral k - 1.5
  in (select within a a0, select within b b0)

-- | The corner before corner @k@ of the first @n@ (the last before the first).
previousOf :: Field a => a -> [(a, a)] -> Int -> (a, a)
previousOf n cs k
  | k == 0 = cornerAt cs (n - 1)
  | otherwise = cs !! (k - 1)

cross2 :: Num a => (a, a) -> (a, a) -> a
cross2 (a, b) (c, d) = a * d - b * c

dot2 :: Num a => (a, a) -> (a, a) -> a
dot2 (a, b) (c, d) = a * c + b * d

minus2 :: Num a => (a, a) -> (a, a) -> (a, a)
minus2 (a, b) (c, d) = (a - c, b - d)

-- | A polygon's first @n@ corners counter-clockwise in the body's frame
-- (turning from @a@ towards @b@): as given, or reversed when given
-- clockwise.
--
-- >>> take 3 (orientCorners 3 [(0, 0), (0, 1), (1, 0), (0, 0 :: Double)])
-- [(1.0,0.0),(0.0,1.0),(0.0,0.0)]
orientCorners :: Field a => a -> [(a, a)] -> [(a, a)]
orientCorners n cs =
  let twiceArea = sum [counted n k * cross2 c (nextOf n cs k) | (k, c) <- zip [0 ..] cs]
      reversed k = cornerAt cs (n - 1 - fromIntegral k)
  in [ (select twiceArea a ra, select twiceArea b rb) | (k, (a, b)) <- zip [0 :: Int ..] cs, let (ra, rb) = reversed k ]

-- | Whether the first @n@ corners go round a convex polygon in order,
-- either way round: for each edge, every corner but its two ends strictly
-- on one side of its line, the same side for every edge (so repeated,
-- collinear, non-convex and doubly wound lists are not). 1 if they do,
-- else 0: a number, so that the page's scene reader runs the same test
-- from generated code (@Manifold.shapes.convexRound@) with the count at
-- run time.
--
-- >>> convexRound 4 [(0, 0), (1, 0), (1, 1), (0, 1 :: Double)]
-- 1.0
-- >>> convexRound 4 [(0, 0), (1, 1), (1, 0), (0, 1 :: Double)]
-- 0.0
-- >>> convexRound 3 [(0, 0), (0, 1), (1, 0), (9, 9 :: Double)]
-- 1.0
convexRound :: Field a => a -> [(a, a)] -> a
convexRound n cs =
  let m = length cs
      -- 1 where corner j is the one after corner k (the first after the last)
      isNext k j
        | j == k + 1 = counted n j
        | j == 0 = counted n k - counted n (k + 1)
        | otherwise = 0
      sides =
        [ (counted n k * counted n j * (1 - isNext k j), cross2 (minus2 (nextOf n cs k) a) (minus2 c a))
        | (k, a) <- zip [0 .. m - 1] cs, (j, c) <- zip [0 .. m - 1] cs, j /= k ]
      total = sum (map fst sides)
      onLeft = sum [ w * select s 1 0 | (w, s) <- sides ]
      onRight = sum [ w * select (negate s) 1 0 | (w, s) <- sides ]
      every x = 0.5 - abs (total - x)
  in select (every onLeft) 1 (select (every onRight) 1 0)

-- | The area, first moment @(Sx, Sy)@ and polar second moment about the
-- frame's origin of a counter-clockwise convex polygon rounded by @r@:
-- the triangles from the origin to each edge (signed, so the origin may
-- lie anywhere), the rectangle of width @r@ out of each edge, and the
-- circular sector of radius @r@ at each corner, between its edges'
-- normals.
--
-- >>> polygonMoments 4 0 [(-1, -1), (1, -1), (1, 1), (-1, 1 :: Double)]
-- (4.0,0.0,0.0,2.6666666666666665)
polygonMoments :: Field a => a -> a -> [(a, a)] -> (a, a, a, a)
polygonMoments n r cs =
  let pieces = [ scaled (counted n k) (corner k c) | (k, c) <- zip [0 ..] cs ]
      scaled w (m, x, y, j) = (w * m, w * x, w * y, w * j)
      add4 (a, b, c, d) (e, f, g, h) = (a + e, b + f, c + g, d + h)
      corner k c@(ax, ay) =
        let nextC@(bx, by) = nextOf n cs k
            prevC = previousOf n cs k
            -- the triangle from the origin to the edge from c
            tri = cross2 c nextC / 2
            triX = tri * (ax + bx) / 3
            triY = tri * (ay + by) / 3
            triJ = tri * (dot2 c c + dot2 c nextC + dot2 nextC nextC) / 6
            -- the rectangle out of that edge
            (ex, ey) = minus2 nextC c
            len = sqrt (ex * ex + ey * ey)
            (nx, ny) = outward (ex, ey) len
            rect = len * r
            mx = (ax + bx) / 2 + r / 2 * nx
            my = (ay + by) / 2 + r / 2 * ny
            rectJ = rect * (len * len + r * r) / 12 + rect * (mx * mx + my * my)
            -- the sector at c, between the normals of the edges into and out of it
            (px, py) = minus2 c prevC
            (qx, qy) = outward (px, py) (sqrt (px * px + py * py))
            (sx, sy) = (qx + nx, qy + ny)
            (dx, dy) = (nx - qx, ny - qy)
            sumLen = sqrt (sx * sx + sy * sy)
            angle = 2 * atanF (sqrt (dx * dx + dy * dy) / maxF sumLen 1e-300)
            sector = angle * r * r / 2
            reach = select (angle - 1e-9) (4 * r * sinF (angle / 2) / (3 * angle)) (2 * r / 3)
            (ux, uy) = (select sumLen (sx / sumLen) qx, select sumLen (sy / sumLen) qy)
            (gx, gy) = (ax + reach * ux, ay + reach * uy)
            sectorJ = angle * r * r * r * r / 4 - sector * reach * reach + sector * (gx * gx + gy * gy)
        in ( tri + rect + sector
           , triX + rect * mx + sector * gx
           , triY + rect * my + sector * gy
           , triJ + rectJ + sectorJ )
  in foldr add4 (0, 0, 0, 0) pieces
  where
    outward (ex, ey) len = (select len (ey / len) 0, select len (negate ex / len) 0)

-- | The corners moved so that the rounded polygon's centroid is the
-- origin (the body's centre is its centre of mass), for a
-- counter-clockwise polygon.
--
-- >>> take 3 (centredCorners 3 0 [(0, 0), (3, 0), (0, 3), (0, 0 :: Double)])
-- [(-1.0,-1.0),(2.0,-1.0),(-1.0,2.0)]
centredCorners :: Field a => a -> a -> [(a, a)] -> [(a, a)]
centredCorners n r cs =
  let (m, sx, sy, _) = polygonMoments n r cs
      cx = sx / m
      cy = sy / m
  in [ (a - cx, b - cy) | (a, b) <- cs ]

-- | The mass and moment of inertia about the origin of a rounded
-- counter-clockwise polygon at a density (about its centre of mass once
-- 'centredCorners' has moved it).
--
-- >>> polygonMass 3 0 [(-1, -1), (2, -1), (-1, 2), (0, 0 :: Double)] 2 -- a right triangle's 9 and 9·18/18
-- (9.0,9.0)
polygonMass :: Field a => a -> a -> [(a, a)] -> a -> (a, a)
polygonMass n r cs density =
  let (m, _, _, j) = polygonMoments n r cs
  in (density * m, density * j)

-- | How far a rounded polygon reaches from the origin: its farthest
-- corner's distance and its radius.
--
-- >>> polygonReach 3 0.5 [(3, 4), (0, 1), (0, -1), (10, 10 :: Double)]
-- 5.5
polygonReach :: Field a => a -> a -> [(a, a)] -> a
polygonReach n r cs = r + foldr maxF 0 [ counted n k * sqrt (dot2 c c) | (k, c) <- zip [0 ..] cs ]

-- | What a rounded counter-clockwise polygon's slop and margins scale by
-- (its 'Manifold.World.Size'): the distance from the origin to its nearest
-- edge, and its radius (a thin plank's half thickness).
--
-- >>> polygonThickness 4 0 [(-2, -1), (2, -1), (2, 1), (-2, 1 :: Double)]
-- 1.0
polygonThickness :: Field a => a -> a -> [(a, a)] -> a
polygonThickness n r cs =
  r + foldr minF 1e300
    [ select (n - fromIntegral k - 0.5) (edgeDistance c (nextOf n cs k)) 1e300 | (k, c) <- zip [0 :: Int ..] cs ]
  where
    edgeDistance c d = let (ex, ey) = minus2 d c in cross2 (ex, ey) c / maxF (sqrt (ex * ex + ey * ey)) 1e-300 * (-1)

-- | Where the ray from the origin at angle θ (from the body's direction)
-- leaves a rounded counter-clockwise polygon holding the origin: where it
-- leaves the polygon with its edges pushed out by @r@, unless that point
-- lies beyond a corner (past the end of the edge into it and before the
-- start of the edge out of it): then where it leaves that corner's disc.
--
-- >>> verticesOutline 4 0 [(-2, -1), (2, -1), (2, 1), (-2, 1 :: Double)] 0
-- 2.0
-- >>> verticesOutline 4 1 [(-2, -1), (2, -1), (2, 1), (-2, 1 :: Double)] (pi / 2)
-- 2.0
verticesOutline :: Field a => a -> a -> [(a, a)] -> a -> a
verticesOutline n r cs theta =
  let u@(ux, uy) = (cosF theta, sinF theta)
      numbered = zip [0 :: Int ..] cs
      -- the pushed-out edges
      exitAt k c =
        let (ex, ey) = minus2 (nextOf n cs k) c
            len = maxF (sqrt (ex * ex + ey * ey)) 1e-300
            nrm = (ey / len, negate ex / len)
            facing = dot2 u nrm
        in select (minF facing (n - fromIntegral k - 0.5)) ((dot2 c nrm + r) / maxF facing 1e-300) 1e300
      mitred = foldr minF 1e300 [ exitAt k c | (k, c) <- numbered ]
      x = (mitred * ux, mitred * uy)
      rounded k c acc =
        let d = minus2 x c
            into = minus2 c (previousOf n cs k)
            outOf = minus2 (nextOf n cs k) c
            along = dot2 u c
            disc = along + sqrt (maxF (r * r - dot2 c c + along * along) 0)
            beyond = minF (minF (dot2 d into) (negate (dot2 d outOf))) (n - fromIntegral k - 0.5)
        in select beyond disc acc
  in foldr (\(k, c) acc -> rounded k c acc) mitred numbered
