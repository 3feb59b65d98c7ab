-- | The flat torus and the flat Klein bottle (paper §4.3–4.4): the plane
-- y = 0 modulo a square lattice of period 2 (with a flip for the Klein
-- bottle). Oracles: free motion is a straight line at constant speed that
-- closes after whole periods; contacts across an edge conserve momentum;
-- a flip edge mirrors z and reverses the angular velocity; and the native
-- engine agrees with the emitted JavaScript on seam-crossing scenes.
module FlatSpec (spec) where

import Control.Monad (forM, forM_)
import Linear.Metric (norm)
import Linear.V3 (V3 (..))
import Test.Hspec

import Manifold
import Manifold.Chart
import Manifold.Engine
import PhysicsUtil

period :: Double
period = flatPeriod

-- | The shortest difference of two points of the flat torus, in the
-- square's coordinates (each coordinate in [−L/2, L/2]).
torusDelta :: V3 Double -> V3 Double -> V3 Double
torusDelta (V3 ax ay az) (V3 bx by bz) = V3 (wrap (ax - bx)) (ay - by) (wrap (az - bz))
  where wrap d = d - period * fromIntegral (round (d / period) :: Int)

noGravity' :: Params
noGravity' = defaultParams { pGravity = False }

-- | Circles crossing edges and meeting across them, spinning: the
-- differential scene (the first two meet across the x edge, the third
-- crosses a corner, the fourth meets its own path across the z edge).
seamScene :: [BodyInit]
seamScene =
  [ dyn circle 0.2 (V3 0.72 0 0.1) (V3 0.4 0 0.05) 0 2
  , dyn square 0.2 (V3 (-0.75) 0 0.05) (V3 (-0.3) 0 0) 0.3 (-1)
  , dyn (regularPolygon 5) 0.15 (V3 0.8 0 0.8) (V3 0.5 0 0.6) 0 1.5
  , dyn circle 0.15 (V3 (-0.2) 0 (-0.85)) (V3 0.1 0 (-0.5)) 0 0 ]

