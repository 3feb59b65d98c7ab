-- | The golden runs: the catalogue's scenes, each run for a number of steps
-- and fingerprinted by the hash of its final state ("Manifold.StateHash").
-- The test suite keeps their hashes (@test/golden/hashes@, which
-- @manifold hashes@ prints and @scripts/regolden@ rewrites) and checks
-- that the compiled native step, the generic one and the page's engine
-- all end on them: a change to the physics changes a hash, and never
-- passes unnoticed.
module Manifold.Golden
  ( GoldenRun (..)
  , goldenRuns
  , defaultScene
  , runHash
  , goldenLine
  ) where

import Control.Monad (replicateM_)
import Data.Maybe (fromMaybe)
import Data.Word (Word64)
import Linear.V3 (V3 (..))

import Manifold.Bench (benchScene, benchSpaces)
import Manifold.Engine
import Manifold.Scene
import Manifold.Space
import Manifold.Body (shapeSize)
import Manifold.Spaces (bolza, catalogue, flatKlein, plane, projectivePlane, rectangle, sphere)
import Manifold.StateHash (showHash)

-- | A scene, its name (a file name: @SPACE-default@, @SPACE-N@) and how
-- many steps it runs.
data GoldenRun = GoldenRun
  { grName :: String
  , grScene :: Scene
  , grSteps :: Int
  }

