-- | The page's engine for one space, as JavaScript: the staged program's
-- procedures ("Manifold.Program") printed as functions, and the object the
-- page reads the world's layout from (array sizes, what each index of the
-- meta, parameter, per-body, contact and mouse arrays means, the default
-- parameters, the phases and the procedures).
module Manifold.Stage.EngineScript
  ( engineProcedures
  , engineObject
  , sceneKeysArray
  , keptFieldsArray
  ) where

import Data.Char (isAsciiUpper, toLower)
import Data.Foldable (toList)
import Data.List (dropWhileEnd, intercalate)

import Manifold.Params
import Manifold.Program
import Manifold.Body (PolygonParams (..), vertexIndex)
import Manifold.Collide (KeyGroup (..), keysPerGroup)
import Manifold.Space
import Manifold.Stage.Code (Function (..))
import Manifold.Stage.Imp (Procedure (..), stageFunctions)
import Manifold.Stage.Expr (sym)
import Manifold.Stage.Print (FnType (..), Target (..), printFunction, printProcedure)
import Manifold.GeodesicPath (PathSlot (..), pathStride)
import Manifold.Anchor (anchorWalkSteps)
import Manifold.Joint (chordSegments, jointPathPoints, jointProblem)
import Manifold.Measures (MeasureSlot (..), measureSize)
import Manifold.Population (frameMisfit)
import Manifold.StateHash (HashedPart (..), hashedParts)
import Manifold.World

-- | The engine's functions for one space, as JavaScript (the step, which
-- calls the phases, then each staged function), and the names of the
-- subroutines among them.
engineProcedures :: Space -> Layout -> ([String], [String])
engineProcedures sp l =
  ( unlines (("function step(" ++ intercalate ", " worldParams ++ ") {")
             : ["  " ++ phaseFunction name ++ "(" ++ intercalate ", " worldParams ++ ");" | (name, _) <- stagedPhases]
             ++ ["}"])
    : map (printProcedure JavaScript) functions
  , [ fnName f | f <- functions, fnName f `notElem` map (procName . fst) procedures ] )
  where
    procedures = pageProcedures sp l
    functions = stageFunctions JavaScript procedures

-- | The engine's description for the page, as a JavaScript object literal:
-- how to allocate a world (sizes are linear in the capacity, which is at
-- most 'pageMaxBodies'), what each
-- index of the meta, parameter, per-body, contact and mouse arrays means,
-- the default parameters, and the procedures (with the names of the
-- subroutines they call).
-- | The most bodies a world of the page's engine holds (its arrays grow to
-- this by doubling, as bodies are added): 32,768 bodies take about 200 MB
-- of arrays, mostly their contact rows.
pageMaxBodies :: Int
pageMaxBodies = 32768

