-- | Running the world natively: a world's arrays, stepped by its space's
-- compiled step where there is one ("Manifold.Compile") and by the generic
-- step otherwise, and the calls that add, pick, grab and read bodies.
module Manifold.Engine
  ( NativeWorld (..)
  , BodyInit (..)
  , Material (..)
  , sceneMaterial
  , newWorld
  , newWorldUsing
  , CompiledStep
  , addBody
  , restoreBody
  , stepNative
  , stepPhasesNative
  , genericStep
  , usesCompiledStep
  , removeBodyAt
  , addJointAt
  , removeJointAt
  , jointCount
  , jointField
  , jointAnchorPoints
  , jointCurves
  , setJointField
  , JointKind (..)
  , JointField (..)
  , pickAt
  , grabAt
  , dragAt
  , releaseMouse
  , Params (..)
  , defaultParams
  , setParams
  , contactCount
  , awakeCount
  , islandCount
  , setSleepingAt
  , bodyCount
  , warningCount
  , readBody
  , BodyState (..)
  , Impulse (..)
  , rememberedImpulses
  , restoreImpulses
  , stateHash
  ) where

import Control.Monad (zipWithM_)
import qualified Data.Vector.Unboxed as U
import qualified Data.Vector.Unboxed.Mutable as MV
import Linear.V3 (V3 (..))

import Manifold.Body
import Manifold.Hull (outlineCode)
import Manifold.Compiled (compiledSteps)
import Manifold.Compiled.Runtime (CompiledStep (..), spaceFingerprint)
import Manifold.Params
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.Grab
import Manifold.Anchor (anchorWalkSteps)
import Manifold.Joint (addJoint, chordSegments, jointAnchors, jointPathPoints, jointPaths, jointProblem, removeJoint)
import Manifold.Population
import Manifold.Sleep (countIslands, setSleeping)
import Manifold.Step (step, stepPhases)
import Manifold.World
import Data.Maybe (fromMaybe, isJust, listToMaybe)
import Data.Word (Word64)
import Manifold.StateHash (HashedPart (..), fnv1a64, hashedParts)

-- | A world run natively: its space, its arrays' layout and the arrays
-- (the state, as "Manifold.World" lays it out; the page's engine holds the
-- same arrays).
data NativeWorld = NativeWorld
  { nwSpace :: Space
  , nwLayout :: Layout -- ^ capacity and polygon
  , nwArrays :: WorldArrays NativeArray -- ^ every body's state, the contacts, the parameters
  , nwCompiled :: Maybe CompiledStep -- ^ the space's compiled step, if it has one
  }

-- | An empty world of a space, run by the space's compiled step if it is
-- a catalogue space ('compiledSteps').
newWorld :: Space -> Layout -> IO NativeWorld
newWorld = newWorldUsing compiledSteps

-- | An empty world run by the first of the given compiled steps made for
-- its space and polygon (a space of one's own: @newWorldUsing [bowlStep]
-- bowl@, see "Manifold.Compile"), or by the generic step if none is.
newWorldUsing :: [CompiledStep] -> Space -> Layout -> IO NativeWorld
newWorldUsing steps sp l = do
  let s = arraySizes l
      alloc n = MV.replicate n 0
  arrays <- traverse alloc s
  let w = NativeWorld sp l arrays (compiledFor steps sp l)
  MV.write (wMeta arrays) (fromEnum Capacity) (fromIntegral (capacity l))
  setParams w defaultParams
  pure w

-- | Set the world's parameters.
setParams :: NativeWorld -> Params -> IO ()
setParams w = writeParams (nwArrays w)

