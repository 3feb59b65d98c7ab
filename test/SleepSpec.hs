-- | Islands and sleeping against what they promise: a settled pile falls
-- asleep soon after it comes to rest and then costs no contact work; an
-- island wakes whole and alone (grabbed, struck, a body removed from under
-- it, a joint made), every island when a parameter changes; a saved
-- sleeping pile goes on bit for bit; with sleeping off nothing sleeps.
module SleepSpec (spec) where

import Control.Monad (forM, forM_, replicateM_, when)
import qualified Data.Aeson as A
import qualified Data.ByteString.Lazy.Char8 as BL
import Data.IORef
import Data.Maybe (fromMaybe, isJust, isNothing)
import Linear.Metric (norm)
import Linear.V3 (V3 (..))
import Test.Hspec

import Manifold
import Manifold.Engine
import Manifold.Scene (BodySpec (..), Scene (..), loadScene, parseScene, sceneJSON, sceneOfWorld)
import PhysicsUtil

-- | Two stacks of three boxes on a static floor on the plane (gravity along
-- −z), far apart: two islands once they sleep. Body 0 is the floor; the
-- left stack is bodies 1–3, the right one 4–6.
twoStacks :: Params -> IO NativeWorld
twoStacks ps = mkWorldCap 8 plane ps
  (still square 3 (V3 0 0 (-3)) 0
     : [ dyn square h (V3 x 0 (z k)) (V3 0 0 0) 0 0 | x <- [-1, 1], k <- [0 .. 2 :: Int] ])
  where
    h = 0.1
    -- the floor's top is at z = −3 + 3/√2; each box a side h√2 tall
    z k = -3 + 3 / sqrt 2 + h / sqrt 2 + fromIntegral k * h * sqrt 2

asleep :: NativeWorld -> Int -> IO Bool
asleep w i = isJust . bsAsleep <$> readBody w i

-- | Step until every movable body sleeps (at most @n@ steps); how many
-- steps that took.
untilAsleep :: NativeWorld -> Int -> IO Int
untilAsleep w n = stepsWhile w n ((> 0) <$> awakeCount w)

