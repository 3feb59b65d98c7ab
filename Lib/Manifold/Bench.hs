-- | The native benchmark (@manifold bench@): scenes of N equal circles and
-- squares covering about a third of a space's area, gravity on, settled for a
-- while, then each step timed.
module Manifold.Bench
  ( BenchCase (..)
  , BenchResult (..)
  , benchSpaces
  , benchSizes
  , benchScene
  , runBench
  ) where

import Control.Monad (forM, replicateM_)
import Data.List (sort, transpose)
import Data.Maybe (listToMaybe)
import qualified Data.Map.Strict as M
import GHC.Clock (getMonotonicTime)
import Linear.Metric (distance, norm)
import Linear.V3 (V3 (..))
import System.Random (mkStdGen, randomRs)

import Manifold.Engine
import Manifold.Space
import Manifold.Spaces
import Manifold.Surface
import Manifold.Scene

data BenchCase = BenchCase
  { bcSpace :: Space
  , bcBodies :: Int
  }

data BenchResult = BenchResult
  { brSpace :: String
  , brBodies :: Int -- ^ bodies placed (fewer than asked when the space is full)
  , brSize :: Double
  , brContacts :: Int -- ^ contacts at the end
  , brMedianMs :: Double
  , brP10Ms :: Double
  , brP90Ms :: Double
  , brSteps :: Int
  , brPhases :: [(String, Double)] -- ^ median ms of each phase of the step
  } deriving Show

-- | Plane, sphere, torus, trumpet, projective plane and a boundary space.
benchSpaces :: [Space]
benchSpaces = [plane, sphere, torus, trumpet, projectivePlane, rectangle]

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
  _ -> (4 * pi, const True)
  where
    -- ∫ 2π e^y √(1 + e^{2y}) dy over [−1, 1]
    trumpetArea = sum [2 * pi * exp y * sqrt (1 + exp (2 * y)) * h | k <- [0 .. 999 :: Int], let y = -1 + (fromIntegral k + 0.5) * h]
    h = 2 / 1000

-- | N bodies (circles and squares in turn) of the size that covers a third
-- of the region, placed by dart throwing on the surface (seeded). Near that
-- density random throwing jams, so fewer bodies may be placed than asked;
-- the result says how many were.
benchScene :: Space -> Int -> Scene
benchScene sp n =
  let (area, inside) = region sp
      size = sqrt (area / (3 * fromIntegral n * ((pi + 2) / 2)))
      b = spaceBounds sp
      f = spaceField sp
      coords = randomRs (-b, b) (mkStdGen (7 + n))
      candidates = [projectToSurface f (V3 x y z) | (x, y, z) <- triples coords]
      usable p = not (any isNaN p) && abs (evalField sp p) < 1e-9 && inside p
                 && evalBoundary sp p > size && norm (unitNormal f p) > 0.5
      cell = 2 * size
      key (V3 x y z) = (floor (x / cell), floor (y / cell), floor (z / cell)) :: (Int, Int, Int)
      far grid p = and [ distance p q >= 2 * size && distance (negate p) q >= 2 * size
                       | (i, j, k) <- [key p, key (negate p)], di <- [-1, 0, 1], dj <- [-1, 0, 1], dk <- [-1, 0, 1]
                       , q <- M.findWithDefault [] (i + di, j + dj, k + dk) grid ]
      place _ acc 0 _ = reverse acc
      place _ acc _ [] = reverse acc
      place grid acc k (p : ps)
        | usable p && far grid p = place (M.insertWith (++) (key p) [p] grid) (p : acc) (k - 1) ps
        | otherwise = place grid acc k ps
      points = place M.empty [] n (take (2000 * n + 20000) candidates)
      shapeOf i = if even i then CircleShape else SquareShape
  in Scene sp 0.01 True 8 0.4 0 [BodySpec (shapeOf i) size 1 False p (V3 0 0 0) 0 0 | (i, p) <- zip [0 :: Int ..] points]
  where
    triples (x : y : z : rest) = (x, y, z) : triples rest
    triples _ = []

-- | Settle for @warmup@ steps, then time @steps@ steps one by one, each
-- phase of each step on its own (the step's time is their sum).
runBench :: (String -> IO ()) -> Int -> Int -> BenchCase -> IO BenchResult
runBench progress warmup steps (BenchCase sp n) = do
  let scene = benchScene sp n
      size = maybe 0 bsSize (listToMaybe (sceneBodies scene))
  w <- loadScene 0 scene >>= either (\e -> ioError (userError ("bench scene " ++ spaceName sp ++ " " ++ show n ++ ": " ++ e))) pure
  placed <- bodyCount w
  progress (spaceName sp ++ ": " ++ show placed ++ " bodies of size " ++ show (roundTo 4 size) ++ ", settling")
  replicateM_ warmup (stepNative w)
  progress (spaceName sp ++ ": " ++ show placed ++ " bodies, timing " ++ show steps ++ " steps")
  let phases = stepPhasesNative w
  phaseTimes <- forM [1 .. steps] $ \_ -> forM phases $ \(_, run) -> do
    t0 <- getMonotonicTime
    run
    t1 <- getMonotonicTime
    pure ((t1 - t0) * 1000)
  contacts <- contactCount w
  let times = map sum phaseTimes
      quantile :: [Double] -> Double -> Double
      quantile xs x = let sorted = sort xs in sorted !! min (length sorted - 1) (floor (x * fromIntegral (length sorted)))
      q = quantile times
      phaseMedians = zip (map fst phases) [quantile ts 0.5 | ts <- transpose phaseTimes]
  pure (BenchResult (spaceName sp) placed size contacts (q 0.5) (q 0.1) (q 0.9) steps phaseMedians)
  where roundTo k x = fromIntegral (round (x * 10 ^ (k :: Int)) :: Integer) / 10 ^ k :: Double