-- | Every catalogue space's default scene (what the page starts with: its
-- bodies at rest, falling), 1000 steps; the benchmark piles of 300 bodies
-- on the benchmark spaces, 600 steps (as they fall and pile up, contacts
-- at every step), and of 1000 bodies, 200 steps; two jointed scenes (every
-- kind of joint, a limit and a motor, across a quotient's flipped edge),
-- 600 steps; two stacks that fall asleep, one woken by a falling ball
-- and its joint to the world, 300 steps; and bodies of their own friction
-- and restitution thrown about the rectangle, 400 steps; boxes, capsules
-- and circles on the plane, the sphere and the projective plane, 500
-- steps; bodies thrown about the Bolza surface, 600 steps (60 of them).
goldenRuns :: [GoldenRun]
goldenRuns =
  [GoldenRun (spaceName sp ++ "-default") (defaultScene sp) 1000 | sp <- catalogue]
    ++ [ GoldenRun (spaceName sp ++ "-" ++ show n) (benchScene sp n) steps
       | (n, steps) <- [(300, 600), (1000, 200)], sp <- benchSpaces ]
    ++ [ GoldenRun "sphere-chain" sphereChain 600, GoldenRun "flat-klein-joints" flatKleinJoints 600 ]
    ++ [ GoldenRun "plane-sleep-wake" planeSleepWake 300 ]
    ++ [ GoldenRun "rectangle-materials" rectangleMaterials 400 ]
    ++ [ GoldenRun "plane-shapes" planeShapes 500, GoldenRun "sphere-shapes" sphereShapes 500
       , GoldenRun "projective-plane-shapes" projectivePlaneShapes 500
       , GoldenRun "sphere-polygons" spherePolygons 500 ]
    ++ [ GoldenRun "bolza-thrown" bolzaThrown 600 ]

-- | The Bolza surface's benchmark scene of 60 bodies, each thrown at
-- speed 1 in its own direction (no gravity there): they cross the
-- octagon's sides and meet through them and its corners.
bolzaThrown :: Scene
bolzaThrown =
  let s = benchScene bolza 60
      throw k b = let a = 2.4 * fromIntegral (k :: Int) in b { bsV = V3 (cos a) 0 (sin a) }
  in s { sceneBodies = zipWith throw [0 ..] (sceneBodies s) }

-- | A joint of a kind between bodies @a@ and @b@ (−1: the world) at
-- anchors @p@ and @q@, its settings left to the defaults.
jointAt :: JointKind -> Int -> Int -> V3 Double -> V3 Double -> JointSpec
jointAt k a b p q = JointSpec k a (if b < 0 then Nothing else Just b) p q Nothing Nothing Nothing 0 0 Nothing Nothing Nothing Nothing [] False

-- | A chain of 20 circles pinned where they touch, hung from a static one
-- on the equator, swinging down the sphere; its last link welded softly
-- to a square, and the square roped to the world.
sphereChain :: Scene
sphereChain =
  let r = 0.03
      at k = let a = 2 * r * fromIntegral (k :: Int) in V3 (cos a) 0 (sin a)
      pin k = let a = 2 * r * (fromIntegral (k :: Int) + 0.5) in V3 (cos a) 0 (sin a)
      bodies = BodySpec CircleShape r 1 True (at 0) (V3 0 0 0) 0 0 Nothing [] Nothing 0 sceneMaterial
               : [BodySpec CircleShape r 1 False (at k) (V3 0 0 0) 0 0 Nothing [] Nothing 0 sceneMaterial | k <- [1 .. 20]]
               ++ [BodySpec SquareShape r 1 False (at 21) (V3 0 0 0) 0 0 Nothing [] Nothing 0 sceneMaterial]
      pins = [ (jointAt Revolute k (k + 1) (pin k) (pin k)) { jsLimit = if k == 3 then Just (-0.5, 0.5) else Nothing
                                                            , jsMotor = if k == 7 then Just (1, 0.01) else Nothing }
             | k <- [0 .. 19] ]
      weld = (jointAt Weld 20 21 (pin 20) (pin 20)) { jsHertz = 5, jsDampingRatio = 0.5 }
      rope = (jointAt Distance 21 (-1) (at 21) (V3 0.8 (-0.6) 0)) { jsLength = Just 1.2, jsMinLength = Just 0, jsMaxLength = Just 1.2 }
  in Scene sphere defaultParams bodies (pins ++ [weld, rope]) Nothing

-- | Pairs of bodies joined across the flat Klein bottle's edges, thrown
-- so that they cross them (one pair through the flipped edge): a pin, a
-- distance spring, a weld.
flatKleinJoints :: Scene
flatKleinJoints =
  let body p v om = BodySpec CircleShape 0.06 1 False p v 0 om Nothing [] Nothing 0 sceneMaterial
      bodies = [ body (V3 0.8 0 0.3) (V3 1 0 0.2) 2, body (V3 0.92 0 0.3) (V3 1 0 0.2) 2
               , body (V3 0.2 0 0.85) (V3 0.1 0 0.8) (-1), body (V3 0.2 0 (-0.85)) (V3 0.1 0 0.8) 0
               , body (V3 (-0.5) 0 0) (V3 (-0.9) 0 0.1) 3, body (V3 (-0.62) 0 0) (V3 (-0.9) 0 0.1) 0 ]
      joints = [ jointAt Revolute 0 1 (V3 0.86 0 0.3) (V3 0.86 0 0.3)
               , (jointAt Distance 2 3 (V3 0.2 0 0.85) (V3 0.2 0 (-0.85))) { jsHertz = 2, jsDampingRatio = 0.1 }
               , jointAt Weld 4 5 (V3 (-0.56) 0 0) (V3 (-0.56) 0 0) ]
  in Scene flatKlein defaultParams bodies joints Nothing

-- | Two stacks of three boxes on a static floor on the plane (gravity along
-- −z), asleep within a second; a ball falls onto the left one and wakes it
-- (about step 120), and a weld from its top box to the world holds it.
planeSleepWake :: Scene
planeSleepWake =
  let h = 0.1
      z k = -3 + 3 / sqrt 2 + h / sqrt 2 + fromIntegral (k :: Int) * h * sqrt 2
      box x k = BodySpec SquareShape h 1 False (V3 x 0 (z k)) (V3 0 0 0) 0 0 Nothing [] Nothing 0 sceneMaterial
      bodies = BodySpec SquareShape 3 1 True (V3 0 0 (-3)) (V3 0 0 0) 0 0 Nothing [] Nothing 0 sceneMaterial
               : [box x k | x <- [-1, 1], k <- [0 .. 2]]
               ++ [BodySpec CircleShape 0.08 1 False (V3 (-1.02) 0 2.5) (V3 0 0 0) 0 0 Nothing [] Nothing 0 sceneMaterial]
      weld = (jointAt Weld 3 (-1) (V3 (-1) 0 (z 2)) (V3 (-1) 0 (z 2))) { jsHertz = 3, jsDampingRatio = 0.7 }
  in Scene plane defaultParams bodies [weld] Nothing

-- | Bodies of their own friction and restitution (and some of the
-- scene's, which are 0.3 and 0.2 here), thrown about the rectangle: they
-- bounce off its walls and each other, slide and roll.
rectangleMaterials :: Scene
rectangleMaterials =
  let body shape k material = BodySpec shape 0.08 1 False (V3 (-0.7 + 0.2 * fromIntegral k) 0 (0.5 - 0.1 * fromIntegral (k `mod` 3)))
                                (V3 (1.5 - 0.4 * fromIntegral k) 0 (-0.5)) 0 (fromIntegral k - 3) Nothing [] Nothing 0 material
      materials = [ Material (Just 0.9) Nothing, Material Nothing (Just 0.8), Material (Just 0) (Just 0.5), sceneMaterial
                  , Material (Just 0.05) (Just 0), Material (Just 1.5) (Just 1), Material Nothing Nothing, Material (Just 0.4) (Just 0.3) ]
      bodies = [ body (if even k then SquareShape else CircleShape) k m | (k, m) <- zip [0 :: Int ..] materials ]
  in Scene rectangle defaultParams { pFriction = 0.3, pRestitution = 0.2 } bodies [] Nothing

-- | A body of a shape at a point, at rest, of the scene's material.
placed :: ShapeKind -> Double -> Bool -> V3 Double -> Double -> BodySpec
placed k size static p angle =
  BodySpec k (fromMaybe size (shapeSize k)) 1 static p (V3 0 0 0) angle 0 Nothing [] Nothing 0 sceneMaterial

-- | Boxes, capsules and circles dropped onto a static box on the plane
-- (gravity along −z): a plank across two boxes, a tilted box onto a box,
-- a capsule, a card and circles.
planeShapes :: Scene
planeShapes =
  let bodies =
        [ placed (BoxShape 1 0.05) 0 True (V3 0 0 (-0.05)) 0
        , placed (BoxShape 0.05 0.05) 0 False (V3 (-0.2) 0 0.06) 0
        , placed (BoxShape 0.05 0.05) 0 False (V3 0.2 0 0.06) 0
        , placed (BoxShape 0.3 0.02) 0 False (V3 0.01 0 0.2) 0.05
        , placed (BoxShape 0.04 0.03) 0 False (V3 0.05 0 0.35) 0.4
        , placed (CapsuleShape 0.06 0.03) 0 False (V3 (-0.5) 0 0.15) 1
        , placed (BoxShape 0.1 0.0005) 0 False (V3 0.5 0 0.1) (-0.1)
        , placed CircleShape 0.04 False (V3 (-0.1) 0 0.5) 0
        , placed SquareShape 0.05 False (V3 0.6 0 0.3) 0.2 ]
  in Scene plane defaultParams bodies [] Nothing

-- | Boxes and capsules sliding down the sphere onto a static box at its
-- south pole, among circles: the corners walked along the sphere's
-- geodesics.
sphereShapes :: Scene
sphereShapes =
  let at a b = let r = sqrt (a * a + b * b) in if r == 0 then V3 0 (-1) 0 else V3 (sin r * a / r) (-(cos r)) (sin r * b / r)
      bodies =
        [ placed (BoxShape 0.25 0.08) 0 True (at 0 0) 0
        , placed (BoxShape 0.06 0.04) 0 False (at 0.3 0.05) 0.3
        , placed (BoxShape 0.05 0.05) 0 False (at (-0.3) 0.1) 0
        , placed (CapsuleShape 0.08 0.03) 0 False (at 0 0.35) 0.7
        , placed (CapsuleShape 0.05 0.04) 0 False (at 0.1 (-0.4)) 0
        , placed (BoxShape 0.12 0.02) 0 False (at (-0.2) (-0.3)) 1
        , placed CircleShape 0.05 False (at 0.45 (-0.1)) 0
        , placed CircleShape 0.04 False (at (-0.45) 0.3) 0 ]
  in Scene sphere defaultParams bodies [] Nothing

-- | Boxes and capsules on the projective plane, near the equator, where
-- they meet each other's images (mirrored: their corners in reverse
-- order), falling to the pole.
projectivePlaneShapes :: Scene
projectivePlaneShapes =
  let at a = V3 (cos a) 0.15 (sin a)
      bodies =
        [ placed (BoxShape 0.08 0.05) 0 False (at 0) 0
        , placed (BoxShape 0.06 0.06) 0 False (at (pi - 0.1)) 0.5
        , placed (CapsuleShape 0.07 0.04) 0 False (at 1.5) 0
        , placed (CapsuleShape 0.05 0.05) 0 False (at (1.5 + pi - 0.12)) 1
        , placed (BoxShape 0.1 0.03) 0 False (at 3.9) 0.2
        , placed CircleShape 0.06 False (at 0.7) 0 ]
  in Scene projectivePlane defaultParams bodies [] Nothing

-- | Convex polygons of their own corners on the sphere, sliding to a
-- static rounded hexagon at its south pole: a right triangle, a rounded
-- pentagon, a quadrilateral given clockwise, a thin plank of eight
-- corners, among a box and a circle.
spherePolygons :: Scene
spherePolygons =
  let at a b = let r = sqrt (a * a + b * b) in if r == 0 then V3 0 (-1) 0 else V3 (sin r * a / r) (-(cos r)) (sin r * b / r)
      regular n r0 = [ (r0 * cos t, r0 * sin t) | k <- [0 .. n - 1 :: Int], let t = 2 * pi * fromIntegral k / fromIntegral n ]
      bodies =
        [ placed (VerticesShape (regular 6 0.2) 0.02) 0 True (at 0 0) 0
        , placed (VerticesShape [(0, 0), (0.1, 0), (0, 0.07)] 0) 0 False (at 0.3 0.05) 0.3
        , placed (VerticesShape (regular 5 0.05) 0.01) 0 False (at (-0.3) 0.1) 0
        , placed (VerticesShape [(-0.04, 0.05), (0.06, 0.03), (0.05, -0.04), (-0.05, -0.03)] 0) 0 False (at 0 0.35) 0.7
        , placed (VerticesShape [(-0.12, -0.01), (-0.08, -0.015), (0.08, -0.015), (0.12, -0.01), (0.12, 0.01), (0.08, 0.015), (-0.08, 0.015), (-0.12, 0.01)] 0) 0 False (at 0.1 (-0.4)) 0
        , placed (BoxShape 0.05 0.04) 0 False (at (-0.2) (-0.3)) 1
        , placed CircleShape 0.05 False (at 0.45 (-0.1)) 0 ]
  in Scene sphere defaultParams bodies [] Nothing

-- | A space's default scene ('spaceScene') with the default parameters.
defaultScene :: Space -> Scene
defaultScene sp =
  Scene sp defaultParams
    [ BodySpec (placeShape pl) (placeSize pl) 1 (placeStatic pl) (placeAt pl) (V3 0 0 0) 0 0 Nothing [] Nothing 0 sceneMaterial
    | pl <- spaceScene sp ] [] Nothing

-- | The hash after @steps@ steps of the scene natively: by the generic step
-- when asked (else by the space's compiled one, where it has one).
runHash :: Bool -> Int -> Scene -> IO (Either String Word64)
runHash generic steps scene = do
  loaded <- loadScene 0 scene
  case loaded of
    Left e -> pure (Left e)
    Right w0 -> do
      let w = if generic then genericStep w0 else w0
      replicateM_ steps (stepNative w)
      Right <$> stateHash w

-- | A line of the golden file: the run's name, its steps and the hash.
goldenLine :: GoldenRun -> Word64 -> String
goldenLine run h = unwords [grName run, show (grSteps run), showHash h]