spec :: Spec
spec = do
  describe "Flat chart (the torus's angle coordinates)" $
    it "maps the square onto the embedded torus and back (1e-12), and carries velocities by its derivative (finite differences, 1e-7)" $ do
      let pts = [V3 x 0 z | x <- [-0.95, -0.5 .. 0.95], z <- [-0.95, -0.4 .. 0.95]]
          roundTrip = maximum [norm (torusToSquare (squareToTorus p) - p) | p <- pts]
          onSurface = maximum [abs (evalField torus (squareToTorus p)) | p <- pts]
          v = V3 0.3 0 (-0.7)
          h = 1e-6
          fd p = fmap (/ (2 * h)) (squareToTorus (p + fmap (* h) v) - squareToTorus (p - fmap (* h) v))
          velocityErr = maximum [norm (fd p - squareVelocityOnTorus p v) | p <- pts]
      labelled "chart: max round-trip error, max |f| of the mapped points, max velocity error vs finite differences"
        (fmt roundTrip ++ ", " ++ fmt onSurface ++ ", " ++ fmt velocityErr)
      roundTrip `shouldSatisfy` (< 1e-12)
      onSurface `shouldSatisfy` (< 1e-12)
      velocityErr `shouldSatisfy` (< 1e-7)

  describe "Flat side by side (the comparison scene's first two launches, alone, 12 s)" $
    it "on the flat torus both launches go straight; on the embedded torus the outer-equator one weaves about its equator and the inner-equator one leaves its equator" $ do
      let run sp (p, v, size) = do
            w <- mkWorld sp noGravity' [dyn circle size p v 0 0]
            forM [1 .. 1200 :: Int] $ \_ -> stepNative w >> (bsPos <$> readBody w 0)
          zOf (V3 _ _ z) = z
          chartZ = zOf . torusToSquare
          -- distance in the square's z from the equator a launch started on
          fromEquator z0 z = abs (z - z0 - 2 * fromIntegral (round ((z - z0) / 2) :: Int))
          [outer, inner] = take 2 comparisonLaunches
      flatOuter <- map zOf <$> run flatTorus (launchOnSquare outer)
      flatInner <- map zOf <$> run flatTorus (launchOnSquare inner)
      embOuter <- map chartZ <$> run torus (launchOnTorus outer)
      embInner <- map chartZ <$> run torus (launchOnTorus inner)
      let maxFrom z0 = maximum . map (fromEquator z0)
          V3 _ _ vz = launchVelocity outer
      labelled "after 12 s: max |z - z0| in the square, flat outer / embedded outer / flat inner / embedded inner (flat: vz t = 0.24)"
        (unwords (map fmt [maxFrom 0 flatOuter, maxFrom 0 embOuter, maxFrom (-1) flatInner, maxFrom (-1) embInner]))
      -- flat: straight lines, z = z0 + vz t
      abs (maxFrom 0 flatOuter - 12 * vz) `shouldSatisfy` (< 1e-9)
      abs (maxFrom (-1) flatInner - 12 * vz) `shouldSatisfy` (< 1e-9)
      -- embedded: positive curvature outside keeps the launch near its equator,
      -- negative curvature inside drives it away
      maxFrom 0 embOuter `shouldSatisfy` (< 0.5 * 12 * vz)
      maxFrom (-1) embInner `shouldSatisfy` (> 2 * 12 * vz)

  describe "Flat free motion" $ do
    it "moves a free body on the flat torus in a straight line at exactly constant speed, back at its start after whole periods (1e-9)" $ do
      let p0 = V3 0.3 0 (-0.2)
          v0 = V3 1 0 0.5 -- 400 steps of 0.01: 2 periods along x, 1 along z
          om = 1.3
      w <- mkWorld flatTorus noGravity' [dyn square 0.2 p0 v0 0 om]
      trail <- forM [1 .. 400 :: Int] $ \k -> do
        stepNative w
        b <- readBody w 0
        pure (k, b)
      let line k = p0 + fmap (* (0.01 * fromIntegral k)) v0
          offLine = maximum [norm (torusDelta (bsPos b) (line k)) | (k, b) <- trail]
          speedDrift = maximum [abs (speed b - norm v0) | (_, b) <- trail]
          inSquare = and [abs x <= 1 && abs z <= 1 | (_, b) <- trail, let V3 x _ z = bsPos b]
          end = snd (last trail)
      labelled "flat torus: max distance from the straight line over 400 steps, |end - start|, max |speed - speed0|, omega at the end"
        (fmt offLine ++ ", " ++ fmt (norm (bsPos end - p0)) ++ ", " ++ fmt speedDrift ++ ", " ++ show (bsOmega end))
      offLine `shouldSatisfy` (< 1e-9)
      norm (bsPos end - p0) `shouldSatisfy` (< 1e-9)
      -- the integrator rescales the carried velocity to its old length: a
      -- few ulps of rounding, nothing else
      speedDrift `shouldSatisfy` (< 1e-14)
      inSquare `shouldBe` True
      bsOmega end `shouldBe` om
      abs (bsAngle end - 4 * om) `shouldSatisfy` (< 1e-9)

    it "mirrors a body through the flat Klein bottle's flip edge: z, angle and angular velocity change sign; back after two periods" $ do
      let p0 = V3 0.1 0 0.3
          v0 = V3 1 0 0
          om = 1
      w <- mkWorld flatKlein noGravity' [dyn square 0.2 p0 v0 0 om]
      steps w 200
      half <- readBody w 0
      steps w 200
      end <- readBody w 0
      labelled "flat Klein bottle: after one period along x (p, omega, angle); after two (|p - p0|, omega)"
        (show (bsPos half) ++ ", " ++ show (bsOmega half) ++ ", " ++ fmt (bsAngle half) ++ "; "
         ++ fmt (norm (bsPos end - p0)) ++ ", " ++ show (bsOmega end))
      norm (bsPos half - V3 0.1 0 (-0.3)) `shouldSatisfy` (< 1e-9)
      bsOmega half `shouldBe` negate om
      bsVel half `shouldBe` v0
      norm (bsPos end - p0) `shouldSatisfy` (< 1e-9)
      bsOmega end `shouldBe` om
      -- the angle is carried in the mirrored frame: +0.9 before the first
      -- crossing, then it runs backwards from −0.9 to −2
      abs (bsAngle half - (-2.0)) `shouldSatisfy` (< 1e-9)

  describe "Flat seam contacts" $ do
    let meet sp a b = do
          w <- mkWorld sp noGravity' { pFriction = 0 } [a, b]
          ms <- mapM (bodyMass w) [0, 1]
          let mom = do
                bs <- bodyStates w
                pure (momentum (zip ms bs))
          m0 <- mom
          rs <- forM [1 .. 300 :: Int] $ \_ -> do
            stepNative w
            n <- contactCount w
            cs <- contacts w
            [x, y] <- bodyStates w
            pure ((n, maxDepthOf cs), x, y)
          m1 <- mom
          pure (m0, m1, rs)
    it "collides two circles touching across the flat torus's x edge: momentum conserved, overlap under 1 %" $ do
      let ra = 0.2
          rb = 0.15
      (m0, m1, rs) <- meet flatTorus (dyn circle ra (V3 0.6 0 0.1) (V3 0.3 0 0.05) 0 0)
                                     (dyn circle rb (V3 (-0.7) 0 0.02) (V3 0 0 0) 0 0)
      let overlap = maximum [(ra + rb - norm (torusDelta (bsPos x) (bsPos y))) / (ra + rb) | (_, x, y) <- rs]
          touched = length [() | ((n, _), _, _) <- rs, n > 0]
          depth = maximum [d | ((_, d), _, _) <- rs] / (ra + rb)
          (_, _, bEnd) = last rs
      labelled "flat torus seam: steps with contacts, worst polygon overlap depth / (ra + rb), worst circle overlap / (ra + rb), |momentum change|, momentum, B's velocity at the end"
        (show touched ++ ", " ++ fmt depth ++ ", " ++ fmt overlap ++ ", " ++ fmt (norm (m1 - m0)) ++ ", " ++ show m0 ++ ", " ++ show (bsVel bEnd))
      touched `shouldSatisfy` (> 0)
      depth `shouldSatisfy` (< 0.01)
      overlap `shouldSatisfy` (< 0.02)
      norm (m1 - m0) `shouldSatisfy` (< 1e-9 * norm m0)
      -- B was hit from across the edge: it moves on in +x
      let V3 bvx _ _ = bsVel bEnd in bvx `shouldSatisfy` (> 0.05)

    it "collides two circles touching across the flat Klein bottle's flip edge: x momentum conserved, overlap under 1 %" $ do
      let ra = 0.2
          rb = 0.15
      -- A crosses x = 1 at z = 0.3 and comes out at x = −1, z = −0.3, where B is
      (m0, m1, rs) <- meet flatKlein (dyn circle ra (V3 0.6 0 0.3) (V3 0.3 0 0) 0 0)
                                     (dyn circle rb (V3 (-0.7) 0 (-0.3)) (V3 0 0 0) 0 0)
      let kleinDistance x y = minimum [norm (torusDelta (bsPos x) q) | q <- [bsPos y, mirrorZ (bsPos y)]]
          mirrorZ (V3 a b c) = V3 a b (negate c)
          overlap = maximum [(ra + rb - kleinDistance x y) / (ra + rb) | (_, x, y) <- rs]
          touched = length [() | ((n, _), _, _) <- rs, n > 0]
          depth = maximum [d | ((_, d), _, _) <- rs] / (ra + rb)
          V3 px0 _ _ = m0
          V3 px1 _ _ = m1
          (_, aEnd, bEnd) = last rs
      labelled "flat Klein seam: steps with contacts, worst polygon overlap depth / (ra + rb), worst circle overlap / (ra + rb), x momentum before/after, velocities at the end"
        (show touched ++ ", " ++ fmt depth ++ ", " ++ fmt overlap ++ ", " ++ show px0 ++ " / " ++ show px1 ++ ", " ++ show (bsVel aEnd) ++ " " ++ show (bsVel bEnd))
      touched `shouldSatisfy` (> 0)
      depth `shouldSatisfy` (< 0.01)
      overlap `shouldSatisfy` (< 0.02)
      abs (px1 - px0) `shouldSatisfy` (< 1e-9 * abs px0)
      let V3 bvx _ _ = bsVel bEnd in bvx `shouldSatisfy` (> 0.05)

    it "finds a body's contact with its own image when it is larger than half the period; the pushes cancel (the spin is the 24-gon's, as for two such circles on the plane)" $ do
      -- a circle of radius 1.05 on the period-2 torus overlaps its translates by ±2
      w <- mkWorld flatTorus noGravity' [dyn circle 1.05 (V3 0.2 0 (-0.1)) 0 0 0]
      steps w 50
      cs <- contacts w
      [b] <- bodyStates w
      labelled "own image: contacts (all with itself), speed after 50 steps, omega"
        (show (length cs) ++ " " ++ show (all (\c -> cA c == 0 && cB c == 0) cs) ++ ", " ++ fmt (speed b) ++ ", " ++ fmt (bsOmega b))
      length cs `shouldSatisfy` (> 0)
      all (\c -> cA c == 0 && cB c == 0) cs `shouldBe` True
      speed b `shouldSatisfy` (< 1e-9)
      -- the inscribed 24-gons' contacts are not exactly radial: two separate
      -- circles of this size 2 apart on the plane spin up to 0.023 in 50 steps
      abs (bsOmega b) `shouldSatisfy` (< 0.05)

  describe "Flat native vs emitted JavaScript (seam-crossing scenes, 200 steps, 1e-9)" $ do
    forM_ [flatTorus, flatKlein] $ \sp ->
      it (spaceName sp) $ do
        w <- mkWorld sp defaultParams seamScene
        steps w 20
        d <- differential w [Steps 200]
        labelled ("differential " ++ spaceName sp ++ ": max |pos|, |vel|, |verts|, |scalars| difference; contacts native/js")
          (fmt (dPos d) ++ ", " ++ fmt (dVel d) ++ ", " ++ fmt (dVerts d) ++ ", " ++ fmt (dScalars d) ++ "; " ++ show (dContacts d))
        dPos d `shouldSatisfy` (< 1e-9)
        dScalars d `shouldSatisfy` (< 1e-9)
        uncurry shouldBe (dContacts d)
    it "flat-klein, a body dragged by the mouse across the flip edge" $ do
      w <- mkWorld flatKlein defaultParams [dyn square 0.2 (V3 0.7 0 0.3) 0 0 0]
      -- the target lies beyond the edge; the joint pulls towards its image
      -- nearest the body, so the body crosses the edge
      d <- differential w [Grab 0 1 (V3 0.75 0 0.3) 5 0.7 100, Drag (V3 1.3 0 0.3), Steps 150, Release, Steps 50]
      [b] <- bodyStates w
      labelled "mouse across the flip edge: body at the end; max |pos| difference native/js" (show (bsPos b) ++ "; " ++ fmt (dPos d))
      let V3 bx _ bz = bsPos b
      -- it followed the target's image (−0.7, −0.3) through the edge
      bx `shouldSatisfy` (< -0.5)
      bz `shouldSatisfy` (< -0.2)
      dPos d `shouldSatisfy` (< 1e-9)
