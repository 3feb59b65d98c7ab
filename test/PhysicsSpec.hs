-- | Physics scenarios (the paper's behaviours, with oracles that can fail):
-- resting contact, stacking, gathering under gravity on a sphere,
-- conservation of momentum, jamming in the trumpet, a boundary, collisions
-- through the antipodal image on the projective plane, the mouse joint, the
-- native engine against the emitted JavaScript on every scenario, and random
-- scenes on every space.
--
-- Every scenario is deterministic (fixed placements, fixed seeds).
module PhysicsSpec (spec) where

import Control.Concurrent (forkIO, getNumCapabilities)
import Control.Concurrent.MVar
import Control.Exception (SomeException, throwIO, try)
import Control.Monad (forM, forM_, replicateM, unless, when, zipWithM_)
import Data.Maybe (fromMaybe)
import Data.List (sortOn)
import Data.Foldable (toList)
import Data.IORef
import qualified Data.Map.Strict as M
import qualified Data.Vector.Unboxed.Mutable as MV
import Linear.Metric (dot, norm, normalize, quadrance)
import Linear.V3 (V3 (..), cross)
import GHC.Clock (getMonotonicTime)
import System.Environment (lookupEnv)
import Test.Hspec
import Test.QuickCheck (Gen, choose, elements, vectorOf)
import Test.QuickCheck.Gen (unGen)
import Test.QuickCheck.Random (mkQCGen)
import Text.Printf (printf)

import Manifold
import Manifold.Bench (benchScene)
import Manifold.Engine
import Manifold.Scene (loadScene)
import Manifold.World
import PhysicsUtil

-- Scenarios -----------------------------------------------------------------

-- | A scene, how far to run it natively before the differential window, and
-- what the window does (200 steps, possibly with mouse actions).
data Scenario = Scenario
  { scName :: String
  , scSpace :: Space
  , scParams :: Params
  , scBodies :: [BodyInit]
  , scWarmup :: Int
  , scWindow :: [Action]
  }

-- | The scenario with sleeping off.
awake :: Scenario -> Scenario
awake s = s { scParams = (scParams s) { pSleep = False } }

build :: Scenario -> IO NativeWorld
build s = mkWorld (scSpace s) (scParams s) (scBodies s)

window200 :: [Action]
window200 = [Steps 200]

-- | The window of a pile that keeps moving (bodies gathering, a bowl of
-- fast ones): its contacts amplify the last-bit differences of the
-- platforms' own sine and cosine (V8's against the C library's) about
-- tenfold every 10 to 20 steps: the gathering pile's native and emitted
-- steps are 8e-13 apart at step 60, 6e-8 at 100 and 1.4e-6 at 200.
windowPile :: [Action]
windowPile = [Steps 60]

-- | The plane's ground: a static square of size 0.5 whose top face is at
-- z = −0.5 + 0.5·cos 45°.
groundSize, groundZ, groundTop :: Double
groundSize = 0.5
groundZ = -0.5
groundTop = groundZ + apothem groundSize

-- | A square's apothem (its centre's distance to a side).
apothem :: Double -> Double
apothem s = s * cos (pi / 4)

ground :: BodyInit
ground = still square groundSize (V3 0 0 groundZ) 0

boxSize :: Double
boxSize = 0.2

-- | One box on the ground, 5 mm above its resting height (it falls first).
restingScenario :: Scenario
restingScenario = Scenario "resting box (plane)" plane defaultParams
  [ground, dyn square boxSize (V3 0 0 0) 0 0 0] 0 window200

-- | Five boxes on the ground, each 1 mm above the one below.
stackScenario :: Params -> Scenario
stackScenario ps = Scenario "stack of five (plane)" plane ps
  (ground : [ dyn square boxSize (V3 0 0 (stackZ k)) 0 0 0 | k <- [0 .. 4] ]) 0 window200

stackZ :: Int -> Double
stackZ k = groundTop + apothem boxSize * fromIntegral (2 * k + 1) + 0.001 * fromIntegral (k + 1)

-- | Twelve bodies on the northern half of the sphere, at rest.
gatherScenario :: Scenario
gatherScenario = Scenario "gathering (sphere)" sphere defaultParams { pSleep = False } bodies 150 windowPile
  where
    bodies =
      [ dyn (if even k then square else circle) 0.2 (V3 (0.6 * cos t) 0.8 (0.6 * sin t)) 0 0.3 0
      | k <- [0 .. 5 :: Int], let t = 2 * pi * fromIntegral k / 6 ] ++
      [ dyn (if even k then circle else square) 0.2 (V3 (cos t) 0 (sin t)) 0 (-0.4) 0
      | k <- [0 .. 5 :: Int], let t = 2 * pi * (fromIntegral k + 0.5) / 6 ]

-- | Three bodies colliding on the plane without gravity or friction, off
-- centre and spinning.
momentumScenario :: Scenario
momentumScenario = Scenario "momentum (plane, no gravity, no friction)" plane
  defaultParams { pGravity = False, pFriction = 0, pRestitution = 0.5 }
  [ dyn square 0.2 (V3 (-0.8) 0 0.05) (V3 2 0 0) 0.3 1.0
  , dyn circle 0.15 (V3 0 0 0) 0 0 0
  , dyn (regularPolygon 5) 0.18 (V3 0.1 0 0.7) (V3 0 0 (-1.5)) 0.2 (-0.5) ]
  0 window200

-- | A body thrown down the trumpet (the window covers the jam).
trumpetScenario :: String -> Shape -> Double -> Scenario
trumpetScenario name sh size = Scenario name trumpet defaultParams
  [dyn sh size (V3 1.6 0.5 0) (V3 0 (-1) 0) 0 0] 200 window200

jamScenario, jamControlScenario, jamSquareScenario :: Scenario
jamScenario = trumpetScenario "jam: circle 0.5 (trumpet)" circle 0.5
jamControlScenario = trumpetScenario "jam control: circle 0.05 (trumpet)" circle 0.05
-- The square's self-contact is violent (see the energy test) and amplifies
-- rounding differences about tenfold every few steps once it starts (1e-16
-- at 90 steps into the window, 3e-9 at 120, 4e-2 at 200), so its window is
-- the first 100 steps, which cover the first 30 steps of self-contact.
jamSquareScenario = (trumpetScenario "square 0.5 (trumpet), 100 steps" square 0.5) { scWindow = [Steps 100] }