engineObject :: Layout -> [String] -> String
engineObject l subroutines =
  let at c = arraySizes l { capacity = c }
      one = at 1
      two = at 2
      size name a b = name ++ ": [" ++ show (a - (b - a)) ++ ", " ++ show (b - a) ++ "]"
      enumObj :: forall e. (Show e, Enum e, Bounded e) => e -> String
      enumObj _ = "{ " ++ intercalate ", " [jsName k ++ ": " ++ show (fromEnum k) | k <- [minBound .. maxBound :: e]] ++ " }"
  in unlines
    [ "{"
    , "  arrays: [" ++ intercalate ", " (map show (toList arrayNames)) ++ "],"
    , "  sizes: { " ++ intercalate ", " (zipWith3 size (toList arrayNames) (toList one) (toList two)) ++ " },"
    , "  directions: " ++ show (polyDirections (polygon l)) ++ ", steps: " ++ show (polySteps (polygon l)) ++ ","
    , "  maxBodies: " ++ show pageMaxBodies ++ ","
    , "  verticesPerBody: " ++ show (verticesPerBody l) ++ ", contactStride: " ++ show contactStride ++ ", contactsPerBody: " ++ show contactsPerBody ++ ","
    , "  meta: " ++ enumObj BodyCount ++ ","
    , "  params: " ++ enumObj Dt ++ ","
    , "  slots: " ++ enumObj Angle ++ ","
    , "  contact: " ++ enumObj CA ++ ","
    , "  prev: " ++ enumObj PrevOwner ++ ", prevStride: " ++ show prevStride ++ ","
    , "  // a contact's key: (other body + 1) * the space's keysPerBody + group * perGroup + point (Manifold.Collide)"
    , "  keys: { perGroup: " ++ show keysPerGroup ++ ", groups: " ++ enumObj PairKey ++ " },"
    , "  // where step k (1 .. steps) along direction d sits among a body's vertices (0 is the centre)"
    , "  vertexIndex: " ++ dropWhileEnd (== '\n') (printFunction JavaScript "vertexIndex" (FnType ["d", "k"] False) [vertexIndex (polygon l) (sym "d") (sym "k")]) ++ ","
    , "  mouse: " ++ enumObj MActive ++ ","
    , "  // a body's hull among its hullStride numbers (Manifold.World): the radius rounding it, corner k's (a, b) in the body's frame at local + 2k, and walked onto the surface, (x, y, z) at world + 3k; scalars' corners counts them"
    , "  hull: { stride: " ++ show hullStride ++ ", radius: 0, local: " ++ show (hullLocalAt 0 :: Int) ++ ", world: " ++ show (hullWorldAt 0 :: Int) ++ " },"
    , "  // a joint's fields (Manifold.Joint): kind (" ++ intercalate ", " [show (fromEnum k) ++ " " ++ jsName k | k <- [minBound .. maxBound :: JointKind]] ++ "), bodies (b -1: the world), anchors, settings, impulses"
    , "  joint: { " ++ intercalate ", " [jointName k ++ ": " ++ show (fromEnum k) | k <- [minBound .. maxBound :: JointField]] ++ " }, jointStride: " ++ show jointStride ++ ", jointKinds: [" ++ intercalate ", " [show (jsName k) | k <- [minBound .. maxBound :: JointKind]] ++ "],"
    , "  // why addJoint refused a joint, by meta.lastJoint (-1, -2, -3)"
    , "  jointProblems: { " ++ intercalate ", " [show (show c) ++ ": " ++ show (jointProblem c) | c <- [-1, -2, -3]] ++ " },"
    , "  addJoint: addJoint, removeJoint: removeJoint, jointAnchors: jointAnchors,"
    , "  // every joint as curves (Manifold.Joint.jointPaths): body a's walk to its anchor, body b's, the chord, points of three numbers"
    , "  jointPaths: jointPaths, jointPath: { walk: " ++ show (anchorWalkSteps + 1) ++ ", chord: " ++ show (chordSegments + 1) ++ ", points: " ++ show jointPathPoints ++ " },"
    , "  // islands and sleeping (Manifold.Sleep): count them into meta.islandCount; put a body to sleep in an island"
    , "  countIslands: countIslands, setSleeping: setSleeping,"
    , "  // the state's hash (Manifold.StateHash): FNV-1a over [array, the meta counting its rows, numbers a row]"
    , "  hashed: [" ++ intercalate ", " [ "[" ++ show (hashedArray part arrayNames) ++ ", " ++ show (jsName (hashedRows part)) ++ ", " ++ show (hashedStride part) ++ "]" | part <- hashedParts ] ++ "],"
    , "  frameMisfit: " ++ show frameMisfit ++ ","
    , "  defaults: { " ++ intercalate ", " [jsName k ++ ": " ++ show (paramValue defaultParams k) | k <- [minBound .. maxBound :: Param]] ++ " },"
    , "  phases: [" ++ intercalate ", " ["[" ++ show name ++ ", " ++ phaseFunction name ++ "]" | (name, _) <- stagedPhases] ++ "],"
    , "  // what the phases call, each printed once: for profiles, and for tests that optimise all of the step"
    , "  subroutines: [" ++ intercalate ", " ["[" ++ show name ++ ", " ++ name ++ "]" | name <- subroutines] ++ "],"
    , "  step: step, polygonise: polygonise, addBody: addBody, removeBody: removeBody,"
    , "  // a walked geodesic (Manifold.GeodesicPath): path[0] the points walked, then per point [" ++ intercalate ", " (map jsName [minBound .. maxBound :: PathSlot]) ++ "]"
    , "  path: { stride: " ++ show pathStride ++ ", slots: " ++ enumObj PathX ++ " },"
    , "  // what measure and measureBody write into their out array (Manifold.Measures)"
    , "  measures: { size: " ++ show measureSize ++ ", slots: " ++ enumObj KineticEnergy ++ " },"
    , "  measure: measure, measureBody: measureBody,"
    , "  pickBody: pickBody, grab: grab, drag: drag, release: release, geodesic: geodesic"
    , "}"
    ]

-- | The scene keys that set parameters ('sceneKeys'), as a JavaScript
-- array of @{ key, param, default, kind, … }@: the key, the parameter it
-- sets (its name in the engine object's @params@ and @defaults@), the
-- value a scene without it gets, its kind (@"switch"@ or @"number"@; the
-- values it takes are the scene format's, "Manifold.SceneFormat", which the
-- page's scene reader and @setSimulation@ check), for a key whose default
-- follows the step @perStep@ ('perStepDefault'), and the control the page
-- makes for it (@control: { label, help, lo, hi, step }@, 'keyControl').
sceneKeysArray :: String
sceneKeysArray = "[\n" ++ concatMap entry sceneKeys ++ "]"
  where
    entry k = "  { " ++ intercalate ", " [ f ++ ": " ++ v | (f, v) <- fields k ++ control k ] ++ " },\n"
    control k = case keyControl k of
      Nothing -> []
      Just c -> [("control", "{ " ++ intercalate ", " (["label: " ++ show (controlLabel c), "help: " ++ show (controlHelp c)] ++ slider c) ++ " }")]
    slider c = case controlSlider c of
      Nothing -> []
      Just (lo, hi, step) -> ["lo: " ++ show lo, "hi: " ++ show hi, "step: " ++ show step]
    fields k =
      [ ("key", show (keyName k)), ("param", show (jsName (keyParam k)))
      , ("default", let x = paramValue defaultParams (keyParam k) in case keyRange k of
            Switch -> if x > 0 then "true" else "false"
            _ -> show x) ]
      ++ [ ("perStep", show x) | Just x <- [perStepDefault (keyParam k)] ]
      ++ [ ("kind", show (if keyRange k == Switch then "switch" else "number" :: String)) ]

-- | A joint field's name as the page's key, without its @J@:
-- @JRadiusA@ → @radiusA@, @JA@ → @a@, @R@-less fields as 'jsName'.
jointName :: JointField -> String
jointName k = case show k of
  'J' : c : cs | isAsciiUpper c -> toLower c : cs
  _ -> jsName k

-- | The remembered row's fields that a kept contact row carries, in the
-- order a saved scene lists them after its impulses ('keptFields').
keptFieldsArray :: String
keptFieldsArray = "[" ++ intercalate ", " [show (jsName f) | (_, f) <- keptFields] ++ "]"

-- | A constructor's name as the page's key: @GravityOn@ → @gravityOn@.
jsName :: Show a => a -> String
jsName k = case show k of
  c : cs -> toLower c : cs
  [] -> []
