-- | What the page plots and inspects ("Manifold.Measures"): a body's
-- kinetic energy is ½ m v² + ½ I ω² with the disc's analytic mass and
-- moment; the centres' angular momentum about a surface of revolution's
-- axis stays as it was for free bodies (Clairaut), with gravity along the
-- axis too, and does not where gravity pulls across it; a body's contact
-- rows are counted; and the page's generated measures give the native
-- ones bit for bit.
module MeasuresSpec (spec) where

import Control.Monad (forM, forM_, replicateM, replicateM_, (>=>))
import qualified Data.Vector.Unboxed as V
import qualified Data.Vector.Unboxed.Mutable as MV
import Linear.V3 (V3 (..))
import Test.Hspec

import Manifold
import Manifold.Engine
import Manifold.Measures
import Manifold.Stage.Imp (runNative)
import Manifold.Stage.Kernels (spaceIndexScript)
import TestUtil (scriptOf)
import Manifold.World (layout)
import NodeJS

-- | A world of these bodies, no gravity unless asked.
worldOf :: Space -> Bool -> [BodyInit] -> IO NativeWorld
worldOf sp gravityOn bodies = do
  w <- newWorld sp (layout (length bodies))
  setParams w defaultParams { pGravity = gravityOn }
  forM_ bodies (addBody w >=> either fail (const (pure ())))
  pure w

circleAt :: Double -> V3 Double -> V3 Double -> Double -> BodyInit
circleAt r p v omega = BodyInit circle r 1 False p v 0 omega sceneMaterial

-- | The world's measures, natively.
measuresOf :: NativeWorld -> IO [Double]
measuresOf w = do
  out <- MV.replicate measureSize 0
  runNative (measureWorld (nwSpace w) (nwArrays w) out)
  V.toList <$> V.freeze out

-- | Body i's measures, natively.
bodyMeasures :: NativeWorld -> Int -> IO [Double]
bodyMeasures w i = do
  out <- MV.replicate measureSize 0
  runNative (measureBody (nwSpace w) (nwArrays w) out i)
  V.toList <$> V.freeze out

at :: MeasureSlot -> [Double] -> Double
at s xs = xs !! fromEnum s

-- | The axial momentum after each of some runs of steps.
axialRun :: NativeWorld -> Int -> Int -> IO [Double]
axialRun w runs k = replicateM runs (replicateM_ k (stepNative w) >> at AxialMomentum <$> measuresOf w)

