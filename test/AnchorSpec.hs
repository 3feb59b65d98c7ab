-- | Points kept in a body's polar coordinates ("Manifold.Anchor"): the
-- coordinates 'polarOf' finds walk back to the point they were found for,
-- on curved, flat and hyperbolic spaces, and on the unit sphere their
-- distance is the great circle's.
module AnchorSpec (spec) where

import Control.Monad (forM, forM_)
import Linear.V3 (V3 (..), cross)
import Linear.Vector ((*^), (^+^), (^-^))
import Test.Hspec

import Manifold
import Manifold.Anchor (AnchorMotion (..), anchorMotion, anchorPoint, polarOf)
import Manifold.Engine (NativeWorld (..), defaultParams)
import Manifold.Stage.Imp (runNative)
import Manifold.World (BodyFrame (..), bodyFrame)
import PhysicsUtil

-- | Points at geodesic distances @ds@ from a body placed where the space's
-- default scene puts its first body (turned by 0.7), in five directions;
-- each with the polar coordinates 'polarOf' finds for it and the miss of
-- their walk ('anchorPoint'), under the space's metric.
roundTrips :: Space -> [Double] -> IO [(V3 Double, V3 Double, Double, Double, Double)]
roundTrips sp ds = do
  let start = placeAt (head (spaceScene sp))
      metric = spaceMetric sp
  w <- mkWorld sp defaultParams [dyn circle 0.05 start (V3 0 0 0) 0.7 0]
  f <- runNative (bodyFrame metric (nwArrays w) 0)
  fmap concat . forM ds $ \d -> forM [0 .. 4 :: Int] $ \k -> do
    let a = 0.3 + 2 * pi * fromIntegral k / 5
        dir = cos a *^ bfU f ^+^ sin a *^ bfW f
        q = fst (expMap metric (spaceField sp) 512 (bfCentre f) dir d)
    (r, theta) <- runNative (polarOf sp f q)
    back <- runNative (anchorPoint sp f r theta)
    pure (bfCentre f, q, r, theta, normIn metric (back ^-^ q))

spec :: Spec
spec = describe "Manifold.Anchor" $ do
  it "finds polar coordinates whose geodesic walk ends at the point (to 1e-9), on curved, flat and hyperbolic spaces" $
    forM_ [(sphere, [0.02, 0.1, 0.3, 0.6, 1.0]), (torus, [0.02, 0.1, 0.3]), (funnel, [0.02, 0.1, 0.3])
          , (hyperbolicPlane, [0.02, 0.1, 0.3, 0.6, 1.0]), (plane, [0.02, 0.3, 1.0]), (flatTorus, [0.02, 0.3])] $ \(sp, ds) -> do
      trips <- roundTrips sp ds
      let worst = maximum [miss | (_, _, _, _, miss) <- trips]
      (spaceName sp, worst) `shouldSatisfy` ((< 1e-9) . snd)

  it "on the unit sphere, gives the great circle's distance to the walk's accuracy (r³/50), not the chord's tangent part (short by r³/6)" $ do
    trips <- roundTrips sphere [0.1, 0.3, 0.6, 1.0]
    forM_ trips $ \(c, q, r, _, _) -> do
      let V3 cx cy cz = c
          V3 qx qy qz = q
          arc = acos (cx * qx + cy * qy + cz * qz)
      -- (four steps of RATTLE shorten the walk by about r³/96: the walk
      -- to 0.6 ends 2.2e-3 long; the chord's tangent part, sin r, is
      -- 0.035 short there)
      (arc, r) `shouldSatisfy` (\(x, y) -> abs (x - y) < x * x * x / 50)


  it "moves an anchor with its body as the unit sphere's rotations do (to 1e-6): a slide along u turns about c × u, a turn about c" $ do
    let sp = sphere
        start = V3 0.3 0.8 0.5
    w <- mkWorld sp defaultParams [dyn circle 0.05 start (V3 0 0 0) 0.7 0]
    f <- runNative (bodyFrame Euclidean (nwArrays w) 0)
    forM_ [(0.02, 0.3), (0.3, 2), (1.0, -1)] $ \(r, theta) -> do
      m <- runNative (anchorMotion sp f r theta)
      let c = bfCentre f
          p = amPoint m
          off expected got = normIn Euclidean (expected ^-^ got)
      (r, off ((c `cross` bfU f) `cross` p) (amSlideU m)) `shouldSatisfy` ((< 1e-6) . snd)
      (r, off ((c `cross` bfW f) `cross` p) (amSlideW m)) `shouldSatisfy` ((< 1e-6) . snd)
      (r, off (c `cross` p) (amTurn m)) `shouldSatisfy` ((< 1e-6) . snd)
