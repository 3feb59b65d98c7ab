-- | Joints against mechanics: a pendulum swings with the rigid pendulum's
-- period, a chain on the sphere keeps its links together, a motor reaches
-- its speed, a limit holds its angle, a distance spring oscillates at its
-- frequency; joints act across a quotient's glued edges (through a flip
-- too); saved and loaded, a jointed run goes on bit for bit; malformed
-- joints are refused with the JSON path.
module JointSpec (spec) where

import Control.Monad (forM_, replicateM_)
import qualified Data.ByteString.Lazy.Char8 as BL
import Data.Either (fromLeft, isLeft)
import Data.IORef
import Data.List (isPrefixOf)
import Linear.Metric (distance, dot, norm)
import Linear.V3 (V3 (..), cross)
import Linear.Vector ((*^))
import Test.Hspec

import Manifold
import Manifold.Engine
import Manifold.World (Slot (..))
import Manifold.Scene (loadScene, parseScene, sceneJSON, sceneOfWorld)
import qualified Data.Aeson as A
import PhysicsUtil

-- | The plane's gravity, along −z.
gravity :: Double
gravity = 4

-- | Add a joint or fail the test.
joined :: NativeWorld -> JointKind -> Int -> Int -> V3 Double -> V3 Double -> IO Int
joined w k a b qa qb = addJointAt w k a b qa qb >>= either fail pure

-- | The times at which @x@ crosses zero going up, over @seconds@.
upCrossings :: NativeWorld -> Double -> IO Double -> IO [Double]
upCrossings w seconds x = do
  let dt = pDt defaultParams
  let n = round (seconds / dt) :: Int
  prev <- x >>= newIORef
  times <- newIORef []
  forM_ [1 .. n] $ \k -> do
    stepNative w
    now <- x
    before <- readIORef prev
    -- the crossing, linearly between the two steps
    if before < 0 && now >= 0
      then modifyIORef' times (((fromIntegral k - now / (now - before)) * dt) :)
      else pure ()
    writeIORef prev now
  reverse <$> readIORef times

-- | The mean period of the crossings.
period :: [Double] -> Double
period ts = (last ts - head ts) / fromIntegral (length ts - 1)

-- | A 50-link chain of circles of radius 0.02 pinned where they touch, the
-- first static, laid along a curve of the sphere (by arc length): the
-- largest anchor gap after 10 s, in links; the chain's end must have
-- fallen (below y = −0.3).
chainGap :: Params -> (Double -> V3 Double) -> IO Double
chainGap ps curve = do
  let n = 50
      r = 0.02
      at k = curve (2 * r * fromIntegral k)
      pin k = curve (2 * r * (fromIntegral k + 0.5))
  w <- mkWorldCap (n + 1) sphere ps
         (still circle r (at (0 :: Int)) 0 : [dyn circle r (at k) (V3 0 0 0) 0 0 | k <- [1 .. n]])
  forM_ [0 .. n - 1] $ \k -> joined w Revolute k (k + 1) (pin k) (pin k)
  steps w 1000
  allFinite w `shouldReturn` True
  end <- readBody w n
  let V3 _ endY _ = bsPos end
  endY `shouldSatisfy` (< -0.3)
  (/ (2 * r)) <$> worstGap w