spec :: Spec
spec = describe "Manifold.Measures" $ do
  it "a spinning disc's kinetic energy is ½ m v² + ½ I ω², m = π r² and I = m r² / 2 (the disc's analytic mass)" $ do
    let r = 0.2
        speed = 0.7
        omega = 3
    w <- worldOf plane False [circleAt r (V3 0 0 0) (V3 speed 0 0) omega]
    measured <- at KineticEnergy <$> measuresOf w
    let m = pi * r * r
        expected = 0.5 * m * speed * speed + 0.5 * (m * r * r / 2) * omega * omega
    abs (measured / expected - 1) `shouldSatisfy` (< 1e-9)
    body <- bodyMeasures w 0
    (at BodySpeed body, at BodyEnergy body, at BodyContacts body) `shouldBe` (speed, measured, 0)

  it "a static body has no energy and no momentum" $ do
    w <- worldOf sphere True [(circleAt 0.2 (V3 0 (-1) 0) (V3 0 0 0) 0) { biStatic = True }]
    ms <- measuresOf w
    (at KineticEnergy ms, at AxialMomentum ms) `shouldBe` (0, 0)

  it "free bodies on the torus keep their centres' angular momentum about its axis (Clairaut), over 20 s" $ do
    w <- worldOf torus False
      [ circleAt 0.15 (V3 1.3 0 0) (V3 0 0.4 0.5) 1
      , circleAt 0.15 (V3 (-0.3) 0.5 0) (V3 0 0 (-0.6)) 0
      , circleAt 0.15 (V3 0 0 (-1.3)) (V3 0.3 0.3 0) (-2) ]
    l0 <- at AxialMomentum <$> measuresOf w
    ls <- axialRun w 20 100
    abs l0 `shouldSatisfy` (> 0.05)
    maximum [abs (l - l0) | l <- ls] / abs l0 `shouldSatisfy` (< 1e-6) -- 1.3e-7 when written

  it "on the sphere gravity along the axis turns nothing about it: a falling, swinging body keeps its momentum" $ do
    w <- worldOf sphere True [circleAt 0.15 (V3 0.6 0.8 0) (V3 0 0 0.9) 0]
    l0 <- at AxialMomentum <$> measuresOf w
    ls <- axialRun w 10 100
    maximum [abs (l - l0) | l <- ls] / abs l0 `shouldSatisfy` (< 1e-10) -- 1.4e-12 when written

  it "the oracle can fail: the torus's gravity across its axis changes the momentum" $ do
    w <- worldOf torus True [circleAt 0.15 (V3 1.3 0 0) (V3 0 0 0.5) 0]
    l0 <- at AxialMomentum <$> measuresOf w
    ls <- axialRun w 5 100
    maximum [abs (l - l0) | l <- ls] / abs l0 `shouldSatisfy` (> 1e-2)

  it "a space without an axis has no axial momentum" $ do
    w <- worldOf cube False [circleAt 0.15 (V3 0 0.9 0) (V3 0.5 0 0.2) 0]
    at AxialMomentum <$> measuresOf w `shouldReturn` 0

  it "counts a body's contact rows: a box resting on a static floor has some, a body alone none" $ do
    w <- worldOf plane True
      [ BodyInit square 0.3 1 True (V3 0 0 (-0.5)) (V3 0 0 0) 0 0 sceneMaterial
      , BodyInit square 0.15 1 False (V3 0 0 (-0.5 + 0.3 / sqrt 2 + 0.15 / sqrt 2 + 0.005)) (V3 0 0 0) 0 0 sceneMaterial
      , circleAt 0.15 (V3 2 0 2) (V3 0 0 0) 0 ]
    -- (awake: a sleeping box has no contact rows)
    setParams w defaultParams { pSleep = False }
    replicateM_ 60 (stepNative w)
    rows <- contactCount w
    counts <- forM [0, 1, 2] (fmap (at BodyContacts) . bodyMeasures w)
    rows `shouldSatisfy` (> 0)
    -- each row is between the two boxes: both are in every one, the lone body in none
    counts `shouldBe` [fromIntegral rows, fromIntegral rows, 0]

  it "the page's generated measures give the native ones bit for bit (torus and sphere piles after 50 steps)" $ do
    let scene = [ circleAt 0.18 (V3 (1.3 * cos t) 0 (1.3 * sin t)) (V3 (0.3 * sin t) 0.2 (-0.3 * cos t)) 0.5
                   | k <- [0 .. 5 :: Int], let t = fromIntegral k ]
        spaces = [torus, sphere]
    native <- forM spaces $ \sp -> do
      w <- worldOf sp True scene
      replicateM_ 50 (stepNative w)
      (++) <$> measuresOf w <*> (concat <$> mapM (bodyMeasures w) [0 .. 5])
    world <- readFile "web/js/world.js"
    let call sp = "(() => { const w = new ManifoldWeb.world.World(" ++ show (spaceName sp) ++ ", Manifold.spaces[" ++ show (spaceName sp) ++ "]);"
          ++ ""
          ++ concat [ " w.add({ shape: 'circle', size: " ++ jsDouble (biSize b) ++ ", p: [" ++ list3 (biPos b) ++ "], v: [" ++ list3 (biVel b) ++ "], omega: " ++ jsDouble (biOmega b) ++ " });" | b <- scene ]
          ++ " w.step(50); const m = w.measures(), E = w.engine;"
          ++ " const out = new Float64Array(E.measures.size); E.measure.apply(null, w.arrays.concat([out]));"
          ++ " const all = Array.from(out); for (let i = 0; i < 6; i++) { out.fill(0); E.measureBody.apply(null, w.arrays.concat([out, i])); all.push(...out); }"
          ++ " return m.kineticEnergy === all[E.measures.slots.kineticEnergy] ? all : null; })()"
        list3 (V3 x y z) = jsDouble x ++ ", " ++ jsDouble y ++ ", " ++ jsDouble z
        script = spaceIndexScript catalogue ++ concatMap scriptOf spaces ++ world ++ "\n__emit([" ++ concatMap ((++ ",") . call) spaces ++ "]);\n"
    js <- runNodeJSON script :: IO [[Bits]]
    map (map doubleBits) native `shouldBe` map (map (doubleBits . unBits)) js
