-- | The preset scenes of @scenes/@ ("Manifold.Presets"): every file is a
-- preset of the space its name starts with, names and scenes that are
-- wrong are refused naming the file, and each preset shows what its name
-- says when the native engine runs it: the pyramid and the cube's stack
-- stand, the trumpet's bodies jam in its neck and stay there, on the
-- projective plane a body meets the antipodal image of another (never the
-- body itself) and sets it moving, the Klein bottle's bodies go round at
-- a constant speed (free motion: nothing touches them); the joint presets
-- keep their joints together as they move (every anchor gap within 1 %
-- of the joined bodies' size after 10 s), and the sphere's chain swings
-- down. Every preset opens with a view of its bodies ("Manifold.Framing").
module PresetSpec (spec) where

import Control.Monad (forM, replicateM_)
import qualified Data.ByteString.Lazy.Char8 as BLC
import Data.Either (fromLeft)
import Data.List (isInfixOf)
import Linear.Metric (distance, dot, norm, normalize)
import Linear.V3 (V3 (..), cross)
import Linear.Vector ((^+^), (^-^))
import Test.Hspec

import qualified Data.Vector.Unboxed.Mutable as MV
import Manifold.Engine
import Manifold.Measures (MeasureSlot (..), measureSize, measureWorld)
import Manifold.Stage.Imp (runNative)
import Manifold.Framing (framingAspect, seenFrom)
import Manifold.Presets
import Manifold.Scene (BodySpec (..), Scene (..), loadScene, parseScene)
import Manifold.Space (Camera (..))
import PhysicsUtil (bodySize)

-- | The preset's world after each of some runs of steps: the bodies'
-- states, and the warnings so far.
runPreset :: String -> [Int] -> IO [([BodyState], Int)]
runPreset name runs = do
  text <- BLC.readFile ("scenes/" ++ name ++ ".json")
  scene <- either fail pure (parseScene text)
  w <- loadScene 0 scene >>= either fail pure
  n <- bodyCount w
  let look = (,) <$> mapM (readBody w) [0 .. n - 1] <*> warningCount w
  forM runs $ \k -> replicateM_ k (stepNative w) >> look

-- | The largest distance a body moved between two states of the world.
mostMoved :: [BodyState] -> [BodyState] -> Double
mostMoved a b = maximum (zipWith (\x y -> distance (bsPos x) (bsPos y)) a b)

spec :: Spec
spec = describe "Manifold.Presets" $ do
  it "every file of scenes/ is a preset of its space, the paper's figures among them" $ do
    presets <- readPresets "scenes" >>= either fail pure
    map presetName presets `shouldSatisfy` \names ->
      all (`elem` names) ["trumpet-jam", "projective-plane-image", "rectangle-pyramid", "sphere-rain", "cube-stack", "klein-bottle-orbit"]
    mapM_ (\p -> presetName p `shouldStartWith` (presetSpace p ++ "-")) presets

  it "refuses a name of no space, an empty part after it, a scene of another space and a bad scene, naming the file" $ do
    let refused file text = fromLeft "accepted" (presetOf file (BLC.pack text))
    refused "moon-jam.json" "{\"space\": \"sphere\"}" `shouldSatisfy` ("scenes/moon-jam.json: the name must be SPACE-WHAT.json" `isInfixOf`)
    refused "sphere-.json" "{\"space\": \"sphere\"}" `shouldSatisfy` ("lower-case words" `isInfixOf`)
    refused "sphere-Rain.json" "{\"space\": \"sphere\"}" `shouldSatisfy` ("lower-case words" `isInfixOf`)
    refused "torus-jam.json" "{\"space\": \"sphere\"}" `shouldBe` "scenes/torus-jam.json: a scene of sphere, but the name says torus"
    refused "sphere-jam.json" "{\"space\": \"sphere\", \"bodies\": [{\"shape\": \"circle\"}]}"
      `shouldBe` "scenes/sphere-jam.json: $.bodies[0].size: is missing"
    -- the longest space name counts: flat-torus-… is the flat torus's, not the torus's
    either id presetSpace (presetOf "flat-torus-wind.json" (BLC.pack "{\"space\": \"flat-torus\"}")) `shouldBe` "flat-torus"
    -- the title: the rest of the name, in words
    either id presetTitle (presetOf "sphere-big-rain.json" (BLC.pack "{\"space\": \"sphere\"}")) `shouldBe` "big rain"

  it "opens every preset with a view that sees most of its bodies (in the picture, not behind the surface), their centres spanning a quarter of the picture or more" $ do
    presets <- readPresets "scenes" >>= either fail pure
    views <- forM presets $ \p -> do
      scene <- either fail pure . parseScene =<< BLC.readFile ("scenes/" ++ presetName p ++ ".json")
      let cam = presetCamera p
          bodies = [(bsP b, bsSize b) | b <- sceneBodies scene]
          seen = filter (seenFrom (sceneSpace scene) cam) bodies
          -- the seen bodies' centres in the picture: x and y over the half-height
          forward = normalize (cameraTarget cam ^-^ cameraEye cam)
          right = normalize (cross forward (cameraUp cam))
          up = cross right forward
          halfHeight = tan (cameraFov cam * pi / 360)
          at (q, _) = let rel = q ^-^ cameraEye cam; d = dot rel forward in (dot rel right / (d * halfHeight), dot rel up / (d * halfHeight))
          xs = map (fst . at) seen
          ys = map (snd . at) seen
          -- the share of the picture's height (or width) the seen centres span
          spans = if length seen < 2 then 0 else max ((maximum ys - minimum ys) / 2) ((maximum xs - minimum xs) / (2 * framingAspect))
      pure (presetName p, fromIntegral (length seen) / fromIntegral (length bodies) :: Double, spans)
    mapM_ (\(name, share, spans) -> putStrLn ("    " ++ name ++ ": bodies seen " ++ show (round (100 * share) :: Int) ++ " %, their centres span "
                                              ++ show (round (100 * spans) :: Int) ++ " % of the picture")) views
    -- most; but the torus's chain is looped round the tube, and no view
    -- has more than about 150° of a loop facing it (13 of its 30 links)
    let most name = if name == "torus-chain" then 0.4 else 0.5
    [(name, share) | (name, share, _) <- views, share <= most name] `shouldBe` []
    [(name, spans) | (name, _, spans) <- views, spans < 0.25] `shouldBe` []

  it "every preset runs 3 s natively without a warning" $ do
    presets <- readPresets "scenes" >>= either fail pure
    warned <- forM presets $ \p -> (,) (presetName p) . snd . last <$> runPreset (presetName p) [300]
    filter ((/= 0) . snd) warned `shouldBe` []

  it "the joint presets hold together: after 10 s every anchor gap within 1 % of a link (2 × the body size); the sphere's chain hangs down" $ do
    let presets = ["sphere-chain", "torus-chain", "plane-pendulum-clock", "funnel-rope-bridge", "moebius-chain"]
    gaps <- forM presets $ \name -> do
      text <- BLC.readFile ("scenes/" ++ name ++ ".json")
      scene <- either fail pure (parseScene text)
      w <- loadScene 0 scene >>= either fail pure
      replicateM_ 1000 (stepNative w)
      anchors <- jointAnchorPoints w
      kinds <- mapM (\j -> jointField w j JKind) [0 .. length anchors - 1]
      sizes <- mapM (\j -> jointField w j JA >>= bodySize w . round) [0 .. length anchors - 1]
      let pinGaps = [ distance a b / (2 * s) | ((a, b), k, s) <- zip3 anchors kinds sizes, k /= fromIntegral (fromEnum Distance) ]
      endY <- if name == "sphere-chain" then (\b -> let V3 _ y _ = bsPos b in y) <$> readBody w 24 else pure (-1)
      pure (name, maximum (0 : pinGaps), endY)
    [ (name, g) | (name, g, _) <- gaps, g > 0.01 ] `shouldBe` []
    [ y | ("sphere-chain", _, y) <- gaps ] `shouldSatisfy` all (< 0)

  it "the rectangle's pyramid of 36 boxes stands: in 10 s no box moves a quarter of its half side (0.11)" $ do
    [(a, _), (b, _)] <- runPreset "rectangle-pyramid" [0, 1000]
    length a `shouldBe` 36
    mostMoved a b `shouldSatisfy` (< 0.25 * 0.11)

  it "the cube's tower stands on its static floor across the face: in 10 s no box moves a fifth of its half side (0.1)" $ do
    [(a, _), (b, _)] <- runPreset "cube-stack" [0, 1000]
    mostMoved a b `shouldSatisfy` (< 0.2 * 0.1)

  -- (a jammed pile of fourteen is chaotic: started with each body turned
  -- by up to 0.1 rad about the axis, 32 runs went as low as -2.80 and as
  -- high as 0.06 at these samples, most between -2.6 and -0.4; a body
  -- falling through the neck passes -3 within a second, and before the
  -- push-out was a speed of the bodies the pile threw bodies up to 1.6)
  it "the trumpet's bodies slide into its neck and jam there: from 10 s to 30 s every one stays between y = -3 and 0.3" $ do
    states <- runPreset "trumpet-jam" (1000 : replicate 4 500)
    let ys = [y | (bodies, _) <- states, b <- bodies, let V3 _ y _ = bsPos b]
    minimum ys `shouldSatisfy` (> -3)
    maximum ys `shouldSatisfy` (< 0.3)

  it "on the projective plane the moving body meets the other's antipodal image, never the body, and sets it moving" $ do
    states <- runPreset "projective-plane-image" (replicate 80 10)
    let pairs = [(bsPos a, bsPos b) | ([a, b], _) <- states]
        direct = minimum [distance pa pb | (pa, pb) <- pairs]
        image = minimum [norm (pa ^+^ pb) | (pa, pb) <- pairs]
        ([_, hit], _) = last states
    direct `shouldSatisfy` (> 1)
    image `shouldSatisfy` (< 0.4 + 0.01) -- within the sum of the radii: a contact through the image
    norm (bsVel hit) `shouldSatisfy` (> 0.1)

  -- (a rack whose balls touch passes the blow on, as Newton's cradle does:
  -- some balls end nearly at rest, 6 of the 15 here, with sleeping on or off)
  it "on the hyperbolic plane the cue ball breaks the rack: most balls set moving, the kinetic energy never growing (restitution 0.9, no friction)" $ do
    states <- runPreset "hyperbolic-plane-break" (replicate 60 10)
    let minkowskiSquare (V3 x y z) = x * x - y * y + z * z
        energy bodies = sum [ minkowskiSquare (bsVel b) | b <- bodies ]
        energies = [ energy bodies | (bodies, _) <- states ]
        initial = head energies -- the cue ball's speed squared (as the scene's velocity, projected): the rack is at rest
        (final, _) = last states
    maximum energies `shouldSatisfy` (<= initial * (1 + 1e-9))
    minimum energies `shouldSatisfy` (< 0.95 * initial) -- the collisions lose some
    length [ b | b <- init final, sqrt (minkowskiSquare (bsVel b)) > 0.05 ] `shouldSatisfy` (>= 8)

  it "on the Bolza surface the thrown bodies meet (through the octagon's sides too) and never gain energy, kept in the octagon" $ do
    text <- BLC.readFile "scenes/bolza-billiards.json"
    scene <- either fail pure (parseScene text)
    w <- loadScene 0 scene >>= either fail pure
    n <- bodyCount w
    let kinetic = do
          out <- MV.replicate measureSize 0
          runNative (measureWorld (nwSpace w) (nwArrays w) out)
          MV.read out (fromEnum KineticEnergy)
        beyond (V3 x y z) = maximum [ (cos a * x + sin a * z) * (1 + sqrt 2) - y * sqrt ((1 + sqrt 2) ^ (2 :: Int) - 1)
                                    | k <- [0 .. 7 :: Int], let a = fromIntegral k * pi / 4 ]
    states <- forM [1 .. 60 :: Int] $ \_ -> do
      replicateM_ 10 (stepNative w)
      (,) <$> kinetic <*> mapM (readBody w) [0 .. n - 1]
    let energies = map fst states
    head energies `shouldSatisfy` (> 0)
    maximum (zipWith (/) (drop 1 energies) energies) `shouldSatisfy` (<= 1 + 1e-9)
    last energies `shouldSatisfy` (< 0.98 * head energies) -- the collisions lose some
    maximum [ beyond (bsPos b) | (_, bodies) <- states, b <- bodies ] `shouldSatisfy` (<= 1e-9)

  it "the Klein bottle's bodies go round each at its speed (0.6: free motion on the surface, no contact)" $ do
    states <- runPreset "klein-bottle-orbit" (replicate 10 100)
    let speeds = [norm (bsVel b) | (bodies, _) <- states, b <- bodies]
    maximum (map (abs . subtract 0.6) speeds) `shouldSatisfy` (< 1e-3)
