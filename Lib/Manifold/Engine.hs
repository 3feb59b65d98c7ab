{-# LANGUAGE FlexibleContexts #-}
-- | Running the world natively and printing it as the page's JavaScript.
module Manifold.Engine
  ( NativeWorld (..)
  , BodyInit (..)
  , newWorld
  , addBody
  , stepNative
  , stepPhasesNative
  , genericStep
  , usesCompiledStep
  , removeBodyAt
  , pickAt
  , grabAt
  , dragAt
  , releaseMouse
  , Params (..)
  , defaultParams
  , setParams
  , contactCount
  , bodyCount
  , warningCount
  , readBody
  , BodyState (..)
  , placementAngleOf
  , Impulse (..)
  , rememberedImpulses
  , restoreImpulses
  , engineScript
  , engineProcedures
  , engineObject
  , engineSubroutines
  , stepProcedures
  , stagedPhases
  , phaseFunction
  , worldParams
  ) where

import qualified Data.Vector.Unboxed.Mutable as MV
import Linear.V3 (V3 (..))

import Manifold.Body
import Manifold.Compiled (compiledSteps)
import Manifold.Compiled.Runtime (CompiledStep (..), spaceFingerprint)
import Manifold.Space
import Manifold.Stage.Expr (E)
import Manifold.Stage.Imp
import Manifold.Grab
import Manifold.Population
import Manifold.Step (step, stepPhases)
import Manifold.World
import Data.Char (toLower, toUpper)
import Data.Foldable (toList)
import Data.List (intercalate)
import Data.Maybe (isJust)

data NativeWorld = NativeWorld
  { nwSpace :: Space
  , nwLayout :: Layout
  , nwArrays :: WorldArrays NativeArray
  , nwCompiled :: Maybe CompiledStep -- ^ the space's compiled step, if it has one
  }

newWorld :: Space -> Layout -> IO NativeWorld
newWorld sp l = do
  let s = arraySizes l
      alloc n = MV.replicate n 0
  arrays <- traverse alloc s
  let w = NativeWorld sp l arrays (compiledFor sp l)
  MV.write (wMeta arrays) (fromEnum Capacity) (fromIntegral (capacity l))
  setParams w defaultParams
  pure w

-- | The engine's parameters.
data Params = Params
  { pDt :: Double
  , pGravity :: Bool
  , pIterations :: Int
  , pFriction :: Double
  , pRestitution :: Double
  , pBaumgarte :: Double -- ^ fraction of the depth removed per step (paper: 0.1)
  , pSlop :: Double -- ^ depth allowed without correction
  , pBounceThreshold :: Double -- ^ approach speeds below this do not bounce
  , pWarmStart :: Bool -- ^ start each contact from its last step's impulses
  , pMaxCorrection :: Double -- ^ the fastest a contact pushes bodies out of an overlap
  , pPolygonStep :: Double -- ^ bodies up to this size walk their outline in one geodesic step (0: never)
  } deriving (Show, Eq)

defaultParams :: Params
defaultParams = Params
  { pDt = 0.01, pGravity = True, pIterations = 8, pFriction = 0.4, pRestitution = 0
  , pBaumgarte = 0.1, pSlop = 0.002, pBounceThreshold = 0.5, pWarmStart = True
  , pMaxCorrection = 0.5, pPolygonStep = 0.05 }

setParams :: NativeWorld -> Params -> IO ()
setParams w p = do
  let a = wParams (nwArrays w)
      set :: Param -> Double -> IO ()
      set k = MV.write a (fromEnum k)
  set Dt (pDt p)
  set GravityOn (if pGravity p then 1 else 0)
  set Iterations (fromIntegral (pIterations p))
  set Friction (pFriction p)
  set Restitution (pRestitution p)
  set Baumgarte (pBaumgarte p)
  set Slop (pSlop p)
  set BounceThreshold (pBounceThreshold p)
  set WarmStart (if pWarmStart p then 1 else 0)
  set MaxCorrection (pMaxCorrection p)
  set PolygonStep (pPolygonStep p)

-- | A body as a scene describes it.
data BodyInit = BodyInit
  { biShape :: Shape
  , biSize :: Double
  , biDensity :: Double
  , biStatic :: Bool
  , biPos :: V3 Double
  , biVel :: V3 Double
  , biAngle :: Double
  , biOmega :: Double
  }

metaValue :: Meta -> NativeWorld -> IO Int
metaValue k w = truncate <$> MV.read (wMeta (nwArrays w)) (fromEnum k)

bodyCount, warningCount, contactCount :: NativeWorld -> IO Int
bodyCount = metaValue BodyCount
warningCount = metaValue Warnings
contactCount = metaValue ContactCount

-- | Add a body: its centre is projected onto the surface, its velocity onto
-- the tangent plane; its axis is the tangent direction nearest to x (or z).
-- Returns the body's index, or why it could not be added.
addBody :: NativeWorld -> BodyInit -> IO (Either String Int)
addBody w b = do
  let Outline outline = shapeOutline (biShape b)
      args = BodyArgs (biSize b) (biDensity b) (if biStatic b then 1 else 0)
                      (biPos b) (biVel b) (biAngle b) (biOmega b)
  runNative (addBodyWith (nwSpace w) (nwLayout w) (nwArrays w) outline args)
  i <- metaValue LastAdded w
  n <- bodyCount w
  pure $ if i >= 0 then Right i
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

dragAt :: NativeWorld -> V3 Double -> IO ()
dragAt w q = runNative (dragTo (nwArrays w) q)

releaseMouse :: NativeWorld -> IO ()
releaseMouse w = runNative (release (nwArrays w))

removeBodyAt :: NativeWorld -> Int -> IO ()
removeBodyAt w i = runNative (removeBody (nwLayout w) (nwArrays w) i)

-- | The compiled step ("Manifold.Compiled.Runtime") of a catalogue space,
-- when the space and polygon are the ones it was printed for.
compiledFor :: Space -> Layout -> Maybe CompiledStep
compiledFor sp l = case [c | c <- compiledSteps, compiledSpace c == spaceName sp] of
  c : _ | compiledFingerprint c == spaceFingerprint sp l -> Just c
  _ -> Nothing

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

data BodyState = BodyState
  { bsPos :: V3 Double
  , bsVel :: V3 Double
  , bsAngle :: Double
  , bsOmega :: Double
  , bsAxis :: V3 Double
  } deriving Show

readBody :: NativeWorld -> Int -> IO BodyState
readBody w i = do
  let a = nwArrays w
      r3 arr = V3 <$> MV.read arr (3 * i) <*> MV.read arr (3 * i + 1) <*> MV.read arr (3 * i + 2)
  BodyState <$> r3 (wPos a) <*> r3 (wVel a) <*> MV.read (wScalars a) (scalarSlots * i) <*> MV.read (wScalars a) (scalarSlots * i + 1) <*> r3 (wAxis a)

-- | The angle that places body @i@'s outline where it is now (see
-- 'placementAngle'): a scene's @angle@.
placementAngleOf :: NativeWorld -> Int -> IO Double
placementAngleOf w i = do
  runNative (placementAngle (nwSpace w) (nwArrays w) (fromIntegral i))
  MV.read (wMeta (nwArrays w)) (fromEnum PlacementAngle)

