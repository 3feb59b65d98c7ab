-- | The soft step's physical properties, each against what mechanics says
-- it should be: a pyramid and a tall stack of boxes stand, the circles of a
-- settled pile overlap by little, a ball dropped with restitution @e@
-- bounces back to @e²@ of its height, and a box on a slope holds below the
-- angle whose tangent is the friction coefficient and slides above it with
-- the acceleration @g (sin θ − μ cos θ)@; bodies of their own friction and
-- restitution do so with the pair's mixed values.
module SolverSpec (spec) where

import Control.Monad (forM, forM_)
import qualified Data.Aeson as A
import qualified Data.ByteString.Lazy.Char8 as BL
import Data.IORef
import Linear.Metric (distance)
import Linear.V3 (V3 (..))
import Test.Hspec

import Manifold
import Manifold.Bench (benchScene)
import Manifold.Engine
import Manifold.Scene (Scene (..), BodySpec (..), loadScene, parseScene, sceneJSON, sceneOfWorld)
import PhysicsUtil

-- | The rectangle's gravity (its magnitude, along −z).
gravity :: Double
gravity = 4

-- | A time step for boxes of half-side @h@ that makes @g·dt²/h@ what it is
-- for Box2D's 60 Hz pyramid of 1 m boxes (g = 10): the same fraction of a
-- box a body falls in one step.
pyramidDt :: Double -> Double
pyramidDt h = sqrt ((10 / 3600 / 0.5) * h / gravity)

-- | A square box of half-side @h@ centred at @(x, z)@ on the rectangle.
squareBox :: Double -> Double -> Double -> BodyInit
squareBox h x z = dyn square (h * sqrt 2) (V3 x 0 z) (V3 0 0 0) 0 0

-- | Run a stack-like scene of boxes of half-side @h@ for @seconds@ and
-- report the farthest any box moved sideways and how far the top box
-- (the last) moved up or down, both in half-sides.
standing :: Double -> [BodyInit] -> Double -> IO (Double, Double)
standing = standingWith id

-- | 'standing' with the parameters changed (stiffer contacts, more
-- sub-steps).
standingWith :: (Params -> Params) -> Double -> [BodyInit] -> Double -> IO (Double, Double)
standingWith change h bodies seconds = do
  let dt = pyramidDt h
  w <- mkWorld rectangle (change defaultParams { pDt = dt, pFriction = 0.6 }) bodies
  before <- bodyStates w
  worst <- newIORef 0
  forM_ [1 .. round (seconds / dt) :: Int] $ \k -> do
    stepNative w
    -- every tenth of a second: the farthest sideways move so far
    if k `mod` max 1 (round (0.1 / dt)) == 0
      then do
        now <- bodyStates w
        modifyIORef' worst (max (maximum (zipWith (\a b -> abs (xOf a - xOf b)) before now)))
      else pure ()
  after <- bodyStates w
  sideways <- max (maximum (zipWith (\a b -> abs (xOf a - xOf b)) before after)) <$> readIORef worst
  let top = zOf (last after) - zOf (last before)
  pure (sideways / h, top / h)

-- | A vertical stack of @n@ boxes of half-side @h@ on the rectangle's floor.
column :: Double -> Int -> [BodyInit]
column h n = [squareBox h 0 (-1 + h + fromIntegral k * 2 * h) | k <- [0 .. n - 1]]

xOf, zOf :: BodyState -> Double
xOf b = let V3 x _ _ = bsPos b in x
zOf b = let V3 _ _ z = bsPos b in z

