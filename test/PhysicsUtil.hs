-- | Helpers for the physics scenario tests: building worlds from bodies,
-- reading contacts, outlines, masses and momenta out of the native arrays,
-- and running a script of actions (steps, mouse grab, drag, release) both
-- natively and in the emitted JavaScript under node, to compare the two.
module PhysicsUtil
  ( -- * Worlds
    dyn
  , still
  , mkWorld
  , mkWorldCap
  , steps
  , stepsWhile
  , bodyStates
    -- * Reading the arrays
  , Contact (..)
  , contacts
  , maxDepthOf
  , slot
  , bodySize
  , bodyMass
  , bodyInertia
  , outline
  , allFinite
  , meta
    -- * Mechanics
  , speed
  , kineticEnergy
  , momentum
  , angularMomentumY
  , angleBetween
    -- * Native versus emitted JavaScript
  , Action (..)
  , act
  , Snapshot
  , snapshot
  , runActionsInNode
  , Differential (..)
  , differential
    -- * Misc
  , labelled
  , fmt
  ) where

import Control.Monad (forM, replicateM_)
import Data.Foldable (toList)
import Data.Traversable (mapAccumL)
import qualified Data.Vector.Unboxed as V
import qualified Data.Vector.Unboxed.Mutable as MV
import Linear.Metric (dot, norm)
import Linear.V3 (V3 (..), cross)
import Text.Printf (printf)

import Manifold
import Manifold.Engine
import TestUtil (scriptOf)
import Manifold.World
import NodeJS (doubleBits, runNodeOverArrays)

-- Worlds ---------------------------------------------------------------------

-- | A movable body of density 1.
dyn :: Shape -> Double -> V3 Double -> V3 Double -> Double -> Double -> BodyInit
dyn sh size p v a om = BodyInit sh size 1 False p v a om sceneMaterial

-- | A static body.
still :: Shape -> Double -> V3 Double -> Double -> BodyInit
still sh size p a = BodyInit sh size 1 True p (V3 0 0 0) a 0 sceneMaterial