-- | A contact row's impulses as the world remembers them after a step, to
-- warm start the same contact (by its key) in the next.
data Impulse = Impulse
  { impulseKey :: Double -- ^ the contact's identity (a whole number)
  , impulseNormal :: Double
  , impulseFriction :: Double
  } deriving (Show, Eq)

-- | What body @i@ remembers of the last step's contact rows it owns (rows
-- whose impulses were both 0 warm start nothing and are left out).
rememberedImpulses :: NativeWorld -> Int -> IO [Impulse]
rememberedImpulses w i = do
  let a = nwArrays w
      field :: Int -> PrevField -> IO Double
      field k f = MV.read (wPrev a) (prevStride * k + fromEnum f)
  start <- truncate <$> MV.read (wBodyPrev a) (2 * i)
  count <- truncate <$> MV.read (wBodyPrev a) (2 * i + 1)
  rows <- mapM (\k -> Impulse <$> field k PrevKey <*> field k PrevNormal <*> field k PrevFriction) [start .. start + count - 1]
  pure [r | r <- rows, impulseNormal r /= 0 || impulseFriction r /= 0]

-- | Give the world's bodies, in order, what they remember of the last
-- step's contacts (as 'rememberedImpulses' read it), replacing what they
-- remembered; the next step warm starts from it.
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
                     | (k, r) <- zip [s ..] rows ]
      | (i, s, rows) <- zip3 [0 ..] starts perBody ]
    pure (Right ())

