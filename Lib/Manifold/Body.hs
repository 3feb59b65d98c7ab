-- | Bodies' shapes (paper §2.3), their mass and moment of inertia (§2.4) and
-- their polygons (§3.4).
--
-- A shape is a polar outline @r = s(θ)@ around the body's centre: the boundary
-- point in direction θ (measured from the body's axis) is reached by walking a
-- geodesic of length @s(θ)@. Diameters are kept as a body moves; area is not.
module Manifold.Body
  ( Outline (..)
  , Shape (..)
  , circle
  , square
  , regularPolygon
  , polygonOutline
  , box
  , capsule
  , shapeArgs
  , shapeSize
  , codeOutline
  , shapeCorners
  , polygonCorners
  , convexPolygon
  , customShape
  , shapeFromKind
  , outlineAt
    -- * Mass
  , MassProperties (..)
  , massProperties
  , massIntegrals
  , massSamples
  , areaOf
  , centroidOffset
  , paperMomentIntegral
    -- * Polygons
  , PolygonParams (..)
  , defaultPolygonParams
  , Polygon (..)
  , polygonise
  , vertexCount
  , vertexIndex
  , triangleCount
  , directionAngle
  , Sectors
  , sectors
  , directionSector
  ) where

import qualified Data.Vector.Unboxed as U
import Linear.V2 (V2 (..))
import Linear.V3 (V3 (..))
import Linear.Vector ((*^), (^+^))

import System.IO.Unsafe (unsafePerformIO)

import Manifold.ContactManifold (maxHullCorners)
import Manifold.Field
import Manifold.Hull
import Manifold.Metric
import Manifold.Space (ShapeKind (..))
import Manifold.Stage.Imp
import Manifold.Surface

-- | A polar outline for a body of size 1; the body's size scales it.
newtype Outline = Outline (forall a. Field a => a -> a)

-- | A named outline, and which built-in shape it is.
data Shape = Shape
  { shapeName :: String -- ^ for messages and the command line
  , shapeKind :: Maybe ShapeKind -- ^ 'Nothing' for user outlines
  , shapeOutline :: Outline
  }

-- | @outlineAt s size θ@: the geodesic distance from the centre to the
-- outline of a body of shape @s@ and this size, in direction θ.
--
-- >>> outlineAt square 2 (pi / 4 :: Double)
-- 2.0
-- >>> outlineAt square 2 0 :: Double
-- 1.4142135623730951
outlineAt :: Field a => Shape -> a -> a -> a
outlineAt s size theta = let Outline f = shapeOutline s in size * f theta

-- | The circle: the outline is at distance 1 in every direction.
circle :: Shape
circle = Shape "circle" (Just CircleShape) (Outline (const 1))

-- | A regular polygon of circumradius 1 with a side (not a corner) facing the
-- axis direction θ = 0.
--
-- >>> shapeName (regularPolygon 6)
-- "6-gon"
regularPolygon :: Int -> Shape
regularPolygon n
  | n < 3 = error ("regularPolygon: a polygon needs at least 3 sides, got " ++ show n)
  | otherwise = Shape (show n ++ "-gon") (Just (PolygonShape n)) (Outline (polygonOutline (fromIntegral n)))

-- | The outline of a regular polygon with @n@ sides (a scalar, so that the
-- page's engine can choose it at run time): 1 at the corners, @cos (π/n)@
-- at the middle of a side.
--
-- >>> polygonOutline 3 (pi / 3 :: Double)
-- 1.0
-- >>> polygonOutline 3 0 :: Double
-- 0.5000000000000001
polygonOutline :: Field a => a -> a -> a
polygonOutline n theta =
  let sector = 2 * pi / n
      half = pi / n
      shifted = theta + half
      within = shifted - sector * floorF (shifted / sector)
  in cosF half / cosF (within - half)

-- | A built-in shape as the engine's body placement and the page take it:
-- its code (0 a circle, @n >= 3@ a regular @n@-gon, −1 a box, −2 a
-- capsule, −3 a convex polygon: "Manifold.Hull") and its two numbers (a
-- box's half-extents, a capsule's half length and radius, a polygon's
-- count of corners and radius; 0 for the others). A polygon's corners are
-- 'shapeCorners'.
--
-- >>> map shapeArgs [CircleShape, SquareShape, PolygonShape 5, BoxShape 2 1, VerticesShape [(0, 0), (1, 0), (0, 1)] 0.5]
-- [(0.0,0.0,0.0),(4.0,0.0,0.0),(5.0,0.0,0.0),(-1.0,2.0,1.0),(-3.0,3.0,0.5)]
shapeArgs :: ShapeKind -> (Double, Double, Double)
shapeArgs CircleShape = (circleCode, 0, 0)
shapeArgs SquareShape = (4, 0, 0)
shapeArgs (PolygonShape n) = (fromIntegral n, 0, 0)
shapeArgs (BoxShape p q) = (boxCode, p, q)
shapeArgs (CapsuleShape p q) = (capsuleCode, p, q)
shapeArgs (VerticesShape cs r) = (verticesCode, fromIntegral (length cs), r)

-- | A convex polygon's corners as the engine's body placement takes them
-- ('Manifold.ContactManifold.maxHullCorners' of them, the unused ones 0);
-- every other shape's are all 0.
--
-- >>> take 4 (shapeCorners (VerticesShape [(0, 0), (1, 0), (0, 1)] 0))
-- [(0.0,0.0),(1.0,0.0),(0.0,1.0),(0.0,0.0)]
shapeCorners :: ShapeKind -> [(Double, Double)]
shapeCorners k = take maxHullCorners (own ++ repeat (0, 0))
  where
    own = case k of
      VerticesShape cs _ -> cs
      _ -> []

-- | A convex polygon's corners in the body's frame as the engine keeps
-- them: counter-clockwise, its centre of mass at the origin (the first
-- 'shapeArgs' count of 'shapeCorners').
--
-- >>> polygonCorners [(0, 0), (0, 3), (3, 0)] 0
-- [(2.0,-1.0),(-1.0,2.0),(-1.0,-1.0)]
polygonCorners :: [(Double, Double)] -> Double -> [(Double, Double)]
polygonCorners cs r =
  let n = fromIntegral (length cs)
      padded = shapeCorners (VerticesShape cs r)
  in take (length cs) (centredCorners n r (orientCorners n padded))

-- | The size a shape's own numbers give it (its circumradius), for the
-- shapes that have them (boxes, capsules, convex polygons: 'hullSize',
-- 'polygonReach').
--
-- >>> shapeSize (BoxShape 3 4)
-- Just 5.0
-- >>> shapeSize CircleShape
-- Nothing
shapeSize :: ShapeKind -> Maybe Double
shapeSize k = case (k, shapeArgs k) of
  (VerticesShape cs r, (_, n, _)) -> Just (polygonReach n r (polygonCorners cs r))
  (_, (code, p, q)) | hullCorners code p >= 2 -> Just (hullSize code p q 0)
  _ -> Nothing

-- | The outline, for size 1, of the built-in shape with the given code and
-- numbers ('shapeArgs'): a box's or a capsule's over its size.
codeOutline :: Field a => a -> a -> a -> a -> a
codeOutline code p q theta =
  select (code + 0.5)
    (select (code - 0.5) (polygonOutline code theta) 1)
    (hullOutline code p q theta / hullSize code p q 1)

-- | The square: the regular 4-gon, a side facing the axis.
square :: Shape
square = (regularPolygon 4) { shapeName = "square", shapeKind = Just SquareShape }

-- | A shape of one's own, from its polar outline for size 1 (a function of
-- the direction θ, at any scalar, so that it stages too).
customShape :: String -> (forall a. Field a => a -> a) -> Shape
customShape name f = Shape name Nothing (Outline f)

-- | The shape a scene's 'ShapeKind' names.
shapeFromKind :: ShapeKind -> Shape
shapeFromKind CircleShape = circle
shapeFromKind SquareShape = square
shapeFromKind (PolygonShape n) = regularPolygon n
shapeFromKind (BoxShape p q) = box p q
shapeFromKind (CapsuleShape p q) = capsule p q
shapeFromKind (VerticesShape cs r) = convexPolygon cs r

-- | A box of half-extents @p@ along the body's direction and @q@ across it
-- (its size is its circumradius, @√(p² + q²)@).
box :: Double -> Double -> Shape
box p q = builtIn "box" (BoxShape p q)

-- | A capsule: a segment along the body's direction, @p@ either side of
-- the centre, rounded by radius @q@ (its size is @p + q@).
capsule :: Double -> Double -> Shape
capsule p q = builtIn "capsule" (CapsuleShape p q)

-- | A convex polygon of 3 to 8 corners @(a, b)@ in the body's frame,
-- rounded by radius @r@ (0: sharp corners). Its centre is its centre of
-- mass: the corners are moved so ('polygonCorners'); its size is how far
-- it reaches ('polygonReach').
convexPolygon :: [(Double, Double)] -> Double -> Shape
convexPolygon cs r =
  let own = polygonCorners cs r
      n = fromIntegral (length cs)
      reach = polygonReach n r own
      padded = take maxHullCorners (own ++ repeat (0, 0))
      outline :: Field a => a -> a
      outline theta = verticesOutline (constant n) (constant r) [ (constant a, constant b) | (a, b) <- padded ] theta / constant reach
  in Shape "vertices" (Just (VerticesShape cs r)) (Outline outline)

-- | A built-in shape with numbers of its own: its outline is
-- 'codeOutline''s, as the page's engine makes it.
builtIn :: String -> ShapeKind -> Shape
builtIn name k =
  let (code, p, q) = shapeArgs k
  in Shape name (Just k) (Outline (codeOutline (constant code) (constant p) (constant q)))

-- Mass -------------------------------------------------------------------

-- | A body's mass and moment of inertia ('massProperties').
data MassProperties = MassProperties
  { mass :: Double
  , inertia :: Double -- ^ about the centre, in the body's plane
  } deriving (Show, Eq)

-- | Midpoint-rule samples of the outline over one turn (for the centroid;
-- the mass integrals take 'massSamples')
samples :: Int
samples = 4096

integrateTurn :: (Double -> Double) -> Double
integrateTurn g =
  let h = 2 * pi / fromIntegral samples
  in h * sum [g ((fromIntegral k + 0.5) * h) | k <- [0 .. samples - 1]]

-- | @½ ∫ s(θ)² dθ@: the area of the flat shape (its mass at density 1),
-- by the midpoint rule.
--
-- >>> areaOf circle 1
-- 3.141592653589793
-- >>> areaOf square 1 -- 2: a polygon of its corners
-- 2.0
-- >>> areaOf (regularPolygon 12) 1 -- 3, less what the samples miss of the corners
-- 2.9999988790937273
areaOf :: Shape -> Double -> Double
areaOf s size = mass (massProperties s size 1)

-- | Mass @ρ · ½∫s²dθ@ and moment of inertia @ρ · ¼∫s⁴dθ@ (the polar
-- integral of r² over the shape), measured in the flat tangent plane as in
-- the paper: 'massIntegrals', as the engine computes them for a body it
-- adds; a box's and a capsule's in closed form ('hullMass'), and a convex
-- polygon's, a square's and a regular polygon's of up to eight sides
-- ('polygonMass').
--
-- >>> massProperties circle 1 1 -- π and π/2
-- MassProperties {mass = 3.141592653589793, inertia = 1.5707963267948966}
massProperties :: Shape -> Double -> Double -> MassProperties
massProperties s size density = case fmap shapeArgs (shapeKind s) of
  Just (_, n, r) | Just (VerticesShape cs _) <- shapeKind s -> uncurry MassProperties (polygonMass n r (polygonCorners cs r) density)
  Just (code, _, _) | isRegularHull code > 0 ->
    let own = centredCorners code 0 (orientCorners code (regularCorners code size))
    in uncurry MassProperties (polygonMass code 0 own density)
  Just (code, p, q) | hullCorners code p >= 2 -> uncurry MassProperties (hullMass code p q density)
  _ -> unsafePerformIO $ runNative $ do
    let Outline outline = shapeOutline s
    (m, i) <- massIntegrals outline size density
    pure (MassProperties m i)
{-# NOINLINE massProperties #-}

-- | Midpoint-rule samples of the outline for the mass integrals.
massSamples :: Int
massSamples = 1024

-- | The mass and moment of inertia of an outline (of size 1, scaled by
-- @size@) at a density, by the midpoint rule over 'massSamples' directions:
-- the one definition, run natively ('massProperties') and staged into the
-- engine's body placement ("Manifold.Population").
massIntegrals :: Imp m => (Scalar m -> Scalar m) -> Scalar m -> Scalar m -> m (Scalar m, Scalar m)
{-# INLINE massIntegrals #-}
massIntegrals outline size density = do
  area <- newRef 0
  quartic <- newRef 0
  let h = constant (2 * pi / fromIntegral massSamples)
  forEach (fromIntegral massSamples) $ \k -> do
    s <- share (size * outline ((toScalar k + 0.5) * h))
    s2 <- share (s * s)
    modifyRef area (+ s2)
    modifyRef quartic (+ s2 * s2)
  a2 <- readRef area
  a4 <- readRef quartic
  m <- share (density * 0.5 * h * a2)
  inertia <- share (density * 0.25 * h * a4)
  pure (m, inertia)

-- | The centroid of the flat shape relative to its centre,
-- @(⅔ ∫ s³ e^{iθ} dθ) / ∫ s² dθ@. The centre acts as the centre of mass when
-- this vanishes.
centroidOffset :: Shape -> Double -> V2 Double
centroidOffset s size =
  let m3 = V2 (integrateTurn (\t -> outlineAt s size t ^ (3 :: Int) * cos t))
              (integrateTurn (\t -> outlineAt s size t ^ (3 :: Int) * sin t))
      a2 = integrateTurn (\t -> outlineAt s size t ^ (2 :: Int))
  in (2 / 3 / a2) *^ m3

-- | The paper's centre-of-mass condition @∫ s(θ)² e^{iθ} dθ = 0@ (it vanishes
-- together with 'centroidOffset' for every shape with a symmetry of order 2
-- or more, which all the built-in shapes have).
paperMomentIntegral :: Shape -> Double -> V2 Double
paperMomentIntegral s size =
  V2 (integrateTurn (\t -> outlineAt s size t ^ (2 :: Int) * cos t))
     (integrateTurn (\t -> outlineAt s size t ^ (2 :: Int) * sin t))

-- Polygons ---------------------------------------------------------------

-- | How finely a body's geodesic polygon is walked (paper §3.4).
data PolygonParams = PolygonParams
  { polyDirections :: Int -- ^ geodesics walked from the centre (paper: 24)
  , polySteps :: Int -- ^ geodesic steps along each (paper: 4)
  } deriving (Show, Eq)

-- | The paper's polygon: 24 directions of 4 steps.
defaultPolygonParams :: PolygonParams
defaultPolygonParams = PolygonParams 24 4

-- | A body's geodesic polygon in world coordinates. Vertex 0 is the centre;
-- vertex @'vertexIndex' d j = d·steps + j@ is step @j@ along direction @d@.
data Polygon a = Polygon
  { polyVertices :: [V3 a]
  , polyLocal :: [(a, a)] -- ^ each vertex's local polar coordinates (r, θ)
  , polyTriangles :: [(Int, Int, Int)] -- ^ the centre fan, then quads as two triangles
  , polyOutline :: [V3 a] -- ^ the outermost ring, in direction order
  }

-- | The vertices of a body's polygon: the centre and every step of every
-- direction.
--
-- >>> vertexCount defaultPolygonParams
-- 97
vertexCount :: PolygonParams -> Int
vertexCount (PolygonParams d s) = 1 + d * s

-- | Where step @j@ (1 … steps) along direction @d@ (0 … directions − 1)
-- sits among a body's polygon vertices (vertex 0 is the centre): the one
-- definition of the layout, used by the polygon walk, the narrow phase and,
-- generated, the page.
--
-- >>> vertexIndex defaultPolygonParams 2 (3 :: Int)
-- 11
vertexIndex :: Num a => PolygonParams -> a -> a -> a
vertexIndex pp d j = d * fromIntegral (polySteps pp) + j

-- | The triangles of a body's polygon ('polyTriangles'): a fan round the
-- centre, then two a quad.
--
-- >>> triangleCount defaultPolygonParams
-- 168
triangleCount :: PolygonParams -> Int
triangleCount (PolygonParams d s) = d + 2 * d * (s - 1)

-- | The body-local angle of direction @d@.
directionAngle :: Field a => PolygonParams -> Int -> a
directionAngle pp d = constant (2 * pi * fromIntegral d / fromIntegral (polyDirections pp))

-- | The sector boundaries between @nd@ directions (their cosines and sines),
-- worked out once for every 'directionSector' that uses them: the generic
-- native step calls it for every outline vertex near another body, with the
-- number of directions known only at run time.
-- (The count, then the cosine and the sine of boundary j's angle, 2πj/nd.)
data Sectors = Sectors !Int !(U.Vector Double) !(U.Vector Double)

-- | The 'Sectors' of @nd@ directions (at least one).
sectors :: Int -> Sectors
sectors nd
  | nd < 1 = error ("sectors: at least one direction, got " ++ show nd)
  | otherwise = Sectors nd (U.generate nd (cos . angle)) (U.generate nd (sin . angle))
  where angle j = 2 * pi / fromIntegral nd * fromIntegral j

-- | Of the @nd@ equal sectors between the directions, the one (0 to nd − 1)
-- that holds the body-local direction @(x, y)@, measured from direction 0:
-- the floor of its angle over @2π/nd@ (0 at the origin; a direction exactly
-- on a boundary may count on either side).
--
-- >>> map (\t -> directionSector (sectors 24) (cos t) (sin t :: Double)) [0.1, 1, pi + 0.1]
-- [0.0,3.0,12.0]
--
-- Counted, not measured: the sector boundaries a direction has passed are
-- those it lies counter-clockwise of, a cross product each with a constant.
-- The narrow phase finds a sector for every outline vertex near another
-- body, and this needs no arctangent, root, division or floor, the most
-- expensive parts of that lookup. With an even @nd@ the lower half turn is
-- first turned onto the upper, which halves the boundaries to count.
directionSector :: Field a => Sectors -> a -> a -> a
{-# INLINE directionSector #-}
directionSector (Sectors nd cosines sines) x y
  | even nd =
      let lower = negate y -- positive below the x axis
          x' = select lower (negate x) x
          y' = select lower (negate y) y
      in select lower (fromIntegral half) 0 + passed x' y' 1 (half - 1)
  | otherwise =
      -- below the x axis every boundary of the upper half (2j < nd) is
      -- passed, above it none of the lower half (2j > nd) is
      let lower = negate y
      in select lower (fromIntegral half + passed x y (half + 1) (nd - 1)) (passed x y 1 half)
  where
    half = nd `div` 2
    -- boundaries lo to hi, summed from the left as 'sum' would (the staged
    -- expression is the same), in a loop that natively allocates nothing
    passed u v lo hi = go lo 0
      where
        go !j !acc
          | j > hi = acc
          | otherwise =
              go (j + 1) (acc + select (constant (cosines U.! j) * v - constant (sines U.! j) * u) 1 0)

-- | Walk the outline: from the centre @p@ with unit tangent axis @axis@ and
-- angle @angle@, along a geodesic in each direction, in equal steps of
-- @s(θ)/steps@, re-projecting every step.
polygonise :: Field a => Metric -> ScalarFn -> PolygonParams -> Shape -> a -> V3 a -> V3 a -> a -> Polygon a
polygonise m f pp shape size p axis angle =
  let n = unitNormal m f p
      (u, w) = tangentFrame m n axis
      nd = polyDirections pp
      ns = polySteps pp
      walk d =
        let theta = directionAngle pp d
            phi = angle + theta
            dir = cos phi *^ u ^+^ sin phi *^ w
            r = outlineAt shape size theta
            h = r / fromIntegral ns
            ring = take ns (tail (iterate (geodesicStep m f h) (p, dir)))
        in ( map fst ring
           , [(r * fromIntegral j / fromIntegral ns, theta) | j <- [1 .. ns]] )
      walks = map walk [0 .. nd - 1]
      vertex d = vertexIndex pp (d `mod` nd)
      fan = [(0, vertex d 1, vertex (d + 1) 1) | d <- [0 .. nd - 1]]
      quads = concat
        [ [ (vertex d j, vertex d (j + 1), vertex (d + 1) (j + 1))
          , (vertex d j, vertex (d + 1) (j + 1), vertex (d + 1) j) ]
        | d <- [0 .. nd - 1], j <- [1 .. ns - 1] ]
  in Polygon
      { polyVertices = p : concatMap fst walks
      , polyLocal = (0, 0) : concatMap snd walks
      , polyTriangles = fan ++ quads
      , polyOutline = map (last . fst) walks
      }