-- | A world holding exactly these bodies (capacity: their number, at least
-- two, so that the native contact limit is the same as a small page's).
mkWorld :: Space -> Params -> [BodyInit] -> IO NativeWorld
mkWorld sp ps bs = mkWorldCap (max 2 (length bs)) sp ps bs

mkWorldCap :: Int -> Space -> Params -> [BodyInit] -> IO NativeWorld
mkWorldCap cap sp ps bs = do
  w <- newWorld sp (layout cap)
  setParams w ps
  mapM_ (\(k, b) -> addBody w b >>= either (\e -> fail ("body " ++ show k ++ " in " ++ spaceName sp ++ ": " ++ e)) (const (pure ())))
        (zip [0 :: Int ..] bs)
  pure w

steps :: NativeWorld -> Int -> IO ()
steps w n = replicateM_ n (stepNative w)

-- | Step up to @n@ times while the condition (checked every step) holds;
-- how many steps were taken.
stepsWhile :: NativeWorld -> Int -> IO Bool -> IO Int
stepsWhile w n ok = go 0
  where
    go k | k >= n = pure k
         | otherwise = do
             stepNative w
             good <- ok
             if good then go (k + 1) else pure (k + 1)

bodyStates :: NativeWorld -> IO [BodyState]
bodyStates w = do
  n <- bodyCount w
  mapM (readBody w) [0 .. n - 1]

-- Reading the arrays ---------------------------------------------------------

meta :: NativeWorld -> Meta -> IO Double
meta w k = MV.read (wMeta (nwArrays w)) (fromEnum k)

-- | One contact row pair of the last step: its bodies (@cB@ is −1 for a
-- boundary or self contact), its depth and point.
data Contact = Contact
  { cA :: Int
  , cB :: Int
  , cOwner :: Int
  , cKey :: Int -- ^ the row's identity under its owner (warm starting)
  , cDirection :: V3 Double -- ^ the push on body a
  , cDepth :: Double
  , cPoint :: V3 Double
  } deriving Show

contacts :: NativeWorld -> IO [Contact]
contacts w = do
  n <- contactCount w
  let arr = wContacts (nwArrays w)
      field :: Int -> ContactField -> IO Double
      field c k = MV.read arr (contactStride * c + fromEnum k)
  forM [0 .. n - 1] $ \c ->
    Contact <$> (round <$> field c CA) <*> (round <$> field c CB)
            <*> (round <$> field c COwner) <*> (round <$> field c CKey)
            <*> (V3 <$> field c JaX <*> field c JaY <*> field c JaZ) <*> field c CDepth
            <*> (V3 <$> field c PointX <*> field c PointY <*> field c PointZ)

maxDepthOf :: [Contact] -> Double
maxDepthOf = maximum . (0 :) . map cDepth

slot :: NativeWorld -> Int -> Slot -> IO Double
slot w i s = MV.read (wScalars (nwArrays w)) (scalarSlots * i + fromEnum s)

bodySize :: NativeWorld -> Int -> IO Double
bodySize w i = slot w i Size

-- | The mass the engine uses (integrated from the outline when the body was
-- added).
bodyMass, bodyInertia :: NativeWorld -> Int -> IO Double
bodyMass w i = recip <$> slot w i InvMass
bodyInertia w i = recip <$> slot w i InvInertia

-- | Body @i@'s outline: the last vertex along each polygon direction.
outline :: NativeWorld -> Int -> IO [V3 Double]
outline w i = do
  let l = nwLayout w
      pp = polygon l
      vpb = verticesPerBody l
      arr = wVerts (nwArrays w)
      r3 :: Int -> IO (V3 Double)
      r3 k = V3 <$> MV.read arr (3 * k) <*> MV.read arr (3 * k + 1) <*> MV.read arr (3 * k + 2)
  forM [0 .. polyDirections pp - 1] $ \d ->
    r3 (vpb * i + 1 + d * polySteps pp + polySteps pp - 1)

-- | Whether every value of the live part of the per-body arrays (positions,
-- velocities, axes, normals, scalars, polygons) is finite.
allFinite :: NativeWorld -> IO Bool
allFinite w = do
  n <- bodyCount w
  let a = nwArrays w
      l = nwLayout w
      live :: MV.IOVector Double -> Int -> IO Bool
      live arr k = V.all (\x -> not (isNaN x || isInfinite x)) . V.take (k * n) <$> V.freeze arr
  and <$> sequence
    [ live (wPos a) 3, live (wVel a) 3, live (wAxis a) 3, live (wNormal a) 3
    , live (wScalars a) scalarSlots, live (wVerts a) (3 * verticesPerBody l) ]

-- Mechanics ------------------------------------------------------------------

speed :: BodyState -> Double
speed = norm . bsVel

-- | ½ m v² + ½ I ω², summed over the movable bodies.
kineticEnergy :: NativeWorld -> IO Double
kineticEnergy w = do
  n <- bodyCount w
  es <- forM [0 .. n - 1] $ \i -> do
    im <- slot w i InvMass
    ii <- slot w i InvInertia
    b <- readBody w i
    pure (if im > 0 then 0.5 * norm (bsVel b) ^ (2 :: Int) / im + 0.5 * bsOmega b ^ (2 :: Int) / ii else 0)
  pure (sum es)

-- | Σ m v in R³ over the given bodies, with the given masses.
momentum :: [(Double, BodyState)] -> V3 Double
momentum = foldr (\(m, b) acc -> acc + fmap (m *) (bsVel b)) (V3 0 0 0)

-- | The angular momentum about the y axis (the plane's normal) through the
-- origin: Σ m (p × v)·ŷ + s Σ I ω, where @s@ is the sign convention under
-- test (+1: ω turns the body counterclockwise about the surface normal).
angularMomentumY :: Double -> [(Double, Double, BodyState)] -> Double
angularMomentumY s bs =
  sum [ m * ((bsPos b `cross` bsVel b) `dot` V3 0 1 0) + s * i * bsOmega b | (m, i, b) <- bs ]

-- | The angle between two vectors, in degrees.
angleBetween :: V3 Double -> V3 Double -> Double
angleBetween a b = 180 / pi * acos (max (-1) (min 1 ((a `dot` b) / (norm a * norm b))))

-- Native versus emitted JavaScript -------------------------------------------

-- | What a test does to a world.
data Action
  = Steps Int
  | Grab Int Double (V3 Double) Double Double Double -- ^ body, sign, point, frequency, damping, max force
  | Drag (V3 Double)
  | Release
  deriving Show

act :: NativeWorld -> Action -> IO ()
act w = \case
  Steps n -> steps w n
  Grab i sgn q hz zeta fmax -> grabAt w i sgn q hz zeta fmax
  Drag q -> dragAt w q
  Release -> releaseMouse w

-- | Every array of a world, frozen.
type Snapshot = WorldArrays [Double]

snapshot :: NativeWorld -> IO Snapshot
snapshot w = traverse (fmap V.toList . V.freeze) (nwArrays w)

jsV3 :: V3 Double -> String
jsV3 (V3 x y z) = concatMap (\c -> "__fromBits(\"" ++ doubleBits c ++ "\"), ") [x, y, z]

jsNum :: Double -> String
jsNum c = "__fromBits(\"" ++ doubleBits c ++ "\")"

-- | Run the space's emitted engine under node from the given arrays through
-- the actions; the arrays afterwards (bit-exact transfer both ways).
runActionsInNode :: Space -> Snapshot -> [Action] -> IO Snapshot
runActionsInNode sp initial actions = do
  let jsAction = \case
        Steps n -> "for (let k = 0; k < " ++ show n ++ "; k++) e.step(...a);"
        Grab i sgn q hz zeta fmax -> "e.grab(...a, " ++ show i ++ ", " ++ jsNum sgn ++ ", " ++ jsV3 q
                                      ++ jsNum hz ++ ", " ++ jsNum zeta ++ ", " ++ jsNum fmax ++ ");"
        Drag q -> "e.drag(...a, " ++ init (init (jsV3 q)) ++ ");"
        Release -> "e.release(...a);"
      script = unlines $
        [ scriptOf sp
        , "const e = Manifold.spaces[" ++ show (spaceName sp) ++ "].engine;"
        , "const a = __arrays;"
        ] ++ map jsAction actions ++ ["__emitArrays(a);"]
  after <- runNodeOverArrays (toList initial) script
  if map length after /= map length (toList initial)
    then fail "node handed back arrays of other lengths"
    else pure (snd (mapAccumL refill after initial))
  where
    refill (x : rest) _ = (rest, x)
    refill [] _ = error "runActionsInNode: fewer arrays than the world's"

-- | The largest differences between the native and the emitted run.
data Differential = Differential
  { dPos :: Double
  , dVel :: Double
  , dVerts :: Double
  , dScalars :: Double
  , dContacts :: (Int, Int) -- ^ native and JavaScript contact counts at the end
  } deriving Show

-- | Snapshot the world, run the actions natively and in node, compare.
differential :: NativeWorld -> [Action] -> IO Differential
differential w actions = do
  s0 <- snapshot w
  mapM_ (act w) actions
  s1 <- snapshot w
  js <- runActionsInNode (nwSpace w) s0 actions
  n <- bodyCount w
  let l = nwLayout w
      diff k f = maximum (0 : take (k * n) (zipWith (\x y -> if isNaN x && isNaN y then 0 else abs (x - y)) (f s1) (f js)))
  pure Differential
    { dPos = diff 3 wPos
    , dVel = diff 3 wVel
    , dVerts = diff (3 * verticesPerBody l) wVerts
    , dScalars = diff scalarSlots wScalars
    , dContacts = ( round (wMeta s1 !! fromEnum ContactCount), round (wMeta js !! fromEnum ContactCount) )
    }

-- Misc -----------------------------------------------------------------------

-- | Print a labelled measurement, indented under the test's name.
labelled :: String -> String -> IO ()
labelled k v = putStrLn ("    " ++ k ++ ": " ++ v)

fmt :: Double -> String
fmt = printf "%.3g"