stagedArrays :: WorldArrays StagedArray
stagedArrays = fmap StagedArray arrayNames

worldParams :: [String]
worldParams = toList arrayNames

-- | The engine's procedures for one space, as JavaScript functions over the
-- world's arrays.
engineProcedures :: Space -> Layout -> [String]
engineProcedures sp l =
  unlines (("function step(" ++ intercalate ", " worldParams ++ ") {")
           : ["  " ++ phaseFunction name ++ "(" ++ intercalate ", " worldParams ++ ");" | (name, _) <- stagedPhases]
           ++ ["}"])
  : stageProcedures (engineProcedureList sp l)

-- | The names of the subroutines among a space's printed functions (each
-- printed function begins @function NAME(@): all but @step@ and the
-- procedures.
engineSubroutines :: Space -> Layout -> [String] -> [String]
engineSubroutines sp l printed =
  [ name | text <- printed, let name = takeWhile (/= '(') (drop (length "function ") text)
         , name `notElem` ("step" : map (procName . fst) (engineProcedureList sp l)) ]

-- | The procedures the page calls: the phases, then the rest.
engineProcedureList :: Space -> Layout -> [(JsProcedure, [StagedArray] -> [E] -> Staged ())]
engineProcedureList sp l = stepProcedures sp l ++
  [ (JsProcedure "polygonise" worldParams [], \_ _ -> polygoniseAll sp l stagedArrays)
  , (JsProcedure "addBody" worldParams
      ["shape", "size", "density", "isStatic", "px", "py", "pz", "vx", "vy", "vz", "angle", "omega"],
      \_ [code, size, density, static, px, py, pz, vx, vy, vz, angle, omega] ->
         addBodyWith sp l stagedArrays (codeOutline code)
           (BodyArgs size density static (V3 px py pz) (V3 vx vy vz) angle omega))
  , (JsProcedure "removeBody" worldParams ["index"],
      \_ [i] -> removeBody l stagedArrays (toIndex i))
  , (JsProcedure "placementAngle" worldParams ["index"],
      \_ [i] -> placementAngle sp stagedArrays (toIndex i))
  , (JsProcedure "pickBody" worldParams ["qx", "qy", "qz"],
      \_ [x, y, z] -> pickBody sp l stagedArrays (V3 x y z))
  , (JsProcedure "grab" worldParams ["index", "sign", "qx", "qy", "qz", "frequency", "damping", "maxForce"],
      \_ [i, sgn, x, y, z, hz, zeta, fmax] -> grab sp stagedArrays (toIndex i) sgn (V3 x y z) hz zeta fmax)
  , (JsProcedure "drag" worldParams ["qx", "qy", "qz"],
      \_ [x, y, z] -> dragTo stagedArrays (V3 x y z))
  , (JsProcedure "release" worldParams [], \_ _ -> release stagedArrays)
  ]

-- | The step's phases as procedures to print, one for each phase.
stepProcedures :: Space -> Layout -> [(JsProcedure, [StagedArray] -> [E] -> Staged ())]
stepProcedures sp l = [ (JsProcedure (phaseFunction name) worldParams [], \_ _ -> phase sp l stagedArrays) | (name, phase) <- stagedPhases ]