-- | What a chain of 50 small links takes to hold within 1 %: eight
-- sub-steps and joints of 200 Hz. (At 120 Hz and four sub-steps the
-- hanging chain's top link sagged by 1.5 % of its size: the sag under the
-- chain's weight is about its load over ω², and these links are small for
-- the gravity; 200 Hz at four sub-steps rings. docs/engine.md#joints.)
longChain :: Params
longChain = defaultParams { pSubsteps = 8, pJointHertz = 200 }

-- | The equator from (1, 0, 0), and the meridian down from 60° north.
equator, meridian :: Double -> V3 Double
equator a = V3 (cos a) 0 (sin a)
meridian a = let lat = pi / 3 - a in V3 (cos lat) (sin lat) 0

-- | The largest gap between any joint's two anchors.
worstGap :: NativeWorld -> IO Double
worstGap w = maximum . (0 :) . map (uncurry distance) <$> jointAnchorPoints w

spec :: Spec
spec = do
  describe "revolute joint" $ do
    it "swings a pendulum with the rigid pendulum's period 2π √(I_pivot / (m g d))" $ do
      let d = 0.3
          theta0 = 0.05
          pivot = V3 0 0 0.5
          centre = pivot + V3 (d * sin theta0) 0 (negate d * cos theta0)
      w <- mkWorld plane defaultParams [dyn circle 0.05 centre (V3 0 0 0) 0 0]
      _ <- joined w Revolute 0 (-1) pivot pivot
      m <- recip <$> slot w 0 InvMass
      inertia <- recip <$> slot w 0 InvInertia
      ts <- upCrossings w 8 ((\b -> let V3 x _ _ = bsPos b in x) <$> readBody w 0)
      let expected = 2 * pi * sqrt ((inertia + m * d * d) / (m * gravity * d))
      length ts `shouldSatisfy` (>= 4)
      abs (period ts / expected - 1) `shouldSatisfy` (< 0.01)

    it "holds a 50-link chain swinging down the sphere together: every anchor gap within 1 % of a link at 10 s" $ do
      -- circles along the equator from a static one, pinned where they
      -- touch
      gap <- chainGap longChain equator
      gap `shouldSatisfy` (< 0.01)

    it "holds a 50-link chain hanging on the sphere (gap within 1 % of a link)" $ do
      -- the same chain hanging down a meridian from a static body at 60° north
      gap <- chainGap longChain meridian
      gap `shouldSatisfy` (< 0.01)

    it "drives a body with its motor to the motor's speed" $ do
      w <- mkWorld plane defaultParams [dyn square 0.1 (V3 0 0 0) (V3 0 0 0) 0 0]
      j <- joined w Revolute 0 (-1) (V3 0 0 0) (V3 0 0 0)
      mapM_ (uncurry (setJointField w j)) [(JMotorOn, 1), (JMotorSpeed, 3), (JMaxTorque, 10)]
      steps w 100
      omega <- bsOmega <$> readBody w 0
      -- the joint's relative angle is b's less a's: a motor speed of 3 turns body a at −3
      abs (omega + 3) `shouldSatisfy` (< 0.03)

    it "keeps a swinging pendulum within its angle limits (to 0.5°)" $ do
      -- a square hung from a point one circumradius above its centre, swung hard
      let pivot = V3 0 0 0.5
          size = 0.1
      w <- mkWorld plane defaultParams [dyn square size (pivot - V3 0 0 size) (V3 1.2 0 0) 0 0]
      j <- joined w Revolute 0 (-1) pivot pivot
      mapM_ (uncurry (setJointField w j)) [(JLimitOn, 1), (JLower, -0.3), (JUpper, 0.3)]
      worst <- newIORef 0
      replicateM_ 300 $ do
        stepNative w
        b <- readBody w 0
        let V3 x _ z = bsPos b - pivot
        modifyIORef' worst (max (abs (atan2 x (negate z))))
      swung <- readIORef worst
      swung `shouldSatisfy` (> 0.29) -- it reached the limit
      swung `shouldSatisfy` (< 0.3 + 0.5 * pi / 180)

  describe "weld joint" $ do
    it "turns a welded pair rigidly about the sphere's pole: once round, each body's carried axis shows the cap's holonomy 2π (1 − cos θ), its direction is back" $ do
      -- two circles at colatitude θ either side of the pole, welded at the
      -- pole, set turning as one body about y at Ω: each spins at Ω cos θ
      -- against the axis it carries, so after a whole turn (its direction
      -- back where it began) that axis has turned by the enclosed cap's
      -- area, not by 0 (drift) nor by its spin
      let th = 0.6
          om = 1
          at s = V3 (s * sin th) (cos th) 0
          vel s = V3 0 0 (negate (s * om * sin th))
          dirOf b = let n = bsNormal b; u = bsAxis b in cos (bsAngle b) *^ u + sin (bsAngle b) *^ (n `cross` u)
          signedAngle n a b = atan2 (n `dot` (a `cross` b)) (a `dot` b)
          azimuth b = let V3 x _ z = bsPos b in atan2 (negate z) x
      w <- mkWorld sphere defaultParams { pGravity = False }
             [dyn circle 0.1 (at 1) (vel 1) 0 (om * cos th), dyn circle 0.1 (at (-1)) (vel (-1)) 0 (om * cos th)]
      j <- joined w Weld 0 1 (V3 0 1 0) (V3 0 1 0)
      start <- readBody w 0
      turned <- newIORef 0
      worst <- newIORef (0 :: Double)
      worstGap' <- newIORef 0
      worstChord <- newIORef 0
      let go prev = do
            stepNative w
            b <- readBody w 0
            other <- readBody w 1
            let a = azimuth b
                da = a - prev - 2 * pi * fromIntegral (round ((a - prev) / (2 * pi)) :: Int)
            modifyIORef' turned (+ da)
            jointField w j JAngleError >>= modifyIORef' worst . max . abs
            worstGap w >>= modifyIORef' worstGap' . max
            modifyIORef' worstChord (max (abs (distance (bsPos b) (bsPos other) - 2 * sin th)))
            t <- readIORef turned
            if t < 2 * pi then go a else pure b
      end <- go (azimuth start)
      readIORef worst >>= (`shouldSatisfy` (< 0.5 * pi / 180))
      readIORef worstGap' >>= (`shouldSatisfy` (< 1e-3))
      readIORef worstChord >>= (`shouldSatisfy` (< 1e-3))
      distance (bsPos end) (bsPos start) `shouldSatisfy` (< 0.02)
      abs (signedAngle (bsNormal end) (dirOf start) (dirOf end)) `shouldSatisfy` (< pi / 180)
      -- spun 2π cos θ against the carried axis, which turned the rest
      let holonomy = 2 * pi * (1 - cos th)
      abs (bsAngle end - bsAngle start - 2 * pi * cos th) `shouldSatisfy` (< 0.01 * 2 * pi * cos th)
      abs (signedAngle (bsNormal end) (bsAxis start) (bsAxis end) - holonomy) `shouldSatisfy` (< 0.01 * holonomy)

    it "carries a welded pair once round the sphere's equator without drift: the relative angle within 0.5°, the pin together, back where it began" $ do
      -- no gravity: the pair moves as one body along the great circle (a
      -- geodesic, whose holonomy keeps every direction's angle to it)
      let at a = V3 (cos a) 0 (sin a)
          along a = V3 (negate (sin a)) 0 (cos a)
      w <- mkWorld sphere defaultParams { pGravity = False }
             [dyn circle 0.05 (at 0) (along 0) 0 0, dyn square 0.05 (at 0.1) (along 0.1) 0 0]
      j <- joined w Weld 0 1 (at 0.05) (at 0.05)
      worst <- newIORef 0
      worstGap' <- newIORef 0
      half <- newIORef (V3 0 0 0)
      forM_ [1 .. 628 :: Int] $ \k -> do
        stepNative w
        if k == 314 then readBody w 0 >>= writeIORef half . bsPos else pure ()
        e <- jointField w j JAngleError
        modifyIORef' worst (max (abs e))
        worstGap w >>= modifyIORef' worstGap' . max
      readIORef worst >>= (`shouldSatisfy` (< 0.5 * pi / 180))
      readIORef worstGap' >>= (`shouldSatisfy` (< 1e-3))
      a <- readBody w 0
      -- half way round at the antipode, and back
      readIORef half >>= (`shouldSatisfy` (< 0.05)) . distance (at pi)
      distance (bsPos a) (at 0) `shouldSatisfy` (< 0.02)

  describe "distance joint" $ do
    it "as a spring oscillates at its frequency (within 2 %)" $ do
      let hz = 2
      w <- mkWorld plane defaultParams { pGravity = False } [dyn circle 0.05 (V3 0.3 0 0) (V3 0 0 0) 0 0]
      j <- joined w Distance 0 (-1) (V3 0.3 0 0) (V3 0 0 0)
      mapM_ (uncurry (setJointField w j)) [(JHertz, hz), (JLength, 0.25), (JMinLength, 0), (JMaxLength, 1)]
      ts <- upCrossings w 5 ((\b -> 0.25 - norm (bsPos b)) <$> readBody w 0)
      length ts `shouldSatisfy` (>= 5)
      abs (period ts * hz - 1) `shouldSatisfy` (< 0.02)

    it "as a rope lets the body come closer but not go farther" $ do
      w <- mkWorld plane defaultParams [dyn circle 0.05 (V3 0.2 0 0) (V3 0 0 0) 0 0]
      j <- joined w Distance 0 (-1) (V3 0.2 0 0) (V3 0 0 0.1)
      mapM_ (uncurry (setJointField w j)) [(JMinLength, 0), (JMaxLength, 0.3)]
      worst <- newIORef 0
      replicateM_ 300 $ do
        stepNative w
        p <- bsPos <$> readBody w 0
        modifyIORef' worst (max (distance p (V3 0 0 0.1)))
      readIORef worst >>= (`shouldSatisfy` (< 0.3 * 1.01))
      -- it has swung down to hang at the rope's length
      p <- bsPos <$> readBody w 0
      distance p (V3 0 0 0.1) `shouldSatisfy` (> 0.29)

  describe "on quotient spaces" $ do
    it "a distance joint acts across the flat torus's edge, through the image" $ do
      -- two bodies on either side of the x = ±1 edge, 0.2 apart through it
      w <- mkWorld flatTorus defaultParams
             [dyn circle 0.05 (V3 0.9 0 0) (V3 0.5 0 0) 0 0, dyn circle 0.05 (V3 (-0.9) 0 0) (V3 0 0 0.3) 0 0]
      _ <- joined w Distance 0 1 (V3 0.9 0 0) (V3 (-0.9) 0 0)
      steps w 200
      gap <- worstGap w
      [(pa, pb)] <- jointAnchorPoints w
      abs (distance pa pb - 0.2) `shouldSatisfy` (< 0.002)
      gap `shouldSatisfy` (< 0.21)

    it "a pin holds across the flat Klein bottle's flipped edge while the pair wraps mirrored" $ do
      w <- mkWorld flatKlein defaultParams
             [dyn circle 0.05 (V3 0.8 0 0.3) (V3 1 0 0.2) 0 2, dyn circle 0.05 (V3 0.9 0 0.3) (V3 1 0 0.2) 0 2]
      _ <- joined w Revolute 0 1 (V3 0.85 0 0.3) (V3 0.85 0 0.3)
      worst <- newIORef 0
      flipped <- newIORef False
      replicateM_ 300 $ do
        stepNative w
        worstGap w >>= modifyIORef' worst . max
        b <- readBody w 0
        let V3 bx _ _ = bsPos b
        if bx < 0 then writeIORef flipped True else pure ()
      readIORef flipped `shouldReturn` True
      readIORef worst >>= (`shouldSatisfy` (< 0.001))

    it "a pin holds across the projective plane's antipode: a body pinned to the other's antipodal image swings under gravity, anchors together" $ do
      -- body b sits at the antipode of a point beside body a; the pin
      -- where a touches b's image is on b at the antipode of the pin
      let e a = V3 (sin a) 0 (cos a)
      w <- mkWorld projectivePlane defaultParams
             [dyn circle 0.08 (e (-0.1)) (V3 0.3 0.2 0) 0 0, dyn circle 0.08 (negate (e 0.1)) (V3 0 0 0) 0 0]
      j <- joined w Revolute 0 1 (e 0) (e 0)
      jointField w j JRadiusB >>= (`shouldSatisfy` (\r -> abs (r - 0.1) < 1e-3))
      -- the pin lets the bodies turn about it, each keeping its centre
      -- 0.1 (a chord of 2 sin 0.05) from the anchor, body b through its image
      let chord = 2 * sin 0.05
      worst <- newIORef 0
      worstReach <- newIORef 0
      replicateM_ 300 $ do
        stepNative w
        worstGap w >>= modifyIORef' worst . max
        [ca, cb] <- mapM (fmap bsPos . readBody w) [0, 1]
        [(pa, pb)] <- jointAnchorPoints w
        let reachB = min (distance pb cb) (distance pb (negate cb))
        modifyIORef' worstReach (max (max (abs (distance pa ca - chord)) (abs (reachB - chord))))
      readIORef worst >>= (`shouldSatisfy` (< 1e-3))
      readIORef worstReach >>= (`shouldSatisfy` (< 2e-3))

  describe "drawing (jointPaths)" $
    it "gives each anchor's geodesic from its body's centre and the chord laid on the sphere along the great circle between the anchors" $ do
      let e a = V3 (sin a) 0 (cos a)
      w <- mkWorld sphere defaultParams { pGravity = False }
             [dyn circle 0.08 (e (-0.5)) (V3 0 0 0) 0.3 0, dyn square 0.08 (e 0.5) (V3 0 0 0) 1 0]
      _ <- joined w Revolute 0 1 (e 0.1) (e 0.1)
      _ <- joined w Distance 0 1 (e (-0.45)) (e 0.45)
      steps w 3
      curves <- jointCurves w
      anchors <- jointAnchorPoints w
      a <- readBody w 0
      b <- readBody w 1
      forM_ (zip curves anchors) $ \((walkA, walkB, chord), (pa, pb)) -> do
        head walkA `shouldBe` bsPos a
        head walkB `shouldBe` bsPos b
        last walkA `shouldBe` pa
        distance (last walkB) pb `shouldSatisfy` (< 1e-12)
        distance (head chord) pa `shouldSatisfy` (< 1e-12)
        distance (last chord) pb `shouldSatisfy` (< 1e-12)
        forM_ (walkA ++ walkB ++ chord) $ \q -> abs (norm q - 1) `shouldSatisfy` (< 1e-9)
        -- on the great circle through the anchors, between them
        forM_ chord $ \q -> abs (q `dot` (pa `cross` pb)) `shouldSatisfy` (< 1e-9)
        -- in eight pieces, none much longer than an eighth of the arc
        let arc = 2 * asin (distance pa pb / 2)
        forM_ (zip chord (drop 1 chord)) $ \(p, q) -> distance p q `shouldSatisfy` (<= 1.1 * arc / 8)

  describe "scenes" $ do
    let chainScene = unlines
          [ "{\"space\": \"sphere\", \"bodies\": ["
          , "  {\"shape\": \"circle\", \"size\": 0.05, \"p\": [1, 0, 0], \"static\": true},"
          , "  {\"shape\": \"square\", \"size\": 0.05, \"p\": [0.995, 0, 0.0998]},"
          , "  {\"shape\": \"circle\", \"size\": 0.05, \"p\": [0.98, 0, 0.199]}],"
          , " \"joints\": ["
          , "  {\"type\": \"revolute\", \"a\": 0, \"b\": 1, \"anchor\": [0.9988, 0, 0.05], \"lowerAngle\": -1, \"upperAngle\": 1},"
          , "  {\"type\": \"distance\", \"a\": 1, \"b\": 2, \"anchorA\": [0.995, 0, 0.0998], \"anchorB\": [0.98, 0, 0.199], \"hertz\": 5, \"dampingRatio\": 0.3},"
          , "  {\"type\": \"weld\", \"a\": 2, \"b\": \"world\", \"anchor\": [0.9, 0, 0.4], \"hertz\": 1}]}" ]
    it "saved and loaded, a jointed run goes on bit for bit" $ do
      scene <- either fail pure (parseScene (BL.pack chainScene))
      w <- loadScene 0 scene >>= either fail pure
      steps w 50
      saved <- sceneOfWorld scene w >>= either fail pure
      again <- either fail pure (parseScene (A.encode (sceneJSON saved)))
      w' <- loadScene 0 again >>= either fail pure
      steps w 50
      steps w' 50
      h <- stateHash w
      h' <- stateHash w'
      h' `shouldBe` h
      jointCount w' `shouldReturn` 3

    it "refuses malformed joints, naming the JSON path" $ do
      let withJoint j = BL.pack (unlines
            [ "{\"space\": \"sphere\", \"bodies\": ["
            , "  {\"shape\": \"circle\", \"size\": 0.05, \"p\": [1, 0, 0]},"
            , "  {\"shape\": \"circle\", \"size\": 0.05, \"p\": [0.98, 0, 0.199]}],"
            , " \"joints\": [" ++ j ++ "]}" ])
          problemOf j = fromLeft "accepted" (parseScene (withJoint j))
      problemOf "{\"type\": \"hinge\", \"a\": 0, \"b\": 1, \"anchor\": [1, 0, 0]}"
        `shouldSatisfy` isPrefixOf "$.joints[0].type: unknown joint type \"hinge\""
      problemOf "{\"type\": \"revolute\", \"a\": 0, \"b\": 2, \"anchor\": [1, 0, 0]}"
        `shouldBe` "$.joints[0].b: must be a body's index, from 0 to 1, or \"world\""
      problemOf "{\"type\": \"revolute\", \"a\": 1, \"b\": 1, \"anchor\": [1, 0, 0]}"
        `shouldBe` "$.joints[0].b: joins body 1 to itself"
      problemOf "{\"type\": \"distance\", \"a\": 0, \"b\": 1, \"anchorA\": [1, 0, 0], \"anchorB\": [1, 0, 0], \"length\": -1}"
        `shouldBe` "$.joints[0].length: must not be negative"
      problemOf "{\"type\": \"revolute\", \"a\": 0, \"b\": 1, \"anchor\": [1, 0, 0], \"length\": 1}"
        `shouldSatisfy` isPrefixOf "$.joints[0].length: unknown key"
      problemOf "{\"type\": \"revolute\", \"a\": 0, \"b\": 1, \"anchor\": [1, 0, 0], \"lowerAngle\": 1}"
        `shouldBe` "$.joints[0].upperAngle: must be given with lowerAngle"
      -- the origin is where the sphere's field has no gradient: nothing to project from
      scene <- either fail pure (parseScene (withJoint "{\"type\": \"revolute\", \"a\": 0, \"b\": 1, \"anchor\": [0, 0, 0]}"))
      loaded <- loadScene 0 scene
      fromLeft "accepted" loaded `shouldSatisfy` isPrefixOf "$.joints[0].anchor: an anchor does not project onto the surface"
      isLeft loaded `shouldBe` True

  describe "removing bodies" $ do
    it "drops the removed body's joints and moves the last body's with it" $ do
      w <- mkWorld plane defaultParams { pGravity = False }
             [dyn circle 0.05 (V3 (0.2 * fromIntegral k) 0 0) (V3 0 0 0) 0 0 | k <- [0 .. 3 :: Int]]
      forM_ [0 .. 2] $ \k -> joined w Distance k (k + 1) (V3 (0.2 * fromIntegral k) 0 0) (V3 (0.2 * fromIntegral k + 0.2) 0 0)
      removeBodyAt w 1
      jointCount w `shouldReturn` 1
      -- the joint 2–3 is now 2–1 (body 3 took index 1)
      a <- jointField w 0 JA
      b <- jointField w 0 JB
      (a, b) `shouldBe` (2, 1)