spec :: Spec
spec = do
  describe "falling asleep" $ do
    it "a pile of 1000 boxes (rectangle, 50 wide and 20 high) falls asleep within 3 s of coming to rest, and asleep a step finds no contacts and moves nothing" $ do
      let side = 2.98 / 50
          boxes = [ dyn square (side / sqrt 2) (V3 (-1.49 + (fromIntegral c + 0.5) * side) 0 (-1 + (fromIntegral r + 0.5) * side)) (V3 0 0 0) 0 0
                  | r <- [0 .. 19 :: Int], c <- [0 .. 49 :: Int] ]
      w <- mkWorld rectangle defaultParams boxes
      n <- bodyCount w
      let dt = pDt defaultParams
          threshold = pSleepSpeed defaultParams
          size = side / sqrt 2
          -- the fastest body, in sizes a second (its rim's speed too)
          fastest = do
            bs <- bodyStates w
            pure (maximum [ max (norm (bsVel b)) (abs (bsOmega b) * size) / size | b <- bs ])
      restRef <- newIORef Nothing
      sleptRef <- newIORef Nothing
      lastFastest <- newIORef 0
      let go k = when (k <= (600 :: Int)) $ do
            stepNative w
            rest <- readIORef restRef
            v <- fastest
            writeIORef lastFastest v
            -- at rest: every body slower than half the sleep threshold
            when (isNothing rest && v < 0.5 * threshold) (writeIORef restRef (Just k))
            awake <- awakeCount w
            if awake == 0 then writeIORef sleptRef (Just k) else go (k + 1)
      go 1
      rest <- readIORef restRef
      slept <- readIORef sleptRef
      v <- readIORef lastFastest
      labelled "pile of 1000 boxes (rectangle): at rest at step, all asleep at step, fastest body at the end (sizes/s)" (show rest ++ ", " ++ show slept ++ ", " ++ fmt v)
      case (rest, slept) of
        (Nothing, Nothing) -> expectationFailure ("the pile does not come to rest in 6 s (its fastest body at "
          ++ fmt v ++ " of its size a second, the sleep threshold " ++ show threshold ++ ")")
        _ -> do
          case slept of
            Nothing -> expectationFailure ("at rest at step " ++ show rest ++ " but not asleep by step 600")
            Just s' -> fromIntegral (s' - fromMaybe 0 rest) * dt `shouldSatisfy` (<= 3)
          before <- bodyStates w
          stepNative w
          contactCount w `shouldReturn` 0
          after <- bodyStates w
          map bsPos after `shouldBe` map bsPos before
          n `shouldBe` 1000

    it "with \"sleep\": false nothing sleeps" $ do
      w <- twoStacks defaultParams { pSleep = False }
      steps w 300
      awakeCount w `shouldReturn` 6

    it "a body held by the mouse does not fall asleep, nor does its island" $ do
      w <- twoStacks defaultParams
      p <- bsPos <$> readBody w 3
      grabAt w 3 1 p 5 0.7 100
      steps w 300
      mapM (asleep w) [1 .. 6] `shouldReturn` replicate 3 False ++ replicate 3 True

  describe "waking" $ do
    it "grabbing a body of a sleeping island wakes that island only" $ do
      w <- twoStacks defaultParams
      k <- untilAsleep w 1000
      labelled "two stacks asleep after steps" (show k)
      islandCount w `shouldReturn` 2
      p <- bsPos <$> readBody w 2
      grabAt w 2 1 p 5 0.7 100
      stepNative w
      mapM (asleep w) [1 .. 6] `shouldReturn` replicate 3 False ++ replicate 3 True

    it "a body dropped onto a sleeping stack wakes it (and not the other)" $ do
      w <- twoStacks defaultParams
      _ <- untilAsleep w 1000
      top <- bsPos <$> readBody w 3
      _ <- addBody w (dyn circle 0.08 (top + V3 0 0 0.4) (V3 0 0 (-1)) 0 0) >>= either fail pure
      woke <- stepsWhile w 200 (asleep w 1)
      labelled "the struck stack woke after steps" (show woke)
      mapM (asleep w) [1 .. 6] `shouldReturn` replicate 3 False ++ replicate 3 True

    it "a box struck while asleep moves as it would awake (its island wakes before the step's solve): under a heavy box dropped on it, it sinks into the floor as with sleeping off" $ do
      -- a box of half-side 0.05 at rest on a static floor (asleep within
      -- 0.5 s) and a box ten times its size and density dropped onto it
      let scene on = BL.pack $ concat
            [ "{\"space\": \"plane\", \"sleep\": ", on, ", \"bodies\": ["
            , "{\"shape\": {\"box\": [2, 0.1]}, \"static\": true, \"p\": [0, 0, -0.1]},"
            , "{\"shape\": {\"box\": [0.05, 0.05]}, \"p\": [0, 0, 0.05]},"
            , "{\"shape\": {\"box\": [0.1, 0.1]}, \"density\": 10, \"p\": [0, 0, 1.5]}]}" ]
          -- the box's height each step, and whether it slept before it was struck
          run on = do
            w <- either fail pure (parseScene (scene on)) >>= loadScene 0 >>= either fail pure
            forM [1 .. 300 :: Int] $ \_ -> do
              stepNative w
              (\(V3 _ _ z) -> z) . bsPos <$> readBody w 1
      slept <- do
        w <- either fail pure (parseScene (scene "true")) >>= loadScene 0 >>= either fail pure
        replicateM_ 70 (stepNative w)
        asleep w 1
      slept `shouldBe` True
      withSleep <- run "true"
      without <- run "false"
      labelled "the struck box's lowest centre, with sleeping and without (resting at 0.05)" (fmt (minimum withSleep) ++ ", " ++ fmt (minimum without))
      minimum without `shouldSatisfy` (< 0.045) -- it was struck hard enough to sink
      abs (minimum withSleep - minimum without) `shouldSatisfy` (< 1e-3)

    it "removing the box under a sleeping stack wakes the boxes on it, which fall" $ do
      w <- twoStacks defaultParams
      _ <- untilAsleep w 1000
      z0 <- (\(V3 _ _ z) -> z) . bsPos <$> readBody w 2
      removeBodyAt w 1 -- body 6 takes index 1
      mapM (asleep w) [1 .. 5] `shouldReturn` [True, False, False, True, True]
      steps w 30
      z1 <- (\(V3 _ _ z) -> z) . bsPos <$> readBody w 2
      z1 `shouldSatisfy` (< z0 - 0.01)

    it "a joint made to a sleeping body wakes its island; a parameter change wakes every island" $ do
      w <- twoStacks defaultParams
      _ <- untilAsleep w 1000
      p <- bsPos <$> readBody w 6
      _ <- addJointAt w Revolute 6 (-1) p p >>= either fail pure
      stepNative w
      mapM (asleep w) [1 .. 6] `shouldReturn` replicate 3 True ++ replicate 3 False
      _ <- untilAsleep w 1000
      setParams w defaultParams { pFriction = 0.5 }
      stepNative w
      awakeCount w `shouldReturn` 6

  describe "saved and loaded" $
    it "a sleeping pile saved as a scene and loaded goes on bit for bit, its islands and timers kept, and wakes alike" $ do
      forM_ [False, True] $ \generic -> do
        w0 <- twoStacks defaultParams
        let w = if generic then genericStep w0 else w0
            scene = Scene plane defaultParams [] [] Nothing
        _ <- untilAsleep w 1000
        n <- bodyCount w
        states <- mapM (readBody w) [0 .. n - 1]
        -- the bodies as a scene holds them (the floor static)
        let bodies = [ bodySpecOf (i == 0) b | (i, b) <- zip [0 :: Int ..] states ]
        saved <- sceneOfWorld scene { sceneBodies = bodies } w >>= either fail pure
        again <- either fail pure (parseScene (A.encode (sceneJSON saved)))
        -- each stack one island, named by one of its boxes
        let labels = map bsSleeping (sceneBodies again)
            left = take 3 (drop 1 labels)
            right = drop 4 labels
        (head labels, all (== head left) left, all (== head right) right, head left /= head right)
          `shouldBe` (Nothing, True, True, True)
        (`elem` map Just [1 .. 3]) (head left) `shouldBe` True
        loaded <- loadScene 1 again >>= either fail pure
        let w' = if generic then genericStep loaded else loaded
        awakeCount w' `shouldReturn` 0
        -- the same blow to both: a body dropped on the left stack
        top <- bsPos <$> readBody w 3
        forM_ [w, w'] $ \v -> addBody v (dyn circle 0.08 (top + V3 0 0 0.4) (V3 0 0 (-1)) 0 0) >>= either fail (const (pure ()))
        steps w 120
        steps w' 120
        h <- stateHash w
        h' <- stateHash w'
        h' `shouldBe` h
  where
    bodySpecOf static b = BodySpec SquareShape (if static then 3 else 0.1) 1 static (bsPos b) (V3 0 0 0) 0 0 Nothing [] Nothing 0 sceneMaterial