-- | The step's phases, staged (to print them).
stagedPhases :: [(String, Space -> Layout -> WorldArrays StagedArray -> Staged ())]
stagedPhases = stepPhases

-- | The JavaScript function of one phase of the step. The step is printed as
-- one function per phase (and the phases' large parts as subroutines, see
-- 'subroutine') because V8 does not optimise a function whose bytecode is
-- larger than 60 KB, and the whole step is larger: unoptimised, it ran 17
-- times slower (torus, 655 bodies, bench/node.mjs).
phaseFunction :: String -> String
phaseFunction (c : cs) = "step" ++ toUpper c : cs
phaseFunction [] = "step"

engineScript :: Space -> Layout -> String
engineScript sp l = unlines (engineProcedures sp l)

-- | The engine's description for the page, as a JavaScript object literal:
-- how to allocate a world (sizes are linear in the capacity), what each
-- index of the meta, parameter, per-body, contact and mouse arrays means,
-- the default parameters, and the procedures.
engineObject :: Layout -> [String] -> String
engineObject l subroutines =
  let at c = arraySizes l { capacity = c }
      one = at 1
      two = at 2
      size name a b = name ++ ": [" ++ show (a - (b - a)) ++ ", " ++ show (b - a) ++ "]"
      enumObj :: forall e. (Show e, Enum e, Bounded e) => e -> String
      enumObj _ = "{ " ++ intercalate ", " [show' k ++ ": " ++ show (fromEnum k) | k <- [minBound .. maxBound :: e]] ++ " }"
      show' k = let (c : cs) = show k in toLower c : cs
      p = defaultParams
      params = [ ("dt", pDt p), ("gravityOn", if pGravity p then 1 else 0), ("iterations", fromIntegral (pIterations p))
               , ("friction", pFriction p), ("restitution", pRestitution p), ("baumgarte", pBaumgarte p)
               , ("slop", pSlop p), ("bounceThreshold", pBounceThreshold p)
               , ("warmStart", if pWarmStart p then 1 else 0), ("maxCorrection", pMaxCorrection p)
               , ("polygonStep", pPolygonStep p) ]
      phaseNames = stagedPhases
  in unlines
    [ "{"
    , "  arrays: [" ++ intercalate ", " (map show (toList arrayNames)) ++ "],"
    , "  sizes: { " ++ intercalate ", " (zipWith3 size (toList arrayNames) (toList one) (toList two)) ++ " },"
    , "  directions: " ++ show (polyDirections (polygon l)) ++ ", steps: " ++ show (polySteps (polygon l)) ++ ","
    , "  verticesPerBody: " ++ show (verticesPerBody l) ++ ", contactStride: " ++ show contactStride ++ ", contactsPerBody: " ++ show contactsPerBody ++ ","
    , "  meta: " ++ enumObj BodyCount ++ ","
    , "  params: " ++ enumObj Dt ++ ","
    , "  slots: " ++ enumObj Angle ++ ","
    , "  contact: " ++ enumObj CA ++ ","
    , "  prev: " ++ enumObj PrevOwner ++ ", prevStride: " ++ show prevStride ++ ","
    , "  mouse: " ++ enumObj MActive ++ ","
    , "  defaults: { " ++ intercalate ", " [k ++ ": " ++ show v | (k, v) <- params] ++ " },"
    , "  phases: [" ++ intercalate ", " ["[" ++ show name ++ ", " ++ phaseFunction name ++ "]" | (name, _) <- phaseNames] ++ "],"
    , "  // what the phases call, each printed once: for profiles, and for tests that optimise all of the step"
    , "  subroutines: [" ++ intercalate ", " ["[" ++ show name ++ ", " ++ name ++ "]" | name <- subroutines] ++ "],"
    , "  step: step, polygonise: polygonise, addBody: addBody, removeBody: removeBody, placementAngle: placementAngle,"
    , "  pickBody: pickBody, grab: grab, drag: drag, release: release"
    , "}"
    ]