-- | A body as a scene describes it.
data BodyInit = BodyInit
  { biShape :: Shape
  , biSize :: Double -- ^ circumradius
  , biDensity :: Double
  , biStatic :: Bool -- ^ a fixed body: it pushes and is never pushed
  , biPos :: V3 Double -- ^ projected onto the surface
  , biVel :: V3 Double -- ^ projected onto the tangent plane
  , biAngle :: Double -- ^ from the axis the body starts with ('Manifold.Surface.referenceAxis'), or from the saved axis ('restoreBody')
  , biOmega :: Double -- ^ angular velocity about the normal
  , biMaterial :: Material -- ^ its friction and restitution ('sceneMaterial': the scene's)
  }

-- | A body's material: its friction coefficient and restitution, each
-- 'Nothing' where the body takes the scene's ('Manifold.Params'). A pair's
-- are mixed as Box2D mixes them: friction @√(μa·μb)@, the larger
-- restitution; a wall's are the scene's.
data Material = Material
  { matFriction :: Maybe Double
  , matRestitution :: Maybe Double
  } deriving (Show, Eq)

-- | The material of a body that takes the scene's friction and restitution.
sceneMaterial :: Material
sceneMaterial = Material Nothing Nothing

metaValue :: Meta -> NativeWorld -> IO Int
metaValue k w = truncate <$> MV.read (wMeta (nwArrays w)) (fromEnum k)

-- | The bodies the world holds; the steps that left a body as it was
-- because they would have made a number infinite or NaN (see
-- "Manifold.World"); the contact rows the last step found.
bodyCount, warningCount, contactCount :: NativeWorld -> IO Int
bodyCount = metaValue BodyCount
warningCount = metaValue Warnings
contactCount = metaValue ContactCount

-- | The movable bodies awake ("Manifold.Sleep").
awakeCount :: NativeWorld -> IO Int
awakeCount w = runNative (countIslands (nwArrays w)) >> metaValue AwakeCount w

-- | The islands of movable bodies, awake and asleep, counted now.
islandCount :: NativeWorld -> IO Int
islandCount w = runNative (countIslands (nwArrays w)) >> metaValue IslandCount w

-- | Body @i@'s sleep timer, and asleep in the island named by a body's
-- index or awake (what a saved scene restores; a static body stays awake).
setSleepingAt :: NativeWorld -> Int -> Maybe Int -> Double -> IO ()
setSleepingAt w i label timer = runNative (setSleeping (nwArrays w) (fromIntegral i) (maybe (-1) fromIntegral label) timer)

-- | Add a body: its centre is projected onto the surface, its velocity onto
-- the tangent plane; its axis is the tangent direction nearest to x (or z).
-- Returns the body's index, or why it could not be added.
addBody :: NativeWorld -> BodyInit -> IO (Either String Int)
addBody w b = addBodyFramed w b Nothing

-- | Add a body as a saved scene holds it, with the axis it carried and its
-- normal: restored bit for bit, its position and velocity as given
-- ('Manifold.Population.addBodyWith'), so that a saved run goes on as it
-- would have. Returns the body's index, or why it could not be added.
restoreBody :: NativeWorld -> BodyInit -> (V3 Double, V3 Double) -> IO (Either String Int)
restoreBody w b frame = addBodyFramed w b (Just frame)

-- | 'addBody', or 'restoreBody' with a frame.
addBodyFramed :: NativeWorld -> BodyInit -> Maybe (V3 Double, V3 Double) -> IO (Either String Int)
addBodyFramed w b frame = do
  let Outline outline = shapeOutline (biShape b)
      (restore, axis, normal) = maybe (0, V3 0 0 0, V3 0 0 0) (\(a, n) -> (1, a, n)) frame
      own = fromMaybe (-1)
      args = BodyArgs (biSize b) (biDensity b) (if biStatic b then 1 else 0)
                      (biPos b) (biVel b) (biAngle b) (biOmega b) restore axis normal
                      (own (matFriction (biMaterial b))) (own (matRestitution (biMaterial b)))
                      code p q
      (code, p, q) = maybe (outlineCode, 0, 0) shapeArgs (shapeKind (biShape b))
  corners <- U.thaw (U.fromList (concat [[a, c] | (a, c) <- maybe (shapeCorners CircleShape) shapeCorners (shapeKind (biShape b))]))
  runNative (addBodyWith (nwSpace w) (nwLayout w) (nwArrays w) corners (\_ _ _ -> outline) args)
  i <- metaValue LastAdded w
  n <- bodyCount w
  pure $ if i >= 0 then Right i
    else if i == -2 then Left frameMisfit
    else if n >= capacity (nwLayout w) then Left ("the world is full (capacity " ++ show (capacity (nwLayout w)) ++ ")")
    else Left "the position does not project onto the surface (the field's gradient vanishes there)"

-- | The body under a surface point, and whether through its image (−1).
pickAt :: NativeWorld -> V3 Double -> IO (Maybe (Int, Double))
pickAt w q = do
  runNative (pickBody (nwSpace w) (nwLayout w) (nwArrays w) q)
  i <- metaValue Picked w
  sgn <- MV.read (wMeta (nwArrays w)) (fromEnum PickedSign)
  pure (if i >= 0 then Just (i, sgn) else Nothing)

-- | Hold a body at a surface point with a mouse joint of the given
-- frequency (Hz), damping ratio and force limit.
grabAt :: NativeWorld -> Int -> Double -> V3 Double -> Double -> Double -> Double -> IO ()
grabAt w i sgn q hz zeta fmax = runNative (grab (nwSpace w) (nwArrays w) i sgn q hz zeta fmax)

-- | Move the mouse joint's target to a surface point.
dragAt :: NativeWorld -> V3 Double -> IO ()
dragAt w q = runNative (dragTo (nwArrays w) q)

-- | Let go of the grabbed body.
releaseMouse :: NativeWorld -> IO ()
releaseMouse w = runNative (release (nwArrays w))

-- | Remove body @i@; the last body takes its index ('removeBody').
removeBodyAt :: NativeWorld -> Int -> IO ()
removeBodyAt w i = runNative (removeBody (nwSpace w) (nwLayout w) (nwArrays w) i)

-- | Add a joint of a kind between body @a@ and body @b@ (−1: the world),
-- anchored at two surface points (for a pin, the same point twice): its
-- length is the anchors' distance, its reference angle the bodies'
-- relative angle now, its limits, motor and spring off ('setJointField'
-- sets them). Returns the joint's index, or why it could not be added.
addJointAt :: NativeWorld -> JointKind -> Int -> Int -> V3 Double -> V3 Double -> IO (Either String Int)
addJointAt w kind a b qa qb = do
  runNative (addJoint (nwSpace w) (nwArrays w) (fromIntegral (fromEnum kind)) (fromIntegral a) (fromIntegral b) qa qb)
  j <- metaValue LastJoint w
  pure (if j >= 0 then Right j else Left (jointProblem j))

-- | Remove joint @j@; the last joint takes its index.
removeJointAt :: NativeWorld -> Int -> IO ()
removeJointAt w j = runNative (removeJoint (nwArrays w) j)

-- | The joints the world holds.
jointCount :: NativeWorld -> IO Int
jointCount = metaValue JointCount

-- | Where every joint's two anchors are now (body b's, on a quotient, at
-- the image nearest body a's).
jointAnchorPoints :: NativeWorld -> IO [(V3 Double, V3 Double)]
jointAnchorPoints w = do
  n <- jointCount w
  out <- MV.replicate (6 * max 1 n) 0
  runNative (jointAnchors (nwSpace w) (nwArrays w) out)
  let at k = MV.read out k
  mapM (\j -> (,) <$> (V3 <$> at (6 * j) <*> at (6 * j + 1) <*> at (6 * j + 2))
                  <*> (V3 <$> at (6 * j + 3) <*> at (6 * j + 4) <*> at (6 * j + 5))) [0 .. n - 1]

-- | Every joint as the page draws it ('jointPaths'): the walk from body a's
-- centre to its anchor, body b's, and the chord between the anchors
-- projected onto the surface.
jointCurves :: NativeWorld -> IO [([V3 Double], [V3 Double], [V3 Double])]
jointCurves w = do
  n <- jointCount w
  let per = 3 * jointPathPoints
      walk = anchorWalkSteps + 1
  out <- MV.replicate (per * max 1 n) 0
  runNative (jointPaths (nwSpace w) (nwArrays w) out)
  let point k = V3 <$> MV.read out k <*> MV.read out (k + 1) <*> MV.read out (k + 2)
      points j from count = mapM (\k -> point (per * j + 3 * k)) [from .. from + count - 1]
  mapM (\j -> (,,) <$> points j 0 walk <*> points j walk walk <*> points j (2 * walk) (chordSegments + 1)) [0 .. n - 1]

-- | A field of joint @j@ ('JointField').
jointField :: NativeWorld -> Int -> JointField -> IO Double
jointField w j k = MV.read (wJoints (nwArrays w)) (jointStride * j + fromEnum k)

-- | Set a field of joint @j@: what a joint's description sets beyond
-- 'addJointAt' (length, limits, motor, spring, a saved joint's anchors and
-- impulses).
setJointField :: NativeWorld -> Int -> JointField -> Double -> IO ()
setJointField w j k = MV.write (wJoints (nwArrays w)) (jointStride * j + fromEnum k)

-- | The compiled step ("Manifold.Compiled.Runtime") among @steps@ that
-- was made for the space and polygon.
compiledFor :: [CompiledStep] -> Space -> Layout -> Maybe CompiledStep
compiledFor steps sp l = listToMaybe
  [ c | c <- steps, compiledSpace c == spaceName sp, compiledFingerprint c == spaceFingerprint sp l ]

-- | The world run by the generic (polymorphic) step even if its space has a
-- compiled one: the reference the compiled step is tested against.
genericStep :: NativeWorld -> NativeWorld
genericStep w = w { nwCompiled = Nothing }

-- | Whether the world runs a compiled step.
usesCompiledStep :: NativeWorld -> Bool
usesCompiledStep = isJust . nwCompiled

-- | One step of the world.
stepNative :: NativeWorld -> IO ()
stepNative w = case nwCompiled w of
  Just c -> mapM_ (\(_, run) -> run (nwArrays w)) (compiledPhases c)
  Nothing -> runNative (stepN (nwSpace w) (nwLayout w) (nwArrays w))

stepN :: Space -> Layout -> WorldArrays NativeArray -> Native ()
stepN = step
{-# NOINLINE stepN #-}

-- | The phases of 'stepNative', named, each runnable alone (in this order
-- they make one step): for benchmarks that say where the time goes.
stepPhasesNative :: NativeWorld -> [(String, IO ())]
stepPhasesNative w = case nwCompiled w of
  Just c -> [(name, run (nwArrays w)) | (name, run) <- compiledPhases c]
  Nothing -> [(name, runNative (phase (nwSpace w) (nwLayout w) (nwArrays w))) | (name, phase) <- nativePhases]

nativePhases :: [(String, Space -> Layout -> WorldArrays NativeArray -> Native ())]
nativePhases = stepPhases
{-# NOINLINE nativePhases #-}

-- | Where a body is and how it moves ('readBody').
data BodyState = BodyState
  { bsPos :: V3 Double -- ^ its centre, on the surface
  , bsVel :: V3 Double -- ^ in the tangent plane
  , bsAngle :: Double -- ^ from 'bsAxis'
  , bsOmega :: Double -- ^ angular velocity about the normal
  , bsAxis :: V3 Double -- ^ the tangent axis the body carries along
  , bsNormal :: V3 Double -- ^ the surface's unit normal at the centre, as the step keeps it
  , bsAsleep :: Maybe Int -- ^ the island it sleeps in (named by one of its bodies' index), or awake
  , bsSleepTimer :: Double -- ^ how long it has moved slower than the sleep threshold (s)
  , bsOwnMaterial :: Material -- ^ its own friction and restitution, where it has them
  } deriving Show

-- | The hash of the world's state ("Manifold.StateHash"): what
-- @manifold sim --hash@ prints and the page's @window.manifold.hash()@
-- gives for the same run.
stateHash :: NativeWorld -> IO Word64
stateHash w = do
  numbers <- mapM part hashedParts
  pure (fnv1a64 (concat numbers))
  where
    part (HashedPart arrayOf rows stride) = do
      n <- metaValue rows w
      mapM (MV.read (arrayOf (nwArrays w))) [0 .. n * stride - 1]

-- | Body @i@'s state, as the world's arrays hold it now.
readBody :: NativeWorld -> Int -> IO BodyState
readBody w i = do
  let a = nwArrays w
      r3 arr = V3 <$> MV.read arr (3 * i) <*> MV.read arr (3 * i + 1) <*> MV.read arr (3 * i + 2)
      slot :: Slot -> IO Double
      slot k = MV.read (wScalars a) (scalarSlots * i + fromEnum k)
  asleep <- slot Asleep
  label <- slot Island
  BodyState <$> r3 (wPos a) <*> r3 (wVel a) <*> slot Angle <*> slot Omega <*> r3 (wAxis a) <*> r3 (wNormal a)
    <*> pure (if asleep > 0 then Just (round label) else Nothing) <*> slot SleepTimer
    <*> (Material <$> (own <$> slot BodyFriction) <*> (own <$> slot BodyRestitution))
  where own x = if x < 0 then Nothing else Just x

-- | A contact row as the world remembers it after a step: its impulses,
-- to warm start the same contact (by its key) in the next; and, for a row
-- the next step may keep instead of finding its pair's contacts again, the
-- numbers keeping it takes ('keptFields': depth, drift, point and rows, in
-- that order), or none.
data Impulse = Impulse
  { impulseKey :: Double -- ^ the contact's identity (a whole number)
  , impulseNormal :: Double
  , impulseFriction :: Double
  , impulseKept :: [Double] -- ^ empty, or one number for each of 'keptFields'
  } deriving (Show, Eq)

-- | What body @i@ remembers of the last step's contact rows it owns (rows
-- whose impulses were both 0 warm start nothing and are left out, unless
-- they are to be kept).
rememberedImpulses :: NativeWorld -> Int -> IO [Impulse]
rememberedImpulses w i = do
  let a = nwArrays w
      field :: Int -> PrevField -> IO Double
      field k f = MV.read (wPrev a) (prevStride * k + fromEnum f)
      row k = do
        kept <- field k PrevKept
        Impulse <$> field k PrevKey <*> field k PrevNormal <*> field k PrevFriction
                <*> (if kept > 0 then mapM (field k . snd) keptFields else pure [])
  start <- truncate <$> MV.read (wBodyPrev a) (2 * i)
  count <- truncate <$> MV.read (wBodyPrev a) (2 * i + 1)
  rows <- mapM row [start .. start + count - 1]
  pure [r | r <- rows, impulseNormal r /= 0 || impulseFriction r /= 0 || not (null (impulseKept r))]

-- | Give the world's bodies, in order, what they remember of the last
-- step's contacts (as 'rememberedImpulses' read it), replacing what they
-- remembered; the next step warm starts from it (and keeps the rows that
-- carry their kept numbers, as it would have).
restoreImpulses :: NativeWorld -> [[Impulse]] -> IO (Either String ())
restoreImpulses w perBody = do
  n <- bodyCount w
  let a = nwArrays w
      total = sum (map length perBody)
      room = maxContacts (nwLayout w)
  if length perBody > n then pure (Left ("impulses for " ++ show (length perBody) ++ " bodies, the world holds " ++ show n))
  else if total > room then pure (Left (show total ++ " remembered contact rows, more than the world's " ++ show room))
  else do
    let starts = scanl (+) 0 (map length perBody)
    mapM_ (\i -> MV.write (wBodyPrev a) (2 * i + 1) 0) [0 .. n - 1]
    sequence_
      [ do MV.write (wBodyPrev a) (2 * i) (fromIntegral s)
           MV.write (wBodyPrev a) (2 * i + 1) (fromIntegral (length rows))
           sequence_ [ do let put :: PrevField -> Double -> IO ()
                              put f = MV.write (wPrev a) (prevStride * k + fromEnum f)
                          put PrevOwner (fromIntegral i)
                          put PrevKey (impulseKey r)
                          put PrevNormal (impulseNormal r)
                          put PrevFriction (impulseFriction r)
                          put PrevKept (if null (impulseKept r) then 0 else 1)
                          zipWithM_ put (map snd keptFields) (impulseKept r)
                     | (k, r) <- zip [s ..] rows ]
      | (i, s, rows) <- zip3 [0 ..] starts perBody ]
    pure (Right ())