-- | Twenty-four bodies thrown about the bowl towards the rim, with speeds
-- from 0.4 to 1 times the given largest one. At 1.9 the fastest just reach
-- the rim (they arrive slowly); at 2.5 they hit it.
hemisphereScenario :: Double -> Scenario
hemisphereScenario vmax = Scenario ("bowl, speeds up to " ++ show vmax ++ " (hemisphere)") hemisphere defaultParams bodies 0 windowPile
  where
    bodies =
      [ dyn sh sz p v (fromIntegral k) 0
      | k <- [0 .. 23 :: Int]
      , let ring = k `mod` 3
            t = 2 * pi * fromIntegral k / 24 + 0.3 * fromIntegral ring
            y = [-0.45, -0.7, -0.9] !! ring
            r = sqrt (1 - y * y)
            p = V3 (r * cos t) y (r * sin t)
            up = V3 0 1 0 - fmap (* y) p -- towards the rim along the surface
            side = V3 (negate (sin t)) 0 (cos t)
            speed0 = vmax * (0.4 + 0.6 * fromIntegral ((k * 7) `mod` 5) / 4)
            v = fmap (* speed0) (normalize (up + fmap (* (0.5 * fromIntegral (ring - 1))) side))
            sh = [square, circle, regularPolygon 3, regularPolygon 5] !! (k `mod` 4)
            sz = 0.1 + 0.02 * fromIntegral (k `mod` 4) ]

-- | Body A at p, body B at −q with q near p: A overlaps B's antipodal image.
-- No gravity, so nothing but the images' contact moves them.
imageSeparation :: Double
imageSeparation = 0.36

imageScenario :: Space -> Scenario
imageScenario sp = Scenario ("antipodal image (" ++ spaceName sp ++ ")") sp defaultParams { pGravity = False }
  [ dyn circle 0.2 (V3 0 0 1) 0 0 0
  , dyn circle 0.2 (negate (V3 (sin imageSeparation) 0 (cos imageSeparation))) 0 0 0 ]
  0 window200

-- | The mouse: a square on the sphere's equator, grabbed 0.1 off its centre
-- and dragged 0.5 along the surface.
mouseScenario :: Scenario
mouseScenario = Scenario "mouse (sphere)" sphere defaultParams
  [dyn square 0.2 (V3 0 0 1) 0 0.4 0] 0
  [Grab 0 1 mouseGrabPoint 5 0.7 mouseMaxForce, Drag mouseTarget, Steps 150, Release, Steps 50]

mouseGrabPoint, mouseTarget :: V3 Double
mouseGrabPoint = fst (expMap Euclidean (spaceField sphere) 8 (V3 0 0 1) (V3 1 1 0) 0.1)
mouseTarget = fst (expMap Euclidean (spaceField sphere) 16 mouseGrabPoint (V3 1 0.5 0) mouseDistance)

mouseDistance :: Double
mouseDistance = 0.5

-- | The page's choice: 1000 times the body's mass (see web/js/world.js).
mouseMaxForce :: Double
mouseMaxForce = 1000 * mass (massProperties square 0.2 1)

allScenarios :: [Scenario]
allScenarios =
  [ restingScenario, stackScenario defaultParams, gatherScenario, momentumScenario
  , jamScenario, jamControlScenario, jamSquareScenario, hemisphereScenario 1.9, hemisphereScenario 2.5
  , imageScenario projectivePlane, imageScenario sphere, mouseScenario ]

-- Helpers -------------------------------------------------------------------

zOf, yOf, xOf :: BodyState -> Double
zOf b = let V3 _ _ z = bsPos b in z
yOf b = let V3 _ y _ = bsPos b in y
xOf b = let V3 x _ _ = bsPos b in x

-- | The largest depth of body @i@'s contacts (as either side).
depthOfBody :: [Contact] -> Int -> Double
depthOfBody cs i = maxDepthOf [c | c <- cs, cA c == i || cB c == i]

