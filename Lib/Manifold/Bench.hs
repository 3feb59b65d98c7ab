-- | The native benchmark (@manifold bench@): scenes of N equal circles and
-- squares covering about a third of a space's area, gravity on, run until
-- their piles have settled, saved, then each step timed from the saved state.
module Manifold.Bench
  ( BenchResult (..)
  , benchSpaces
  , benchSizes
  , benchScene
  , settleScene
  , defaultSettleSteps
  , runBench
  , ContactSettings (..)
  , sceneSettings
  ) where

import Control.Monad (forM, replicateM_)
import Data.List (sort, transpose)
import Data.Maybe (fromMaybe, listToMaybe)
import qualified Data.Map.Strict as M
import GHC.Clock (getMonotonicTime)
import Linear.Metric (normalize)
import Linear.Vector ((*^), (^+^), (^-^))
import Linear.V3 (V3 (..))
import System.Random (mkStdGen, randomR)

import Manifold.Bolza (sideExcess)
import Manifold.Engine
import Manifold.Metric
import Manifold.Space
import Manifold.Spaces
import Manifold.Surface
import Manifold.Scene

-- | What a timed run measured: steps' times in milliseconds.
data BenchResult = BenchResult
  { brSpace :: String
  , brBodies :: Int -- ^ bodies placed (fewer than asked when the space is full)
  , brSize :: Double -- ^ the bodies' circumradius
  , brContacts :: Double -- ^ contact rows, the mean over the timed steps (a settled pile's count moves by a tenth from step to step)
  , brMedianMs :: Double -- ^ a step's time, the median
  , brP10Ms :: Double -- ^ the 10th percentile
  , brP90Ms :: Double -- ^ the 90th percentile
  , brSteps :: Int -- ^ steps timed
  , brPhases :: [(String, Double)] -- ^ median ms of each phase of the step
  , brSubsteps :: Int -- ^ the solver's sub-steps while timed
  , brIterations :: Int -- ^ the solver's iterations (a sub-step) while timed
  , brSlop :: Double -- ^ the contacts' slop (a fraction of the body size) while timed
  } deriving Show

-- | Contact settings a run may put in place of a scene's, from the warm-up
-- on: to measure what firmer contacts cost and how piles then scale (a
-- pile needs a few hundred steps to settle under new settings, so such a
-- run wants a long warm-up).
data ContactSettings = ContactSettings
  { csSubsteps :: Maybe Int -- ^ solver sub-steps instead of the scene's
  , csIterations :: Maybe Int -- ^ solver iterations a sub-step instead of the scene's
  , csSlop :: Maybe Double -- ^ the slop (a fraction of the body size) instead of the engine's
  } deriving Show

-- | The engine's parameters for a scene under these settings.
sceneSettings :: ContactSettings -> Scene -> Params
sceneSettings cs scene =
  let p = sceneParams scene
  in p { pSubsteps = fromMaybe (pSubsteps p) (csSubsteps cs)
       , pIterations = fromMaybe (pIterations p) (csIterations cs)
       , pSlop = fromMaybe (pSlop p) (csSlop cs) }

-- | Plane, sphere, torus, trumpet, projective plane and a boundary space.
benchSpaces :: [Space]
benchSpaces = [plane, sphere, torus, trumpet, projectivePlane, rectangle]

-- | The body counts a full benchmark runs each space with.
benchSizes :: [Int]
benchSizes = [10, 100, 300, 1000, 3000]

-- | The area bodies are spread over, and a test for a point inside it.
region :: Space -> (Double, V3 Double -> Bool)
region sp = case spaceName sp of
  "plane" -> (5.6 * 5.6, \(V3 x _ z) -> abs x <= 2.8 && abs z <= 2.8)
  "sphere" -> (4 * pi, const True)
  "projective-plane" -> (2 * pi, const True) -- each body is at p and −p
  "torus" -> (4 * pi * pi * torusMajor * torusMinor, const True)
  "trumpet" -> (trumpetArea, \(V3 _ y _) -> y >= -1 && y <= 1)
  "rectangle" -> (6, const True)
  -- the hyperbolic disc of radius 1.5 about the vertex: area 2π (cosh 1.5 − 1)
  "hyperbolic-plane" -> (2 * pi * (cosh 1.5 - 1), \(V3 _ y _) -> y <= cosh 1.5)
  -- the octagon (Gauss–Bonnet: 4π for genus 2), sides excluded
  "bolza" -> (4 * pi, \p -> and [sideExcess k p < 0 | k <- [0 .. 7]])
  _ -> (4 * pi, const True)
  where
    -- ∫ 2π e^y √(1 + e^{2y}) dy over [−1, 1]
    trumpetArea = sum [2 * pi * exp y * sqrt (1 + exp (2 * y)) * h | k <- [0 .. 999 :: Int], let y = -1 + (fromIntegral k + 0.5) * h]
    h = 2 / 1000

-- | N bodies (circles and squares in turn) of the size that covers a third
-- of the region, at least two sizes (circumradii) apart, placed on the
-- surface by Poisson-disc sampling (Bridson's algorithm on the surface,
-- seeded): from a random placed body, up to 30 candidates at a random
-- distance of 1 to 1.6 times the spacing in a random tangent direction,
-- projected onto the surface; a body with no room around it leaves the
-- active list, and when the list runs dry a new random seed is thrown (up to
-- a thousand times), so every component of the region gets bodies. Should
-- the region still fill up, the scene holds fewer bodies than asked; the
-- result says how many it holds.
benchScene :: Space -> Int -> Scene
benchScene sp n =
  let (area, inside) = region sp
      size = sqrt (area / (3 * fromIntegral n * ((pi + 2) / 2)))
      b = spaceBounds sp
      f = spaceField sp
      metric = spaceMetric sp
      spacing = 2 * size
      usable p = not (any isNaN p) && abs (evalField sp p) < 1e-9 && inside p
                 && evalBoundary sp p > size && normIn metric (unitNormal metric f p) > 0.5
      -- (cells of the broad phase's coordinates: a chord is never shorter)
      key p = let V3 x y z = gridPoint metric p in (floor (x / spacing), floor (y / spacing), floor (z / spacing)) :: (Int, Int, Int)
      -- on a quotient space a body is also at its images
      images p = p : [applyIso g p | g <- quotientImages (spaceQuotient sp)]
      far grid p = and [ normIn metric (p' ^-^ q) >= spacing
                       | p' <- images p, let (i, j, k) = key p', di <- [-1, 0, 1], dj <- [-1, 0, 1], dk <- [-1, 0, 1]
                       , q <- M.findWithDefault [] (i + di, j + dj, k + dk) grid ]
      insert p = M.insertWith (++) (key p) [p]
      -- a random point of the surface: a random point of the bounds, projected
      seed g tries grid
        | tries <= (0 :: Int) = Nothing
        | otherwise =
            let (x, g1) = randomR (-b, b) g
                (y, g2) = randomR (-b, b) g1
                (z, g3) = randomR (-b, b) g2
                p = projectToSurface f (V3 x y z)
            in if usable p && far grid p then Just (p, g3) else seed g3 (tries - 1) grid
      around g p grid = go g (30 :: Int)
        where
          nrm = unitNormal metric f p
          V3 nx _ _ = nrm
          a = if abs nx < 0.9 then V3 1 0 0 else V3 0 1 0
          -- (in R³ "Linear"'s normalize, which the golden scenes were made with)
          unit = if metric == Euclidean then normalize else normalizeIn metric
          u = unit (tangentProjection metric nrm a)
          v = perpendicular metric nrm u
          go g0 0 = (Nothing, g0)
          go g0 k =
            let (theta, g1) = randomR (0, 2 * pi) g0
                (r, g2) = randomR (spacing, 1.6 * spacing) g1
                q = projectToSurface f (p ^+^ r *^ (cos theta *^ u ^+^ sin theta *^ v))
            in if usable q && far grid q then (Just q, g2) else go g2 (k - 1)
      place g grid active placed count
        | count >= n = reverse placed
        | null active = case seed g 1000 grid of
            Nothing -> reverse placed
            Just (p, g') -> place g' (insert p grid) [p] (p : placed) (count + 1)
        | otherwise =
            let (k, g1) = randomR (0, length active - 1) g
                p = active !! k
            in case around g1 p grid of
                 (Just q, g2) -> place g2 (insert q grid) (q : active) (q : placed) (count + 1)
                 (Nothing, g2) -> place g2 grid (take k active ++ drop (k + 1) active) placed count
      points = place (mkStdGen (7 + n)) M.empty [] [] 0
      shapeOf i = if even i then CircleShape else SquareShape
  in Scene sp defaultParams { pSleep = False } [BodySpec (shapeOf i) size 1 False p (V3 0 0 0) 0 0 Nothing [] Nothing 0 sceneMaterial | (i, p) <- zip [0 :: Int ..] points] [] Nothing

-- | How long the benchmark scenes run before they are timed. The bodies
-- start apart and fall; contacts per body rise for a few hundred steps
-- (after 100 steps the trumpet's scenes had 0.1 contact rows per body, at
-- 800 steps 2.1; the projective plane's 1000 bodies 2.1 and 2.9) and change
-- by about 3 % between 800 and 1200 steps.
defaultSettleSteps :: Int
defaultSettleSteps = 1000

-- | A scene after @settle@ steps of the native step, saved as a scene: what
-- 'runBench' times, and what the browser benchmark loads, so that both time
-- the same settled piles.
settleScene :: Int -> Scene -> IO Scene
settleScene 0 scene = pure scene -- exactly as placed
settleScene settle scene = do
  w <- loadScene 0 scene >>= either (benchError scene) pure
  replicateM_ settle (stepNative w)
  sceneOfWorld scene w >>= either (benchError scene) pure

benchError :: Scene -> String -> IO a
benchError scene e =
  ioError (userError ("bench scene " ++ spaceName (sceneSpace scene) ++ " " ++ show (length (sceneBodies scene)) ++ ": " ++ e))

-- | Run @warmup@ steps (the contacts' warm start and the caches), then time
-- @steps@ steps one by one, each phase of each step on its own (the step's
-- time is their sum). With @generic@, the world runs the generic step even
-- where its space has a compiled one (to see what the compiled step gains).
runBench :: (String -> IO ()) -> Bool -> ContactSettings -> Int -> Int -> Scene -> IO BenchResult
runBench progress generic settings warmup steps scene = do
  let sp = sceneSpace scene
      size = maybe 0 bsSize (listToMaybe (sceneBodies scene))
      params = sceneSettings settings scene
  w <- (if generic then genericStep else id) <$> (loadScene 0 scene >>= either (benchError scene) pure)
  setParams w params
  placed <- bodyCount w
  progress (spaceName sp ++ ": " ++ show placed ++ " bodies of size " ++ show (roundTo 4 size) ++ ", warming up")
  replicateM_ warmup (stepNative w)
  progress (spaceName sp ++ ": " ++ show placed ++ " bodies, timing " ++ show steps ++ " steps")
  let phases = stepPhasesNative w
  timed <- forM [1 .. steps] $ \_ -> do
    ts <- forM phases $ \(_, run) -> do
      t0 <- getMonotonicTime
      run
      t1 <- getMonotonicTime
      pure ((t1 - t0) * 1000)
    c <- contactCount w
    pure (ts, c)
  let phaseTimes = map fst timed
      contacts = fromIntegral (sum (map snd timed)) / fromIntegral steps
      times = map sum phaseTimes
      quantile :: [Double] -> Double -> Double
      quantile xs x = let sorted = sort xs in sorted !! min (length sorted - 1) (floor (x * fromIntegral (length sorted)))
      q = quantile times
      phaseMedians = zip (map fst phases) [quantile ts 0.5 | ts <- transpose phaseTimes]
  pure (BenchResult (spaceName sp) placed size contacts (q 0.5) (q 0.1) (q 0.9) steps phaseMedians (pSubsteps params) (pIterations params) (pSlop params))
  where roundTo k x = fromIntegral (round (x * 10 ^ (k :: Int)) :: Integer) / 10 ^ k :: Double
