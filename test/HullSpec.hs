{-# LANGUAGE OverloadedStrings #-}
-- | Bodies with exact hulls ("Manifold.Hull"): a box's and a capsule's
-- outline, mass and moment of inertia against closed forms and fine
-- integrals; their corners walked onto the sphere at their geodesic
-- distances and angles; and in the engine, a box resting on a box by two
-- points at its corners, a thin card lying on a box, and boxes, capsules
-- and circles coming to rest on a slab at their heights; picked by their
-- hulls.
module HullSpec (spec) where

import Control.Monad (forM, forM_, replicateM_)
import qualified Data.ByteString.Lazy.Char8 as BL
import qualified Data.Vector.Unboxed.Mutable as MV
import Linear.Metric (dot, norm)
import Linear.V3 (V3 (..), cross)
import Linear.Vector ((^-^))
import Test.Hspec

import Manifold
import Manifold.ContactManifold (maxHullCorners)
import Manifold.Engine
import Manifold.Hull
import Manifold.Scene
import Manifold.World

spec :: Spec
spec = describe "Manifold.Hull" $ do
  closedForms
  cornersOnTheSphere
  picking
  resting

-- | @∫₀^{2π} g@ by the midpoint rule in @n@ pieces.
integral :: Int -> (Double -> Double) -> Double
integral n g = let h = 2 * pi / fromIntegral n in h * sum [g ((fromIntegral k + 0.5) * h) | k <- [0 .. n - 1]]

closeRel :: Double -> Double -> Double -> Bool
closeRel tol expected x = abs (x - expected) <= tol * abs expected

closedForms :: Spec
closedForms = describe "shapes" $ do
  it "a box's outline reaches its corners and the middles of its sides, and lies on its sides between" $ do
    let (p, q) = (0.3, 0.1)
    boxOutline p q (atan2 q p) `shouldSatisfy` closeRel 1e-12 (sqrt (p * p + q * q))
    boxOutline p q 0 `shouldSatisfy` closeRel 1e-12 p
    boxOutline p q (pi / 2) `shouldSatisfy` closeRel 1e-12 q
    forM_ [0.05, 0.37 .. 6.2] $ \t -> do
      let r = boxOutline p q t
          (x, y) = (abs (r * cos t), abs (r * sin t))
      -- on the boundary: inside both slabs, on one of them
      max (x / p) (y / q) `shouldSatisfy` closeRel 1e-12 1
  it "a capsule's outline lies at its radius from its segment, in every direction" $ do
    let (l, r) = (0.2, 0.05)
        fromSegment x y = let cx = max (-l) (min l x) in sqrt ((x - cx) ^ (2 :: Int) + y * y)
    forM_ [0, 0.05 .. 6.3] $ \t -> do
      let s = capsuleOutline l r t
      fromSegment (s * cos t) (s * sin t) `shouldSatisfy` closeRel 1e-12 r
  it "a box's and a capsule's mass and moment of inertia: closed forms (1e-9), and the polar integrals of their outlines (1e-6)" $ do
    let density = 1.7
        (p, q) = (0.3, 0.1)
        (bm, bi) = hullMass boxCode p q density :: (Double, Double)
    bm `shouldSatisfy` closeRel 1e-9 (density * 2 * p * 2 * q)
    bi `shouldSatisfy` closeRel 1e-9 (density * 2 * p * 2 * q * ((2 * p) ^ (2 :: Int) + (2 * q) ^ (2 :: Int)) / 12)
    -- a capsule: the rectangle, and the disc of its two caps, whose halves
    -- sit at ±L (each half's moment about the centre: by the polar
    -- integral of a half disc about its own centre, carried along)
    let (l, r) = (0.2, 0.05)
        (cm, ci) = hullMass capsuleCode l r density :: (Double, Double)
        halfDiscAbout d = density * (pi * r ^ (4 :: Int) / 4 + pi * r * r / 2 * d * d + 2 * d * (2 * r ^ (3 :: Int) / 3))
    cm `shouldSatisfy` closeRel 1e-9 (density * (4 * l * r + pi * r * r))
    ci `shouldSatisfy` closeRel 1e-9 (density * 4 * l * r * (l * l + r * r) / 3 + 2 * halfDiscAbout l)
    -- against the outlines: ρ·½∫s², ρ·¼∫s⁴
    let polar outline = (density * 0.5 * integral 400000 (\t -> outline t ^ (2 :: Int)), density * 0.25 * integral 400000 (\t -> outline t ^ (4 :: Int)))
        (bm', bi') = polar (boxOutline p q)
        (cm', ci') = polar (capsuleOutline l r)
    [bm', bi', cm', ci'] `shouldSatisfy` and . zipWith (closeRel 1e-6) [bm, bi, cm, ci]
  it "names a box's and a capsule's numbers their size, and gives the mass of a body added as the closed form" $ do
    shapeSize (BoxShape 0.3 0.4) `shouldBe` Just 0.5
    shapeSize (CapsuleShape 0.2 0.05) `shouldBe` Just 0.25
    massProperties (box 0.3 0.1) 0 2 `shouldBe` uncurry MassProperties (hullMass boxCode 0.3 0.1 2)
    w <- newWorld plane (layout 2)
    Right i <- addBody w (BodyInit (capsule 0.2 0.05) 0.25 2 False (V3 0 0 0) (V3 0 0 0) 0 0 sceneMaterial)
    invMass <- MV.read (wScalars (nwArrays w)) (scalarSlots * i + fromEnum InvMass)
    recip invMass `shouldSatisfy` closeRel 1e-12 (fst (hullMass capsuleCode 0.2 0.05 2))

  polygons

-- | Convex polygons of their own corners: mass against closed forms and
-- the polar integrals of their outlines, the outline at the radius from
-- the polygon, the centre of mass at the origin, either orientation.
polygons :: Spec
polygons = describe "convex polygons" $ do
  let padded cs = take maxHullCorners (cs ++ repeat (0, 0))
      density = 1.3
  it "a box's, a right triangle's (m(a² + b²)/18 about its centroid) and a rounded polygon's mass and moment of inertia: closed forms (1e-12)" $ do
    let (p, q) = (0.3, 0.1)
    polygonMass 4 0 (padded (polygonCorners [(-p, -q), (p, -q), (p, q), (-p, q)] 0)) density
      `shouldSatisfy` (\(m, i) -> closeRel 1e-12 (fst (hullMass boxCode p q density)) m && closeRel 1e-12 (snd (hullMass boxCode p q density)) i)
    let (a, b) = (0.3, 0.2)
        (tm, ti) = polygonMass 3 0 (padded (polygonCorners [(0, 0), (a, 0), (0, b)] 0)) density
    tm `shouldSatisfy` closeRel 1e-12 (density * a * b / 2)
    ti `shouldSatisfy` closeRel 1e-12 (tm * (a * a + b * b) / 18)
    -- rounded: the polygon, a rectangle on each side, a disc at the corners
    let r = 0.04
        (rm, _) = polygonMass 3 r (padded (polygonCorners [(0, 0), (a, 0), (0, b)] r)) density
    rm `shouldSatisfy` closeRel 1e-12 (density * (a * b / 2 + (a + b + sqrt (a * a + b * b)) * r + pi * r * r))
  it "a rounded polygon's outline lies at its radius from the polygon in every direction, and its polar integrals give its mass and moment of inertia about its centre of mass (1e-6)" $
    forM_ [([(0, 0), (0.3, 0), (0, 0.2)], 0.04), ([(-0.1, -0.02), (0.2, -0.05), (0.25, 0.1), (0.05, 0.15), (-0.12, 0.08)], 0), ([(0.1, 0), (0, 0.1), (-0.1, 0), (0, -0.1)], 0.02)] $ \(given, r) -> do
      let own = polygonCorners given r
          n = fromIntegral (length own)
          outline = verticesOutline n r (padded own)
          segment (ax, ay) (bx, by) (x, y) =
            let (ex, ey) = (bx - ax, by - ay)
                t = max 0 (min 1 (((x - ax) * ex + (y - ay) * ey) / (ex * ex + ey * ey)))
            in sqrt ((x - ax - t * ex) ^ (2 :: Int) + (y - ay - t * ey) ^ (2 :: Int))
          fromPolygon pt = minimum (zipWith (\c d -> segment c d pt) own (tail own ++ [head own]))
      forM_ [0, 0.013 .. 6.28] $ \t -> do
        let s = outline t
        abs (fromPolygon (s * cos t, s * sin t) - r) `shouldSatisfy` (< 1e-12)
      -- the midpoint rule over the outline, sampled once
      let pieces = 40000 :: Int
          h = 2 * pi / fromIntegral pieces
          sampled = [ (t, outline t) | k <- [0 .. pieces - 1], let t = (fromIntegral k + 0.5) * h ]
          polar g = h * sum [ g t o | (t, o) <- sampled ]
          (m, i) = polygonMass n r (padded own) density
      (density * 0.5 * polar (\_ o -> o ^ (2 :: Int))) `shouldSatisfy` closeRel 1e-6 m
      (density * 0.25 * polar (\_ o -> o ^ (4 :: Int))) `shouldSatisfy` closeRel 1e-6 i
      -- the centre of mass: the first moments of the outline vanish
      let first f = density * polar (\t o -> o ^ (3 :: Int) * f t / 3)
      abs (first cos) `shouldSatisfy` (< 1e-9)
      abs (first sin) `shouldSatisfy` (< 1e-9)
  it "takes corners given clockwise as the same polygon, and names its size how far it reaches" $ do
    let given = [(-0.04, 0.05), (0.06, 0.03), (0.05, -0.04), (-0.05, -0.03)]
    polygonCorners (reverse given) 0.01 `shouldBe` polygonCorners given 0.01
    let Just reach = shapeSize (VerticesShape given 0.01)
    reach `shouldSatisfy` closeRel 1e-12 (0.01 + maximum [sqrt (a * a + b * b) | (a, b) <- polygonCorners given 0.01])
  it "adds a polygon body with its closed-form mass, its corners about its centre of mass, and its size how far it reaches" $ do
    w <- newWorld plane (layout 2)
    let shape = VerticesShape [(0, 0), (0.3, 0), (0, 0.2)] 0.01
    Right i <- addBody w (BodyInit (shapeFromKind shape) 0 2 False (V3 0 0 0) (V3 0 0 0) 0 0 sceneMaterial)
    let slot :: Slot -> IO Double
        slot f = MV.read (wScalars (nwArrays w)) (scalarSlots * i + fromEnum f)
        own = polygonCorners [(0, 0), (0.3, 0), (0, 0.2)] 0.01
    invMass <- slot InvMass
    recip invMass `shouldSatisfy` closeRel 1e-12 (fst (polygonMass 3 0.01 (padded own) 2))
    slot Corners `shouldReturn` 3
    locals <- forM [0 .. 2] $ \k -> (,) <$> MV.read (wHull (nwArrays w)) (hullStride * i + hullLocalAt k) <*> MV.read (wHull (nwArrays w)) (hullStride * i + hullLocalAt k + 1)
    and (zipWith close2 locals own) `shouldBe` True
    bound <- slot BoundRadius
    bound `shouldSatisfy` (>= polygonReach 3 0.01 (padded own) - 1e-12)
  it "makes a square and a regular polygon of up to eight sides the polygon of its corners (a side facing its direction), its mass exact; one of more sides keeps its outline" $ do
    w <- newWorld plane (layout 3)
    Right sq <- addBody w (BodyInit square 0.1 2 False (V3 0 0 0) (V3 0 0 0) 0 0 sceneMaterial)
    Right oct <- addBody w (BodyInit (regularPolygon 8) 0.1 1 False (V3 1 0 0) (V3 0 0 0) 0 0 sceneMaterial)
    Right dodeca <- addBody w (BodyInit (regularPolygon 12) 0.1 1 False (V3 2 0 0) (V3 0 0 0) 0 0 sceneMaterial)
    let slot :: Int -> Slot -> IO Double
        slot i f = MV.read (wScalars (nwArrays w)) (scalarSlots * i + fromEnum f)
        local :: Int -> Int -> IO (Double, Double)
        local i k = (,) <$> MV.read (wHull (nwArrays w)) (hullStride * i + hullLocalAt k) <*> MV.read (wHull (nwArrays w)) (hullStride * i + hullLocalAt k + 1)
        h = 0.1 / sqrt 2
    mapM (`slot` Corners) [sq, oct, dodeca] `shouldReturn` [4, 8, 0]
    corners <- mapM (local sq) [0 .. 3]
    and (zipWith close2 corners [(h, -h), (h, h), (-h, h), (-h, -h)]) `shouldBe` True
    -- a square of side 2h: mass 4h²ρ, inertia m(2h)²/6; its Size its inradius
    invMass <- slot sq InvMass
    recip invMass `shouldSatisfy` closeRel 1e-12 (4 * h * h * 2)
    invInertia <- slot sq InvInertia
    recip invInertia `shouldSatisfy` closeRel 1e-12 (4 * h * h * 2 * (2 * h) ^ (2 :: Int) / 6)
    slot sq Size >>= (`shouldSatisfy` closeRel 1e-12 h)
  where
    close2 (a, b) (c, d) = abs (a - c) < 1e-12 && abs (b - d) < 1e-12

-- | Body @i@'s corner @k@ as the last polygon walk left it.
corner :: NativeWorld -> Int -> Int -> IO (V3 Double)
corner w i k = do
  let at :: Int -> IO Double
      at o = MV.read (wHull (nwArrays w)) (hullStride * i + hullWorldAt k + o)
  V3 <$> at 0 <*> at 1 <*> at 2

cornersOnTheSphere :: Spec
cornersOnTheSphere = describe "corners" $
  it "walks a box's corners onto the unit sphere at their geodesic distance from the centre and their angles, as closely as the outline's walk (its steps h: h^2/3)" $ do
    let (p, q) = (0.4, 0.25)
    forM_ [(0.05, 0), (0.3, 1.1)] $ \(size, angle) -> do
      -- large enough that the corners are walked in four steps, and small
      -- enough for one (the polygon step is 0.05)
      let (p', q') = (p * size / 0.3, q * size / 0.3)
      w <- newWorld sphere (layout 1)
      Right _ <- addBody w (BodyInit (box p' q') 0 1 False (V3 0.3 0.8 0.5) (V3 0 0 0) angle 0 sceneMaterial)
      st <- readBody w 0
      let c = bsPos st
          n = bsNormal st
          e1 = cos angle `scale` bsAxis st + sin angle `scale` (n `cross` bsAxis st)
      forM_ (zip [0 ..] [(-p', -q'), (p', -q'), (p', q'), (-p', q')]) $ \(k, (a, b)) -> do
        v <- corner w 0 k
        norm v `shouldSatisfy` closeRel 1e-9 1
        -- the great circle's arc, and the direction it leaves the centre
        -- in, to within what one step of the walk (RATTLE) misses by: a
        -- relative h^2/3 (the step lands at atan h for h), one step for a body no larger than the polygon
        -- step, four for a larger one
        let r = sqrt (a * a + b * b)
            h = if size > 0.05 then r / 4 else r
            t = v ^-^ (c `dot` v) `scale` c
            heading = atan2 (t `dot` (n `cross` e1)) (t `dot` e1)
        acos (c `dot` v) `shouldSatisfy` closeRel (h * h / 3) r
        abs (heading - atan2 b a) `shouldSatisfy` (< h * h / 3)
  where scale s (V3 x y z) = V3 (s * x) (s * y) (s * z)

picking :: Spec
picking = describe "picking" $
  it "picks a box in its corners and not just beyond them (plane and sphere), a capsule within its rounded ends, as they are drawn" $ do
    forM_ [(plane, V3 0 0 0, False), (sphere, V3 0.3 0.8 0.5, True)] $ \(sp, at, curved) -> do
      w <- newWorld sp (layout 1)
      Right _ <- addBody w (BodyInit (box 0.2 0.1) 0 1 False at (V3 0 0 0) 0.3 0 sceneMaterial)
      c <- bsPos <$> readBody w 0
      forM_ [0 .. 3] $ \k -> do
        v <- corner w 0 k
        -- 5 % of the way from the corner to the centre, and beyond it; on
        -- the sphere put back on it
        let onSurface p = if curved then p `over` norm p else p
            toward f = onSurface (c + f `times` (v ^-^ c))
        pickAt w (toward 0.95) `shouldReturn` Just (0, 1)
        pickAt w (toward 1.05) `shouldReturn` Nothing
    w <- newWorld plane (layout 1)
    Right _ <- addBody w (BodyInit (capsule 0.15 0.05) 0 1 False (V3 0 0 0) (V3 0 0 0) 0 0 sceneMaterial)
    st <- readBody w 0
    let e1 = bsAxis st
        e2 = bsNormal st `cross` e1
        point a b = a `times` e1 + b `times` e2
    mapM (pickAt w) [point 0.195 0, point 0.18 0.035, point (-0.15) 0.045] `shouldReturn` replicate 3 (Just (0, 1))
    mapM (pickAt w) [point 0.205 0, point 0.19 0.035, point 0 0.055] `shouldReturn` replicate 3 Nothing
  where
    times s (V3 x y z) = V3 (s * x) (s * y) (s * z)
    over (V3 x y z) s = V3 (x / s) (y / s) (z / s)

-- | A scene from its JSON text, loaded.
loaded :: BL.ByteString -> IO NativeWorld
loaded text = either fail pure (parseScene text) >>= loadScene 0 >>= either fail pure

-- | The contact rows of the last step between bodies @a@ and @b@: their
-- points.
contactPoints :: NativeWorld -> Int -> Int -> IO [V3 Double]
contactPoints w a b = map fst <$> contactRows w a b

-- | The element with the least measure.
minimumOn :: Ord b => (a -> b) -> [a] -> a
minimumOn f = foldr1 (\x y -> if f x <= f y then x else y)

-- | The contact rows of the last step between bodies @a@ and @b@: their
-- points and keys.
contactRows :: NativeWorld -> Int -> Int -> IO [(V3 Double, Double)]
contactRows w a b = do
  n <- contactCount w
  rows <- forM [0 .. n - 1] $ \c -> do
    let field :: ContactField -> IO Double
        field f = MV.read (wContacts (nwArrays w)) (contactStride * c + fromEnum f)
    ca <- field CA
    cb <- field CB
    point <- V3 <$> field PointX <*> field PointY <*> field PointZ
    key <- field CKey
    pure [(point, key) | (round ca, round cb) `elem` [(a, b), (b, a)]]
  pure (concat rows)

resting :: Spec
resting = describe "in the engine" $ do
  it "rests a box on a box by two points, at the upper box's lower corners (flat: 1e-3 of its size), level and still after 3 s" $ do
    w <- loaded "{\"space\": \"plane\", \"bodies\": [{\"shape\": {\"box\": [0.3, 0.05]}, \"static\": true, \"p\": [0, 0, -0.05]},\
                \ {\"shape\": {\"box\": [0.1, 0.04]}, \"p\": [0.05, 0, 0.045]}]}"
    replicateM_ 300 (stepNative w)
    st <- readBody w 1
    bsAngle st `shouldSatisfy` (\a -> abs a < 1e-6)
    let V3 x _ z = bsPos st
    abs (x - 0.05) `shouldSatisfy` (< 1e-4)
    abs (z - 0.04) `shouldSatisfy` (< 2e-4)
    norm (bsVel st) `shouldSatisfy` (< 1e-3)
    -- a step's contacts, found where the box lies
    w' <- loaded "{\"space\": \"plane\", \"bodies\": [{\"shape\": {\"box\": [0.3, 0.05]}, \"static\": true, \"p\": [0, 0, -0.05]},\
                 \ {\"shape\": {\"box\": [0.1, 0.04]}, \"p\": [0.05, 0, 0.04]}]}"
    stepNative w'
    points <- contactPoints w' 0 1
    length points `shouldBe` 2
    let xs = [px | V3 px _ _ <- points]
    minimum xs `shouldSatisfy` (\v -> abs (v - (-0.05)) < 1e-3 * 0.1)
    maximum xs `shouldSatisfy` (\v -> abs (v - 0.15) < 1e-3 * 0.1)
  it "keys a row by the corner it is at: a box tipped onto either lower corner keeps the key that corner's row had with the box level" $ do
    -- (a 0.2 by 0.08 box, its lowest corner 1e-3 into the slab)
    let rowsAt :: Double -> IO [(V3 Double, Double)]
        rowsAt angle = do
          let z = 0.1 * sin (abs angle) + 0.04 * cos angle - 1e-3
          w <- loaded (BL.pack ("{\"space\": \"plane\", \"bodies\": [{\"shape\": {\"box\": [0.3, 0.05]}, \"static\": true, \"p\": [0, 0, -0.05]},\
                                \ {\"shape\": {\"box\": [0.1, 0.04]}, \"p\": [0.05, 0, " ++ show z ++ "], \"angle\": " ++ show angle ++ "}]}"))
          stepNative w
          contactRows w 0 1
    level <- rowsAt 0
    map snd level `shouldSatisfy` (\case [k1, k2] -> k1 /= k2; _ -> False)
    -- (a positive angle turns the box's +x end down)
    forM_ [(0.3, 0.1337), (-0.3, -0.0337)] $ \(angle, cornerX) -> do
      tipped <- rowsAt angle
      case tipped of
        [(V3 x _ _, key)] -> do
          abs (x - cornerX) `shouldSatisfy` (< 1e-3)
          let nearest = snd (minimumOn (\(V3 lx _ _, _) -> abs (lx - x)) level)
          (angle, key) `shouldBe` (angle, nearest)
        _ -> expectationFailure ("tipped by " ++ show angle ++ ": expected one row, got " ++ show tipped)
  -- (the paper's jam, §4.2, with a card: girth 2π·e^y is its length 1 at
  -- y = −1.84)
  it "jams a card (1 by 0.04) thrown across the trumpet's neck where the neck's girth is about its length (its corners' self-contact), and one thrown along the neck only where its width wraps" $ do
    let thrown :: Double -> IO (Double, Double, Double)
        thrown angle = do
          w <- loaded (BL.pack ("{\"space\": \"trumpet\", \"sleep\": false, \"bodies\": [{\"shape\": {\"box\": [0.5, 0.02]},\
                                \ \"p\": [1.6, 0.5, 0], \"v\": [0, -1, 0], \"angle\": " ++ show angle ++ "}]}"))
          replicateM_ 1200 (stepNative w)
          before <- readBody w 0
          replicateM_ 300 (stepNative w)
          after <- readBody w 0
          let height s = let V3 _ y _ = bsPos s in y
          pure (height after, abs (height after - height before), norm (bsVel after))
    (across, drift, speed) <- thrown (pi / 2)
    (along, _, _) <- thrown 0
    (across, drift, speed) `shouldSatisfy` (\(y, d, v) -> y > -2 && y < -1.5 && d < 1e-3 && v < 1e-3)
    along `shouldSatisfy` (< -4)
  -- (of equal mass: a heavy body on a light one sinks into it by the soft
  -- contact's give, g/omega^2 times the masses' ratio)
  it "keeps a card 0.001 thick and 0.2 long lying on a box, and a box of its mass resting on the card (200 : 1), each within 1e-4 of its height" $ do
    w <- loaded "{\"space\": \"plane\", \"bodies\": [{\"shape\": {\"box\": [0.3, 0.05]}, \"static\": true, \"p\": [0, 0, -0.05]},\
                \ {\"shape\": {\"box\": [0.1, 0.0005]}, \"density\": 8, \"p\": [0, 0, 0.003], \"angle\": 0.02},\
                \ {\"shape\": {\"box\": [0.02, 0.02]}, \"p\": [0.04, 0, 0.05]}]}"
    replicateM_ 400 (stepNative w)
    card <- readBody w 1
    top <- readBody w 2
    let height s = let V3 _ _ z = bsPos s in z
    height card `shouldSatisfy` (\z -> abs (z - 0.0005) < 1e-4)
    abs (bsAngle card) `shouldSatisfy` (< 1e-3)
    height top `shouldSatisfy` (\z -> abs (z - 0.021) < 1e-4)
    warningCount w `shouldReturn` 0
  it "brings a box and a capsule at rest on the rectangle's floor (the boundary, met by their corners) to their heights (2e-4), level" $ do
    -- (a 10 : 3 box's corners lie between its outline's directions: by the
    -- outline it sank at them)
    w <- loaded "{\"space\": \"rectangle\", \"bodies\": [{\"shape\": {\"box\": [0.1, 0.03]}, \"p\": [-0.4, 0, -0.6], \"angle\": 0.5},\
                \ {\"shape\": {\"capsule\": [0.08, 0.025]}, \"p\": [0.4, 0, -0.6], \"angle\": -0.4}]}"
    replicateM_ 500 (stepNative w)
    states <- forM [0, 1] (readBody w)
    let heights = [z | s <- states, let V3 _ _ z = bsPos s]
    zipWith (\h z -> abs (h - z) < 2e-4) [-0.97, -0.975] heights `shouldBe` [True, True]
    -- level: a multiple of a half turn
    [abs (sin (bsAngle s)) < 1e-3 | s <- states] `shouldBe` [True, True]
  it "brings boxes, capsules and circles at rest on a slab to their heights: half a side, a radius (2e-4)" $ do
    w <- loaded "{\"space\": \"plane\", \"bodies\": [{\"shape\": {\"box\": [1, 0.05]}, \"static\": true, \"p\": [0, 0, -0.05]},\
                \ {\"shape\": {\"box\": [0.06, 0.03]}, \"p\": [-0.5, 0, 0.2], \"angle\": 0.3},\
                \ {\"shape\": {\"capsule\": [0.06, 0.02]}, \"p\": [0, 0, 0.2], \"angle\": 0.2},\
                \ {\"shape\": \"circle\", \"size\": 0.05, \"p\": [0.5, 0, 0.2]}]}"
    replicateM_ 600 (stepNative w)
    let height s = let V3 _ _ z = bsPos s in z
    heights <- forM [1, 2, 3] (fmap height . readBody w)
    zipWith (\h z -> abs (h - z) < 2e-4) [0.03, 0.02, 0.05] heights `shouldBe` [True, True, True]
  it "brings a right triangle, a rounded pentagon and a plank of eight corners at rest on a slab to their heights: a third of the leg up, the inradius and radius, half the plank's thickness (2e-4)" $ do
    -- (b is along normal × direction: −z on the plane; the triangle's third
    -- corner is above its first leg)
    let pentagon = concat [ "[" ++ show (0.05 * cos t :: Double) ++ ", " ++ show (0.05 * sin t :: Double) ++ "]" ++ (if k < 4 then ", " else "")
                          | k <- [0 .. 4 :: Int], let t = 2 * pi * fromIntegral k / 5 ]
    w <- loaded (BL.pack ("{\"space\": \"plane\", \"bodies\": [{\"shape\": {\"box\": [1, 0.05]}, \"static\": true, \"p\": [0, 0, -0.05]},\
                \ {\"shape\": {\"vertices\": [[0, 0], [0.1, 0], [0, -0.06]]}, \"p\": [-0.5, 0, 0.05], \"angle\": 0.1},\
                \ {\"shape\": {\"vertices\": [" ++ pentagon ++ "], \"radius\": 0.01}, \"p\": [0, 0, 0.1], \"angle\": 0.2},\
                \ {\"shape\": {\"vertices\": [[-0.12, -0.01], [-0.08, -0.015], [0.08, -0.015], [0.12, -0.01], [0.12, 0.01], [0.08, 0.015], [-0.08, 0.015], [-0.12, 0.01]]}, \"p\": [0.5, 0, 0.05], \"angle\": -0.1}]}"))
    replicateM_ 600 (stepNative w)
    let height s = let V3 _ _ z = bsPos s in z
    heights <- forM [1, 2, 3] (fmap height . readBody w)
    zipWith (\h z -> abs (h - z) < 2e-4) [0.02, 0.05 * cos (pi / 5) + 0.01, 0.015] heights `shouldBe` [True, True, True]
    warningCount w `shouldReturn` 0