-- | ½ m v² + ½ I ω² + potential, for one body under uniform gravity @g@.
bodyEnergy :: NativeWorld -> V3 Double -> Int -> IO Double
bodyEnergy w g i = do
  m <- bodyMass w i
  inertia' <- bodyInertia w i
  b <- readBody w i
  pure (0.5 * m * quadrance (bsVel b) + 0.5 * inertia' * bsOmega b ^ (2 :: Int) - m * (g `dot` bsPos b))

-- | Whether the stack stands: each box within 10 % of its size of x = 0 and
-- of its starting height, and the boxes in their order.
data StackState = StackState { ssDrift :: Double, ssSink :: Double, ssOrdered :: Bool }

stackState :: NativeWorld -> IO StackState
stackState w = do
  bs <- tail <$> bodyStates w
  let zs = map zOf bs
  pure StackState
    { ssDrift = maximum (map (abs . xOf) bs)
    , ssSink = maximum [abs (z - stackZ k) | (k, z) <- zip [0 ..] zs]
    , ssOrdered = and (zipWith (<) zs (tail zs))
    }

stands :: StackState -> Bool
stands s = ssDrift s < 0.1 * boxSize && ssSink s < 0.1 * boxSize && ssOrdered s

-- | Run a stack for 1000 steps, stopping as soon as it fails; whether it
-- stood, and the worst drift and sinking seen.
runStack :: Params -> IO (Bool, Double, Double)
runStack ps = do
  w <- build (stackScenario ps)
  worst <- newIORef (0, 0)
  let check = do
        s <- stackState w
        modifyIORef' worst (\(d, k) -> (max d (ssDrift s), max k (ssSink s)))
        pure (stands s)
  _ <- stepsWhile w 1000 check
  ok <- stands <$> stackState w
  (d, k) <- readIORef worst
  pure (ok, d, k)

-- | A bowl run: the worst violation of @b >= 0@ by an outline vertex, over
-- the body's size (and when); the worst beyond 2 % of the size plus the
-- farthest the body stepped in the last ten steps (|v| dt + |ω| size dt: a
-- vertex can go out that far in the step before its contact is found, and
-- Baumgarte takes a few steps to bring it back); the worst in the second
-- half; the steps with boundary contacts.
data Bowl = Bowl { bowlWorst :: Double, bowlWorstStep :: Int, bowlBeyond :: Double, bowlLate :: Double, bowlRimSteps :: Int }

runBowl :: Scenario -> IO Bowl
runBowl sc = do
  let n = length (scBodies sc)
      dt = pDt (scParams sc)
      sp = scSpace sc
  w <- build sc
  sizes <- mapM (bodySize w) [0 .. n - 1]
  history <- newIORef (replicate n [])
  worst <- newIORef (0, 0)
  beyond <- newIORef (-1)
  late <- newIORef 0
  rims <- newIORef (0 :: Int)
  forM_ [1 .. 2000 :: Int] $ \s -> do
    stepNative w
    cs <- contacts w
    when (any ((< 0) . cB) cs) $ modifyIORef' rims (+ 1)
    ts <- forM (zip [0 ..] sizes) $ \(i, sz) -> do
      b <- readBody w i
      pure ((speed b + abs (bsOmega b) * sz) * dt)
    modifyIORef' history (zipWith (\t h -> take 10 (t : h)) ts)
    recent <- readIORef history
    forM_ (zip3 [0 ..] sizes recent) $ \(i, sz, h) -> do
      o <- outline w i
      let out = maximum [negate (evalBoundary sp q) | q <- o] / sz -- > 0 outside
      modifyIORef' worst (\(a, st) -> if out > a then (out, s) else (a, st))
      modifyIORef' beyond (max (out - 0.02 - maximum h / sz))
      when (s > 1000) $ modifyIORef' late (max out)
  (wv, ws) <- readIORef worst
  Bowl wv ws <$> readIORef beyond <*> readIORef late <*> readIORef rims

-- | Copy every array of one world into another of the same layout.
copyWorld :: NativeWorld -> NativeWorld -> IO ()
copyWorld from to = zipWithM_ MV.copy (toList (nwArrays to)) (toList (nwArrays from))

-- | The point of a grabbed body the mouse joint holds: the engine keeps the
-- grab point's polar coordinates in the body's frame (the projected offset's
-- length and angle from the body's axis and angle) and walks a geodesic that
-- long from the centre.
data Held = Held Double Double

heldAt :: NativeWorld -> Int -> V3 Double -> IO Held
heldAt w i q = do
  b <- readBody w i
  let c = bsPos b
      n = unitNormal Euclidean (spaceField (nwSpace w)) c
      u = bsAxis b
      v = n `cross` u
      d = q - c
      x = d `dot` u
      y = d `dot` v
  pure (Held (sqrt (x * x + y * y)) (atan2 y x - bsAngle b))

heldPoint :: NativeWorld -> Int -> Held -> IO (V3 Double)
heldPoint w i (Held r theta) = do
  b <- readBody w i
  let f = spaceField (nwSpace w)
      c = bsPos b
      n = unitNormal Euclidean f c
      u = bsAxis b
      v = n `cross` u
      phi = bsAngle b + theta
  pure (fst (expMap Euclidean f 4 c (fmap (* cos phi) u + fmap (* sin phi) v) r))

-- Random scenes ---------------------------------------------------------------

genBody :: Space -> Gen BodyInit
genBody sp = do
  pl <- elements (spaceScene sp)
  off <- V3 <$> choose (-0.15, 0.15) <*> choose (-0.15, 0.15) <*> choose (-0.15, 0.15)
  sh <- elements [circle, square, regularPolygon 3, regularPolygon 5, regularPolygon 6]
  sz <- choose (0.05, 0.3)
  dir <- V3 <$> choose (-1, 1) <*> choose (-1, 1) <*> choose (-1, 1)
  sp' <- choose (0, 2)
  ang <- choose (-pi, pi)
  om <- choose (-5, 5)
  pure (dyn sh sz (placeAt pl + off) (fmap (* sp') (normalize dir)) ang om)

genScene :: Space -> Gen [BodyInit]
genScene sp = do
  n <- choose (2, 6)
  vectorOf n (genBody sp)

-- | A random joint of a scene of @n@ bodies: its kind, bodies (b −1: the
-- world), where its anchors sit between the two bodies' centres (0: at
-- a's, 1: at b's), and settings: a limit, a motor, a spring, a rope.
data RandomJoint = RandomJoint JointKind Int Int Double Double [(JointField, Double)]

genJoints :: Int -> Gen [RandomJoint]
genJoints n = do
  k <- choose (0, 3)
  vectorOf k $ do
    kind <- elements [Revolute, Distance, Weld]
    a <- choose (0, n - 1)
    b <- elements (-1 : [j | j <- [0 .. n - 1], j /= a])
    ta <- choose (0, 0.5)
    tb <- choose (0.5, 1)
    settings <- case kind of
      Revolute -> do
        lim <- choose (0, 1.5)
        speed <- choose (-5, 5)
        torque <- choose (0, 0.05)
        elements [[], [(JLimitOn, 1), (JLower, negate lim), (JUpper, lim)], [(JMotorOn, 1), (JMotorSpeed, speed), (JMaxTorque, torque)]]
      Distance -> do
        hz <- choose (0.5, 10)
        elements [[], [(JHertz, hz), (JDamping, 0.2)], [(JMinLength, 0)]]
      Weld -> do
        hz <- choose (0.5, 10)
        elements [[], [(JHertz, hz), (JDamping, 1)]]
    pure (RandomJoint kind a b ta tb settings)

-- | Add the random joints that the world takes, between bodies within
-- twice their sizes' sum (an anchor that does not project is refused, and
-- left out); how many it took.
addRandomJoints :: NativeWorld -> [RandomJoint] -> IO Int
addRandomJoints w js = do
  added <- forM js $ \(RandomJoint kind a b ta tb settings) -> do
    pa <- bsPos <$> readBody w a
    pb <- if b < 0 then pure (pa + V3 0.05 0.05 0.05) else bsPos <$> readBody w b
    reach <- (\sa sb -> 2 * (sa + sb)) <$> bodySize w a <*> (if b < 0 then pure 0.05 else bodySize w b)
    let between t = pa + fmap (* t) (pb - pa)
        (qa, qb) = if kind == Distance then (between ta, between tb) else (between 0.5, between 0.5)
    -- joints between bodies near each other, as one makes them (a pin
    -- midway between bodies far apart on the trumpet makes a long rigid
    -- lever: see docs/engine.md#joints)
    if norm (pb - pa) > reach then pure 0 else do
      r <- addJointAt w kind a b qa qb
      case r of
        Left _ -> pure 0
        Right j -> do
          mapM_ (uncurry (setJointField w j)) settings
          pure (1 :: Int)
  pure (sum added)

-- | Scenes per space and steps per scene: MANIFOLD_ROBUSTNESS="NxK", or 50
-- scenes of 1000 steps (a quarter of the long run, 100x2000, which took
-- 45 s of the suite's time on two cores).
robustnessCounts :: IO (Int, Int)
robustnessCounts = do
  e <- lookupEnv "MANIFOLD_ROBUSTNESS"
  pure $ case fmap (break (== 'x')) e of
    Just (a, 'x' : b) | [(n, "")] <- reads a, [(k, "")] <- reads b, n > 0, k > 0 -> (n, k)
    _ -> (50, 1000)

-- | Run the actions on as many threads as there are capabilities (the test
-- suite runs with +RTS -N), each taking the next action when it is done;
-- the results in the actions' order. An exception in one is rethrown here.
inParallel :: [IO a] -> IO [a]
inParallel actions = do
  caps <- getNumCapabilities
  let indexed = zip [0 :: Int ..] actions
  queue <- newMVar indexed
  results <- newMVar []
  done <- replicateM (max 1 caps) $ do
    finished <- newEmptyMVar
    let worker = do
          next <- modifyMVar queue (\q -> pure (drop 1 q, take 1 q))
          case next of
            [(k, act)] -> act >>= \r -> modifyMVar_ results (pure . ((k, r) :)) >> worker
            _ -> pure ()
    _ <- forkIO (try worker >>= putMVar finished)
    pure finished
  outcomes <- mapM takeMVar done
  case [e | Left e <- outcomes] of
    (e : _) -> throwIO (e :: SomeException)
    [] -> map snd . sortOn fst <$> readMVar results

-- Spec -----------------------------------------------------------------------

spec :: Spec
spec = do
  describe "resting contact" $
    it "keeps a box on a static box within 1 % of its size of penetration, at the analytic height, at rest after 300 steps" $ do
      -- (awake: a sleeping box has no contact rows to measure)
      w <- build (awake restingScenario)
      steps w 300
      b <- readBody w 1
      cs <- contacts w
      let depth = depthOfBody cs 1
          analytic = groundTop + apothem boxSize
          offset = analytic - zOf b
      labelled "resting box: max contact depth / size" (fmt (depth / boxSize))
      labelled "resting box: (analytic height - height) / size" (fmt (offset / boxSize) ++ "  (analytic z " ++ fmt analytic ++ ", z " ++ fmt (zOf b) ++ ")")
      labelled "resting box: speed, |omega|" (fmt (speed b) ++ ", " ++ fmt (abs (bsOmega b)))
      length cs `shouldSatisfy` (> 0)
      depth `shouldSatisfy` (< 0.01 * boxSize)
      abs offset `shouldSatisfy` (< 0.01 * boxSize)
      abs (xOf b) `shouldSatisfy` (< 0.01 * boxSize)
      speed b `shouldSatisfy` (< 1e-6)
      abs (bsOmega b) `shouldSatisfy` (< 1e-5)

  describe "stacking" $ do
    it "a stack of five boxes on a static box stands for 1000 steps (drift < 10 % of a box, order kept, none falls)" $ do
      w <- build (stackScenario defaultParams)
      worst <- newIORef (0, 0, True)
      forM_ [1 .. 1000 :: Int] $ \_ -> do
        stepNative w
        s <- stackState w
        modifyIORef' worst (\(d, k, o) -> (max d (ssDrift s), max k (ssSink s), o && ssOrdered s))
      (d, k, o) <- readIORef worst
      labelled "stack (defaults): max drift / size, max height change / size" (fmt (d / boxSize) ++ ", " ++ fmt (k / boxSize))
      o `shouldBe` True
      d `shouldSatisfy` (< 0.1 * boxSize)
      k `shouldSatisfy` (< 0.1 * boxSize)

    it "measures what warm starting, friction and restitution do to the stack (minimum sub-steps that stand)" $ do
      let counts = [1, 2, 3, 4, 6, 8, 12, 16, 24, 32]
          minIterations ps = go counts
            where
              go [] = pure Nothing
              go (n : ns) = do
                (ok, _, _) <- runStack ps { pSubsteps = n }
                if ok then pure (Just n) else go ns
          shown = maybe ("none up to " ++ show (last counts)) show
      warmOn <- minIterations defaultParams
      warmOff <- minIterations defaultParams { pWarmStart = False }
      frictionless <- minIterations defaultParams { pFriction = 0 }
      frictionlessCold <- minIterations defaultParams { pFriction = 0, pWarmStart = False }
      labelled "stack: warm start on (friction 0.4) -> min sub-steps" (shown warmOn)
      labelled "stack: warm start off (friction 0.4) -> min sub-steps" (shown warmOff)
      labelled "stack: friction 0.4 (warm start on) -> min sub-steps" (shown warmOn)
      labelled "stack: friction 0 (warm start on) -> min sub-steps" (shown frictionless)
      labelled "stack: friction 0, warm start off -> min sub-steps" (shown frictionlessCold)
      forM_ [0.5, 1] $ \e -> do
        (ok, d, k) <- runStack defaultParams { pRestitution = e }
        labelled ("stack: restitution " ++ show e ++ " (4 sub-steps, warm start) ->")
          ((if ok then "stands" else "falls") ++ ", max drift / size " ++ fmt (d / boxSize) ++ ", max height change / size " ++ fmt (k / boxSize))
        -- a bouncing stack may lean, but it stays a stack: no box moves by its size
        (e, d < boxSize, k < boxSize) `shouldBe` (e, True, True)
      -- warm starting is what lets few sub-steps hold a stack (it stands
      -- with the default 4), with friction or without: an aligned stack on
      -- level ground has no sideways force for friction to hold (friction's
      -- own measures are the slope tests)
      let rank = fromMaybe (maxBound :: Int)
      rank warmOn `shouldSatisfy` (<= 4)
      rank warmOn `shouldSatisfy` (< rank warmOff)
      rank frictionless `shouldSatisfy` (<= 4)
      rank frictionless `shouldSatisfy` (< rank frictionlessCold)

  describe "gathering" $
    it "gathers bodies at the sphere's south pole under its gravity, packed, at rest, without overlapping > 2 %" $ do
      let sc = gatherScenario
          n = length (scBodies sc)
          south = V3 0 (-1) 0
          -- the cap holding the bodies' total area at a packing density of 1/2
          area = sum [mass (massProperties (biShape b) (biSize b) 1) | b <- scBodies sc]
          capAngle = 180 / pi * acos (1 - 2 * area / (2 * pi))
      w <- build sc
      before <- bodyStates w
      steps w 1500
      after <- bodyStates w
      ke <- kineticEnergy w
      cs <- contacts w
      let angles bs = [angleBetween (bsPos b) south | b <- bs]
          overlap = maximum (0 : [cDepth c / 0.2 | c <- cs])
      labelled "gather: initial angles from the south pole (min..max, degrees)" (fmt (minimum (angles before)) ++ ".." ++ fmt (maximum (angles before)))
      labelled "gather: after 1500 steps, max / mean angle (degrees)" (fmt (maximum (angles after)) ++ " / " ++ fmt (sum (angles after) / fromIntegral n) ++ "  (bound: cap of twice the bodies' area, " ++ fmt capAngle ++ ")")
      labelled "gather: mean kinetic energy, max depth / size, contacts" (fmt (ke / fromIntegral n) ++ ", " ++ fmt overlap ++ ", " ++ show (length cs))
      maximum (angles after) `shouldSatisfy` (< capAngle)
      overlap `shouldSatisfy` (< 0.02)
      length cs `shouldSatisfy` (>= n - 1) -- they touch: a packing, not a scattering
      -- nothing feeds the pile more than a swirl (measured 4e-5)
      ke / fromIntegral n `shouldSatisfy` (< 1e-4)
      unless (ke / fromIntegral n < 1e-6) $
        pendingWith ("ENGINE DEFECT: the gathered pile does not come to rest (mean kinetic energy " ++ fmt (ke / fromIntegral n)
          ++ " a body after 1500 steps; the solver before the soft step reached 1e-6): it swirls about the pole, gaining angular "
          ++ "momentum about the axis, because a body on the surface spins only about its normal and the part of a contact's "
          ++ "torque about its tangent plane is lost")

  describe "conservation" $
    it "conserves momentum in R³ (1e-9), and angular momentum about the plane's normal to first order in dt (contacts found anew every step), in frictionless, gravity-free collisions" $ do
      -- A step's contact anchors stay where the step found them while the
      -- bodies move over its sub-steps (as in Box2D v3), so an impulse's
      -- lever arms are off by the bodies' motion within the step: angular
      -- momentum changes by O(dt), linear momentum not at all. (Kept over
      -- steps, the anchors are off by the pair's drift since they were
      -- found, which the kept drift bounds, not dt: below.)
      let run = runKept False
          runKept keep halvings = do
            let sc0 = momentumScenario
                scale = 2 ^ (halvings :: Int)
                sc = sc0 { scParams = (scParams sc0) { pDt = pDt (scParams sc0) / fromIntegral scale, pKeepContacts = keep } }
            w <- build sc
            let k = length (scBodies sc)
                state = do
                  bs <- bodyStates w
                  ms <- mapM (bodyMass w) [0 .. k - 1]
                  is <- mapM (bodyInertia w) [0 .. k - 1]
                  pure (bs, ms, is)
            (b0, ms, is) <- state
            contactSteps <- forM [1 .. 300 * scale :: Int] $ \_ -> stepNative w >> contactCount w
            (b1, _, _) <- state
            let p0 = momentum (zip ms b0)
                p1 = momentum (zip ms b1)
                l s bs = angularMomentumY s (zip3 ms is bs)
                relP = norm (p1 - p0) / norm p0
                rel s = abs (l s b1 - l s b0) / abs (l s b0)
                massErr = maximum [ abs (m - mass (massProperties (biShape b) (biSize b) 1)) / m | (m, b) <- zip ms (scBodies sc) ]
            pure (relP, rel, massErr, contactSteps, b0, b1)
      let sc0 = momentumScenario
      (relP, rel, massErr, contactSteps, b0, b1) <- run 0
      (relPHalf, relHalf, _, _, _, _) <- run 1
      (_, relEighth, _, _, _, _) <- run 3
      labelled "momentum: |P1 - P0| / |P0| (dt, dt/2)" (fmt relP ++ ", " ++ fmt relPHalf)
      labelled "momentum: angular momentum about y, spin sign +1 (omega about the normal +y): relative change (dt, dt/2, dt/8)" (fmt (rel 1) ++ ", " ++ fmt (relHalf 1) ++ ", " ++ fmt (relEighth 1))
      labelled "momentum: steps with contacts" (show (length (filter (> 0) contactSteps)))
      labelled "momentum: engine mass vs massProperties, max relative difference" (fmt massErr)
      -- every body took part, and the hits turned the square and the
      -- pentagon; the circle, pushed without friction along normals
      -- through its centre, does not turn
      forM_ (zip3 (map biShape (scBodies sc0)) b0 b1) $ \(sh, x, y) -> do
        norm (bsVel y - bsVel x) `shouldSatisfy` (> 0.1)
        if shapeKind sh == Just CircleShape
          then abs (bsOmega y - bsOmega x) `shouldSatisfy` (< 1e-12)
          else abs (bsOmega y - bsOmega x) `shouldSatisfy` (> 0.1)
      relP `shouldSatisfy` (< 1e-9)
      relPHalf `shouldSatisfy` (< 1e-9)
      rel 1 `shouldSatisfy` (< 0.05)
      relHalf 1 `shouldSatisfy` (< 0.05)
      -- it shrinks with the step, though not step by step (the hits fall
      -- on other steps: 1.8e-2, 1.4e-2, 1.5e-2 and 8.0e-3 at dt, dt/2, dt/4
      -- and dt/8 when squares met by their hulls): an eighth of the step,
      -- under 0.6 of the change
      relEighth 1 `shouldSatisfy` (< 0.6 * rel 1)
      -- kept contacts (the default): bounded by the kept drift at every dt
      kept <- forM [0, 1, 3] (fmap (\(p, r, _, _, _, _) -> (p, r 1)) . runKept True)
      labelled "momentum, contacts kept: |P1 - P0| / |P0|, angular momentum's relative change (dt, dt/2, dt/8)"
        (unwords [fmt p ++ " " ++ fmt r | (p, r) <- kept])
      forM_ kept $ \(p, r) -> (p < 1e-9, r < 0.05) `shouldBe` (True, True)
      -- one integral ('massIntegrals'), native and in the engine
      massErr `shouldSatisfy` (< 1e-15) -- (the engine keeps 1/m)

  describe "jamming" $ do
    it "jams a circle of size 0.5 thrown into the trumpet's neck at a finite height, while a small one goes much further" $ do
      -- (awake: a sleeping circle has no self-contact rows to count)
      big <- build (awake jamScenario)
      small <- build (awake jamControlScenario)
      steps big 1500
      steps small 1500
      b <- readBody big 0
      s <- readBody small 0
      cs <- contacts big
      labelled "jam: circle 0.5 after 1500 steps: y, speed, contacts" (fmt (yOf b) ++ ", " ++ fmt (speed b) ++ ", " ++ show (length cs))
      labelled "jam: control circle 0.05 after 1500 steps: y" (fmt (yOf s))
      yOf b `shouldSatisfy` (> -2.2)
      speed b `shouldSatisfy` (< 1e-6)
      length cs `shouldSatisfy` (> 0) -- held by its self-contact
      yOf s `shouldSatisfy` (< yOf b - 1)
      abs (evalField trumpet (bsPos b)) `shouldSatisfy` (< 1e-6)

    -- (awake: asleep, a jammed body holds whatever its self-contact does.
    -- With the push taken in the tangent plane at the crossing, on the far
    -- side of the neck, the circle of 0.3 crept round the neck from
    -- round-off, its speed e-fold every 72 steps: 5e-5 at 2000 steps, 0.07
    -- at 3000, and it kept circling; 0.4 and 0.5 held)
    it "keeps jammed circles of 0.3, 0.4 and 0.5 still for 6000 steps with sleeping off" $
      forM_ [0.3, 0.4, 0.5] $ \size -> do
        w <- build (awake (trumpetScenario "jam" circle size))
        steps w 1000
        jammed <- readBody w 0
        speeds <- forM [2 .. 6 :: Int] $ \_ -> steps w 1000 >> speed <$> readBody w 0
        b <- readBody w 0
        labelled ("jam: circle " ++ fmt size ++ ": y at 1000 steps, speeds at 2000, ..., 6000")
          (fmt (yOf jammed) ++ "; " ++ unwords (map fmt speeds))
        (size, maximum speeds < 1e-6, abs (yOf b - yOf jammed) < 1e-6, yOf jammed < -1.5) `shouldBe` (size, True, True, True)

    -- (a square's self-contact was tested only once its rays had turned
    -- far enough, by when they already overran each other by a fiftieth of
    -- its size: the row that appeared pushed it out of the test's reach and
    -- it fell back, every seven steps, and the relaxing sweep, scaled as
    -- the self-contact's push is, left it 0.4 of the push-out speed: it
    -- moved at up to 0.07 a second)
    it "keeps squares of 0.3, 0.4 and 0.5 jammed alone still with sleeping off (under 1 % of their size a second)" $
      forM_ [0.3, 0.4, 0.5] $ \size -> do
        w <- build (awake (trumpetScenario "jam" square size))
        steps w 1000
        later <- forM [1 .. 1000 :: Int] $ \_ -> steps w 1 >> readBody w 0
        let places = map bsPos later
            secondMoves = zipWith (\p q -> norm (q - p)) places (drop 100 places)
            fastest = maximum (map speed later)
            y0 = yOf (head later)
        labelled ("jam: square " ++ fmt size ++ ": y at 1000 steps, fastest speed and largest move in 100 steps over the next 1000")
          (fmt y0 ++ "; " ++ fmt fastest ++ ", " ++ fmt (maximum secondMoves))
        (size, fastest < 0.01 * size, maximum secondMoves < 0.01 * size, y0 < -1.5) `shouldBe` (size, True, True, True)

    -- (the line between two bodies either side of a neck narrower than
    -- they are wide runs through the neck, so each side of their row is
    -- short, 0.11 here: at the push-out in the row's own units they rose
    -- 0.55 in the first 50 steps, 1.1 a second)
    it "pushes two circles wedged either side of the trumpet's neck apart no faster than the push-out" $ do
      let y0 = -2.3
          r0 = exp y0
      w <- build (Scenario "wedge" trumpet defaultParams { pSleep = False }
                    [dyn circle 0.25 (V3 r0 y0 0) 0 0 0, dyn circle 0.25 (V3 (negate r0) y0 0) 0 0 0] 0 [])
      heights <- forM [1 .. 50 :: Int] $ \_ -> steps w 10 >> mapM (fmap yOf . readBody w) [0, 1]
      let hs = [y0, y0] : heights
          rises = zipWith (\a b -> maximum (zipWith (-) b a) / (10 * pDt defaultParams)) hs (tail hs)
      labelled "wedge: the circles' heights every 10 steps (first), their fastest rise a second" (unwords (map (fmt . head) heights) ++ "; " ++ fmt (maximum rises))
      maximum rises `shouldSatisfy` (<= pPushout defaultParams)
      -- and they still rise to where two such circles jam (y = -1.535)
      minimum (last heights) `shouldSatisfy` (> -1.6)

    it "does not give a square wedged in the trumpet's neck energy (self-contact)" $ do
      w <- build jamSquareScenario
      let g = V3 0 (-0.6) 0
      e0 <- bodyEnergy w g 0
      es <- forM [1 .. 600 :: Int] $ \_ -> stepNative w >> bodyEnergy w g 0
      let gain = maximum es - e0
      labelled "trumpet square 0.5: initial energy, largest energy in 600 steps" (fmt e0 ++ ", " ++ fmt (maximum es))
      -- (the first self-contact is found at depth ~0.12: a Baumgarte bias of
      -- 0.6·β·depth/dt once threw the body back up the horn)
      gain `shouldSatisfy` (< 0.01 * abs e0 + 1e-3)

  describe "boundaries" $ do
    it "keeps 24 bodies dropped into the hemisphere inside it for 2000 steps (every outline vertex b(p) >= -2 % of size)" $ do
      r <- runBowl (hemisphereScenario 1.9)
      labelled "hemisphere (speeds up to 1.9): worst outline violation / size (step), steps with boundary contacts"
        (fmt (bowlWorst r) ++ " (" ++ show (bowlWorstStep r) ++ "), " ++ show (bowlRimSteps r))
      bowlRimSteps r `shouldSatisfy` (> 0) -- the rim was reached
      bowlWorst r `shouldSatisfy` (<= 0.02)

    it "lets bodies thrown at the hemisphere's rim out by no more than a recent step's travel beyond 2 %, and has them back inside after" $ do
      r <- runBowl (hemisphereScenario 2.5)
      labelled "hemisphere (speeds up to 2.5): worst outline violation / size (step), steps with boundary contacts"
        (fmt (bowlWorst r) ++ " (" ++ show (bowlWorstStep r) ++ "), " ++ show (bowlRimSteps r))
      labelled "hemisphere (speeds up to 2.5): worst violation beyond 2 % + the body's largest step in the last 10, / size; worst in steps 1001-2000"
        (fmt (bowlBeyond r) ++ "; " ++ fmt (bowlLate r))
      bowlRimSteps r `shouldSatisfy` (> 0)
      bowlBeyond r `shouldSatisfy` (<= 0)
      bowlLate r `shouldSatisfy` (<= 0.02)

  describe "quotients" $
    it "collides a body with another's antipodal image on the projective plane and pushes them apart; not on the sphere" $ do
      let run sp = do
            w <- build (imageScenario sp)
            bs0 <- bodyStates w
            counts <- forM [1 .. 300 :: Int] $ \_ -> stepNative w >> contactCount w
            bs <- bodyStates w
            cs <- contacts w
            pure (counts, zip bs0 bs, cs)
      (pc, pmoves, pcs) <- run projectivePlane
      (sc, smoves, _) <- run sphere
      let pbs = map snd pmoves
          sbs = map snd smoves
          [a, b] = pbs
          -- (how far each went, not its speed: the soft step's relaxing
          -- solve leaves an overlap's push-out no velocity behind)
          moved (x, y) = norm (bsPos y - bsPos x)
          -- circles of geodesic radius 0.2 overlap when their centres are
          -- closer than 0.4 along the sphere
          imageGap = angleBetween (bsPos a) (negate (bsPos b)) * pi / 180
          directGap = angleBetween (bsPos a) (bsPos b) * pi / 180
          lastDepth = maxDepthOf pcs / 0.2
      labelled "projective plane: steps with contacts, initial overlap of the images" (show (length (filter (> 0) pc)) ++ ", " ++ fmt (0.4 - imageSeparation))
      labelled "projective plane: after 300 steps, gap between A and B's image (geodesic), distances moved" (fmt imageGap ++ ", " ++ unwords (map (fmt . moved) pmoves))
      labelled "sphere (control): steps with contacts" (show (length (filter (> 0) sc)))
      head pc `shouldSatisfy` (> 0)
      imageGap `shouldSatisfy` (> 0.4 - 0.02 * 0.2)
      lastDepth `shouldSatisfy` (< 0.02)
      -- far apart in R³ (they start 2.78 apart; touching directly would
      -- take under 0.4), so what pushed them was the image's contact
      directGap `shouldSatisfy` (> 1)
      forM_ pmoves $ \m -> moved m `shouldSatisfy` (> 0.01)
      sum sc `shouldBe` 0
      forM_ sbs $ \x -> bsVel x `shouldBe` V3 0 0 0

  describe "symmetry" $
    it "pushes two equal circles overlapping on the sphere apart by equal distances (mirror symmetry)" $ do
      -- (distances, not speeds: the soft step's relaxing solve leaves an
      -- overlap's push-out no velocity behind)
      let sep = imageSeparation
          run sp bodies = do
            w <- mkWorld sp defaultParams { pGravity = False } bodies
            [a0, b0] <- bodyStates w
            steps w 300
            [a, b] <- bodyStates w
            pure (norm (bsPos a - bsPos a0), norm (bsPos b - bsPos b0))
          two p q = [dyn circle 0.2 p 0 0 0, dyn circle 0.2 q 0 0 0]
      (pa, pb) <- run plane (two (V3 0 0 0) (V3 sep 0 0))
      (sa, sb) <- run sphere (two (V3 0 0 1) (V3 (sin sep) 0 (cos sep)))
      (ia, ib) <- run projectivePlane (scBodies (imageScenario projectivePlane))
      let asym (x, y) = abs (x - y) / max x y
      labelled "symmetry: distances moved in separating, plane / sphere / projective plane (images)"
        (unwords [fmt pa, fmt pb, "/", fmt sa, fmt sb, "/", fmt ia, fmt ib])
      asym (pa, pb) `shouldSatisfy` (< 1e-9)
      -- (a pair's push is along the tangent plane midway between the two:
      -- along one body's own plane, its projection onto the other's was
      -- shorter by the cosine between the planes, 0.94 here)
      asym (sa, sb) `shouldSatisfy` (< 1e-3)
      asym (ia, ib) `shouldSatisfy` (< 1e-3)

  describe "mouse" $
    it "drags a body grabbed off its centre to a target 0.5 away (within 5 %), on the surface; after release the joint has no effect" $ do
      let sc = mouseScenario
      w <- build sc
      before <- readBody w 0
      held <- heldAt w 0 mouseGrabPoint
      let Held r _ = held
      grabAt w 0 1 mouseGrabPoint 5 0.7 mouseMaxForce
      dragAt w mouseTarget
      steps w 300
      b <- readBody w 0
      q <- heldPoint w 0 held
      o <- outline w 0
      let miss = norm (q - mouseTarget)
      labelled "mouse: grabbed offset from the centre, target distance" (fmt r ++ ", " ++ fmt (norm (mouseTarget - mouseGrabPoint)))
      labelled "mouse: after 300 steps, |grabbed point - target| / 0.5, centre moved" (fmt (miss / mouseDistance) ++ ", " ++ fmt (norm (bsPos b - bsPos before)))
      r `shouldSatisfy` (> 0.09)
      miss `shouldSatisfy` (< 0.05 * mouseDistance)
      abs (evalField sphere (bsPos b)) `shouldSatisfy` (< 1e-9)
      maximum [abs (evalField sphere v) | v <- o] `shouldSatisfy` (< 1e-6)
      -- release; a copy of the world that was never grabbed must run the same
      releaseMouse w
      fresh <- newWorld sphere (nwLayout w)
      copyWorld w fresh
      MV.set (wMouse (nwArrays fresh)) 0
      e0 <- bodyEnergy w (V3 0 (-4) 0) 0
      om0 <- bsOmega <$> readBody w 0
      steps w 200
      steps fresh 200
      x <- readBody w 0
      y <- readBody fresh 0
      e1 <- bodyEnergy w (V3 0 (-4) 0) 0
      m <- bodyMass w 0
      let scale = m * 4 -- m |g| R, the energy of a fall of one radius
      labelled "mouse: after release, 200 steps: |released - never grabbed|, omega change, energy change / (m g R)" (fmt (norm (bsPos x - bsPos y)) ++ ", " ++ fmt (abs (bsOmega x - om0)) ++ ", " ++ fmt (abs (e1 - e0) / scale))
      bsPos x `shouldBe` bsPos y
      bsVel x `shouldBe` bsVel y
      bsOmega x `shouldBe` bsOmega y
      abs (bsOmega x - om0) `shouldSatisfy` (< 1e-12) -- a free body spins freely
      abs (e1 - e0) `shouldSatisfy` (< 3e-3 * scale) -- the integrator's O(dt) energy error, not a pull

  describe "native vs emitted JavaScript (200 steps per scenario, 60 for moving piles, bit for bit)" $
    forM_ allScenarios $ \sc ->
      it (scName sc) $ do
        w <- build sc
        steps w (scWarmup sc)
        d <- differential w (scWindow sc)
        labelled ("differential " ++ scName sc ++ ": max |pos|, |vel|, |verts| difference; contacts native/js")
          (fmt (dPos d) ++ ", " ++ fmt (dVel d) ++ ", " ++ fmt (dVerts d) ++ "; " ++ show (dContacts d))
        (dPos d, dVel d, dVerts d) `shouldBe` (0, 0, 0)
        uncurry shouldBe (dContacts d)

  describe "robustness" $
    it "random scenes on every space (2-6 bodies, sizes 0.05-0.3, speeds up to 2, gravity, 0-3 random joints): finite, on the surface, no body or joint lost" $ do
      (nScenes, nSteps) <- robustnessCounts
      labelled "robustness" (show nScenes ++ " scenes x " ++ show nSteps ++ " steps per space (MANIFOLD_ROBUSTNESS=NxK), the spaces shared among the cores")
      t0 <- getMonotonicTime
      let runSpace sp = do
            s0 <- getMonotonicTime
            results <- forM [1 .. nScenes] $ \seed -> do
              let bodies = unGen (genScene sp) (mkQCGen (seed + 1000 * length (spaceName sp))) 30
              w <- mkWorld sp defaultParams bodies
              _ <- addRandomJoints w (unGen (genJoints (length bodies)) (mkQCGen (seed + 7 + 1000 * length (spaceName sp))) 30)
              n0 <- bodyCount w
              j0 <- jointCount w
              worstField <- newIORef (0 :: Double)
              okRef <- newIORef True
              let check = do
                    fin <- allFinite w
                    n <- bodyCount w
                    nj <- jointCount w
                    bs <- bodyStates w
                    let f = maximum (0 : [abs (evalField sp (bsPos b)) | b <- bs])
                    modifyIORef' worstField (max f)
                    unless (fin && n == n0 && nj == j0) $ writeIORef okRef False
              forM_ [1 .. nSteps] $ \k -> do
                stepNative w
                when (k `mod` 50 == 0 || k == nSteps) check
              ok <- readIORef okRef
              f <- readIORef worstField
              warnings <- warningCount w
              pure ((seed, ok, f, warnings), j0)
            s1 <- getMonotonicTime
            pure (sp, s1 - s0, map fst results, sum (map snd results))
      perSpace <- inParallel (map runSpace catalogue)
      t1 <- getMonotonicTime
      summary <- forM perSpace $ \(sp, secs, results, joints) -> do
        let worst = maximum [f | (_, _, f, _) <- results]
            bad = [seed | (seed, ok, _, _) <- results, not ok]
            warned = [(seed, k) | (seed, _, _, k) <- results, k > 0]
        putStrLn (printf "    robustness %-17s %6.1f s (%.2f ms/step), %d joints, max |field| %.1e, warnings %d (scenes with warnings: %s)" (spaceName sp) secs
                    (1000 * secs / fromIntegral (nScenes * nSteps)) joints worst (sum (map snd warned)) (show (map fst warned)))
        pure (spaceName sp, bad, worst < 1e-6)
      labelled "robustness: total time" (printf "%.1f s" (t1 - t0))
      forM_ summary $ \(name, bad, onSurface) -> do
        (name, bad) `shouldBe` (name, [])
        (name, onSurface) `shouldBe` (name, True)

  describe "contact pairs" $
    it "gives a touching pair at most two contact rows, both pushing along one direction (settled piles of 300 bodies)" $
      forM_ [sphere, torus, projectivePlane, rectangle] $ \sp -> do
        w <- loadScene 0 (benchScene sp 300) >>= either (fail . ((spaceName sp ++ ": ") ++)) pure
        steps w 100
        cs <- contacts w
        let n = length cs
            rows = [((cOwner c, cKey c `div` 4), cDirection c) | c <- cs, cB c >= 0]
        -- under its owner, a pair (through one image) has the keys 4k to
        -- 4k + 3 (it used up all four, two for each body's vertices in the
        -- other). (A body's boundary rows, 8 and 9, may push along two
        -- walls in a corner.)
        let groups = M.elems (M.fromListWith (++) [(k, [d]) | (k, d) <- rows])
            largest = maximum (0 : map length groups)
            spread = maximum (0 : [norm (d - d') | d : ds <- groups, d' <- ds])
        labelled ("contact pairs " ++ spaceName sp ++ ": rows, pairs, largest pair, direction spread")
          (show n ++ ", " ++ show (length groups) ++ ", " ++ show largest ++ ", " ++ fmt spread)
        (spaceName sp, n > 100) `shouldBe` (spaceName sp, True) -- a pile, not a scattering
        (spaceName sp, largest) `shouldSatisfy` ((<= 2) . snd)
        (spaceName sp, spread) `shouldSatisfy` ((< 1e-12) . snd)

  describe "deep overlaps" $ do
    it "separates two hexagons whose centres start 0.4 radii apart (a vertex past the other's centre faces its far edge), without passing them through each other" $ do
      w <- mkWorld plane defaultParams { pGravity = False }
             [dyn (regularPolygon 6) 0.2 (V3 (-0.04) 0 0) 0 0 0, dyn (regularPolygon 6) 0.2 (V3 0.04 0 0) 0 0 0]
      steps w 200
      [a, b] <- bodyStates w
      let apart = norm (bsPos a - bsPos b)
      labelled "deep overlap, hexagons: centre distance after 200 steps (sides touch at 0.346), x of each" (fmt apart ++ ", " ++ fmt (xOf a) ++ ", " ++ fmt (xOf b))
      apart `shouldSatisfy` (> 0.2 * sqrt 3 - 0.002)
      xOf a `shouldSatisfy` (< xOf b)
    it "separates two circles whose centres start 0.4 radii apart to touching (within the slop), awake until they are out, at rest then" $ do
      w <- mkWorld plane defaultParams { pGravity = False }
             [dyn circle 0.2 (V3 (-0.04) 0 0) 0 0 0, dyn circle 0.2 (V3 0.04 0 0) 0 0 0]
      steps w 200
      [a, b] <- bodyStates w
      let apart = norm (bsPos a - bsPos b)
      labelled "deep overlap, circles: centre distance after 200 steps (touching at 0.4), x of each" (fmt apart ++ ", " ++ fmt (xOf a) ++ ", " ++ fmt (xOf b))
      apart `shouldSatisfy` (\d -> d > 0.4 - 2 * 0.001 * 0.2 && d < 0.4)
      xOf a `shouldSatisfy` (< xOf b)
      map (norm . bsVel) [a, b] `shouldSatisfy` all (< 1e-9)

  describe "frictionless stacking" $
    it "a frictionless stack of two boxes stands for 1000 steps" $ do
      w <- mkWorld plane defaultParams { pFriction = 0 } (take 3 (scBodies (stackScenario defaultParams)))
      steps w 1000
      bs <- tail <$> bodyStates w
      let drift = maximum (map (abs . xOf) bs)
          tilt = maximum (map (abs . bsAngle) bs)
      labelled "frictionless two-box stack after 1000 steps: max drift / size, max tilt (rad)" (fmt (drift / boxSize) ++ ", " ++ fmt tilt)
      -- (it slid apart while each pair had two contact sets, one per body,
      -- which disagreed once the boxes tilted: without friction the
      -- difference was an unbalanced sideways impulse)
      drift `shouldSatisfy` (< 0.1 * boxSize)
      tilt `shouldSatisfy` (< 0.01)