-- | The solver's properties (the suite's "Solver" group).
spec :: Spec
spec = do
  describe "stacking" $ do
    it "a pyramid of 20 rows (210 boxes, friction 0.6) stands on the rectangle for 20 s: no box moves sideways by half its half-side, the top box neither rises nor falls by one" $ do
      let rows = 20 :: Int
          h = 0.9 / fromIntegral rows
          bodies = [ squareBox h ((fromIntegral k - fromIntegral (n - 1) / 2) * 2 * h) (-1 + h + fromIntegral r * 2 * h)
                   | r <- [0 .. rows - 1], let n = rows - r, k <- [0 .. n - 1] ]
      (sideways, top) <- standing h bodies 20
      labelled "pyramid of 20 rows after 20 s: max sideways / half-side, top box's height change / half-side" (fmt sideways ++ ", " ++ fmt top)
      sideways `shouldSatisfy` (< 0.5)
      abs top `shouldSatisfy` (< 1)

    -- (At the default 60 Hz, 15 boxes of this size fall: the column
    -- bends, each box tilting further than the one below, and topples
    -- within five seconds. Stiffer contacts hold taller stacks, below.)
    it "a stack of 10 boxes (friction 0.6) stands on the rectangle for 20 s" $ do
      let h = 0.03
      (sideways, top) <- standing h (column h 10) 20
      labelled "stack of 10 after 20 s: max sideways / half-side, top box's height change / half-side" (fmt sideways ++ ", " ++ fmt top)
      sideways `shouldSatisfy` (< 0.5)
      abs top `shouldSatisfy` (< 1)

    it "a stack of 20 boxes stands for 20 s with contacts at 150 Hz" $ do
      let h = 0.03
      (sideways, top) <- standingWith (\p -> p { pContactHertz = 150 }) h (column h 20) 20
      labelled "stack of 20 at 150 Hz after 20 s: max sideways / half-side, top box's height change / half-side" (fmt sideways ++ ", " ++ fmt top)
      sideways `shouldSatisfy` (< 0.5)
      abs top `shouldSatisfy` (< 1)

    it "a stack of 30 boxes stands for 20 s with 8 sub-steps and contacts at 250 Hz" $ do
      let h = 0.03
      (sideways, top) <- standingWith (\p -> p { pSubsteps = 8, pContactHertz = 250 }) h (column h 30) 20
      labelled "stack of 30 with 8 sub-steps at 250 Hz after 20 s: max sideways / half-side, top box's height change / half-side" (fmt sideways ++ ", " ++ fmt top)
      sideways `shouldSatisfy` (< 0.5)
      abs top `shouldSatisfy` (< 1)

  describe "piles" $
    it "settled piles of 300 bodies: touching circles overlap by at most 2 % of their radius on average and 5 % at most (rectangle, sphere, torus)" $
      forM_ [rectangle, sphere, torus] $ \sp -> do
        let scene = benchScene sp 300
        w <- loadScene 0 scene >>= either fail pure
        steps w 1000
        bs <- bodyStates w
        -- a bench scene's circles are its even-numbered bodies
        let circles = [ (b, bsSize spec') | (k, b, spec') <- zip3 [0 :: Int ..] bs (sceneBodies scene), even k ]
            overlaps = [ (ra + rb - distance (bsPos a) (bsPos b)) / min ra rb
                       | (i, (a, ra)) <- zip [0 :: Int ..] circles, (j, (b, rb)) <- zip [0 ..] circles, i < j
                       , distance (bsPos a) (bsPos b) < ra + rb ]
            mean = sum overlaps / fromIntegral (max 1 (length overlaps))
            worst = maximum (0 : overlaps)
        labelled ("pile of 300 on the " ++ spaceName sp ++ " after 1000 steps: touching circle pairs, mean / max overlap (of the radius)")
          (show (length overlaps) ++ ", " ++ fmt mean ++ " / " ++ fmt worst)
        (spaceName sp, length overlaps > 20) `shouldBe` (spaceName sp, True)
        -- (the circles' outlines are inscribed polygons: two touching
        -- ones' centres are up to 1 % of a radius closer than the circles')
        (spaceName sp, mean <= 0.02, worst <= 0.05) `shouldBe` (spaceName sp, True, True)

  describe "restitution" $
    it "a ball dropped from 0.5 with restitution e bounces back to e² of its height (within 15 %, e = 0.3, 0.6, 0.9)" $
      forM_ [0.3, 0.6, 0.9] $ \e -> do
        rebound <- bounce sceneMaterial sceneMaterial e
        labelled ("ball dropped with restitution " ++ show e ++ ": rebound height / drop height (e² = " ++ fmt (e * e) ++ ")") (fmt rebound)
        (e, abs (rebound / (e * e) - 1) < 0.15) `shouldBe` (e, True)

  describe "materials (a body's own friction and restitution, mixed as Box2D mixes them)" $ do
    it "a box of its own friction on a slope slides with g (sin θ − μ cos θ), μ = √(μ box · μ ground), the ground taking the scene's: holds, slides slowly, slides fast (within 10 %)" $ do
      -- the scene's friction 0.25 (the ground's): a box of 1.0 mixes to
      -- 0.5, one of 0.04 to 0.1, one of 0.36 (of 32.3°, past 0.5's hold)
      let sceneMu = 0.25
          critical = atan 0.5
          cases = [ (1.0, critical - 0.1, 0.5), (1.0, critical + 0.1, 0.5), (0.04, critical + 0.1, 0.1) ]
      forM_ cases $ \(own, theta, mixed) -> do
        (measured, moved) <- slide (Material (Just own) Nothing) sceneMu theta
        let expected = max 0 (gravity * (sin theta - mixed * cos theta))
        labelled ("box of friction " ++ fmt own ++ " on ground of the scene's " ++ fmt sceneMu ++ " at " ++ fmt (theta * 180 / pi) ++ "°: acceleration measured, expected (μ = " ++ fmt mixed ++ "); moved / half-side")
          (fmt measured ++ ", " ++ fmt expected ++ "; " ++ fmt moved)
        if expected == 0
          then (own, theta, abs moved < 0.5) `shouldBe` (own, theta, True)
          else (own, theta, abs (measured / expected - 1) < 0.1) `shouldBe` (own, theta, True)

    it "a ball of its own restitution bounces to e² of its drop, e the larger of the ball's and the ground's (the scene's unless the ground says): 0.6 on a scene of 0, 0.6 own on 0.3, none where both say 0 on a scene of 0.9" $
      forM_ [ (Material Nothing (Just 0.6), Nothing, 0, 0.6)
            , (Material Nothing (Just 0.6), Nothing, 0.3, 0.6)
            , (Material Nothing (Just 0), Just 0, 0.9, 0) ] $ \(ball, ground, sceneE, e) -> do
        rebound <- bounce ball (Material Nothing ground) sceneE
        labelled ("ball of restitution " ++ show (matRestitution ball) ++ " on ground of " ++ show ground ++ ", scene " ++ fmt sceneE ++ ": rebound / drop (e² = " ++ fmt (e * e) ++ ")") (fmt rebound)
        (ball, sceneE, if e == 0 then rebound < 0.01 else abs (rebound / (e * e) - 1) < 0.15) `shouldBe` (ball, sceneE, True)

    it "a saved scene keeps each body's own material, and a body without one keeps the scene's" $ do
      let text = "{\"space\": \"rectangle\", \"friction\": 0.3, \"bodies\": [{\"shape\": \"square\", \"size\": 0.1, \"p\": [0, 0, 0], \"friction\": 0.9}, "
                 ++ "{\"shape\": \"circle\", \"size\": 0.1, \"p\": [0.5, 0, 0], \"restitution\": 0.7}, {\"shape\": \"circle\", \"size\": 0.1, \"p\": [-0.5, 0, 0]}]}"
          materials = [Material (Just 0.9) Nothing, Material Nothing (Just 0.7), sceneMaterial]
      scene <- either fail pure (parseScene (BL.pack text))
      map bsMaterial (sceneBodies scene) `shouldBe` materials
      w <- loadScene 0 scene >>= either fail pure
      steps w 20
      mapM (fmap bsOwnMaterial . readBody w) [0 .. 2] `shouldReturn` materials
      saved <- sceneOfWorld scene w >>= either fail pure
      again <- either fail pure (parseScene (A.encode (sceneJSON saved)))
      map bsMaterial (sceneBodies again) `shouldBe` materials

  describe "friction" $
    it "a box on a slope (the plane's gravity turned by θ) holds at tan θ below μ = 0.5 and slides above it with acceleration g (sin θ − μ cos θ), within 10 %" $ do
      let mu = 0.5
          critical = atan mu
      results <- forM [critical - 0.1, critical + 0.1, critical + 0.3] $ \theta -> do
        (measured, moved) <- slide sceneMaterial mu theta
        let expected = max 0 (gravity * (sin theta - mu * cos theta))
        labelled ("box on a slope of " ++ fmt (theta * 180 / pi) ++ "° (μ = 0.5 holds to " ++ fmt (critical * 180 / pi) ++ "°): acceleration measured, expected; moved in the second / half-side")
          (fmt measured ++ ", " ++ fmt expected ++ "; " ++ fmt moved)
        pure (theta, measured, expected, moved)
      forM_ results $ \(theta, measured, expected, moved) ->
        if expected == 0
          -- (it creeps: a fifth of a half-side a second at 20.8°, against
          -- nine and a half sliding at 32.3°)
          then (theta, abs moved < 0.5) `shouldBe` (theta, True)
          else (theta, abs (measured / expected - 1) < 0.1) `shouldBe` (theta, True)

-- | A box of half-side 0.05 and this material on a static ground, the
-- plane's gravity turned by @θ@, the scene's friction @mu@: after half a
-- second to settle, its acceleration down the slope over the next second
-- and how far it moved in it (in half-sides).
slide :: Material -> Double -> Double -> IO (Double, Double)
slide material mu theta = do
  let slope = plane { spaceName = "slope", spaceGravity = uniformGravity (V3 (gravity * sin theta) 0 (negate gravity * cos theta)) }
      groundSize = 2
      top = -0.5 + groundSize * cos (pi / 4)
      h = 0.05
      dt = 0.005
  w <- mkWorld slope defaultParams { pFriction = mu, pDt = dt }
         [ still square groundSize (V3 0 0 (-0.5)) 0, (squareBox h 0 (top + h)) { biMaterial = material } ]
  let state = do
        b <- readBody w 1
        let V3 vx _ _ = bsVel b
        pure (xOf b, vx)
  steps w (round (0.5 / dt))
  (x0, v0) <- state
  steps w (round (1 / dt))
  (x1, v1) <- state
  pure (v1 - v0, (x1 - x0) / h)

-- | A ball of radius 0.05 and material @ball@ dropped from 0.5 onto a
-- static ground of material @ground@, the scene's restitution @e@: the top
-- of its flight after the bounce, over the drop.
bounce :: Material -> Material -> Double -> IO Double
bounce ball ground e = do
  let r = 0.05
      drop' = 0.5
      groundSize = 0.5
      top = -0.5 + groundSize * cos (pi / 4)
      start = top + r + drop'
  w <- mkWorld plane defaultParams { pRestitution = e, pDt = 0.002 }
         [ (still square groundSize (V3 0 0 (-0.5)) 0) { biMaterial = ground }, (dyn circle r (V3 0 0 start) (V3 0 0 0) 0 0) { biMaterial = ball } ]
  -- down, the bounce, and the top of the flight after it (or where it
  -- comes to rest, a second after the drop would have reached the ground)
  let fly :: Int -> Int -> Double -> IO Double
      fly k phase apex = do
        stepNative w
        b <- readBody w 1
        let vz = let V3 _ _ z = bsVel b in z
        case phase of
          _ | k > 1000 -> pure (max apex (zOf b))
          0 | vz > 0 -> fly (k + 1) 1 (zOf b)
            | otherwise -> fly (k + 1) 0 apex
          _ | vz > 0 -> fly (k + 1) 1 (max apex (zOf b))
            | otherwise -> pure (max apex (zOf b))
  apex <- fly 0 0 (-1)
  pure ((apex - (top + r)) / drop')
