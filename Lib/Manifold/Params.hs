-- | The engine's parameters, defined once: the record a native world is
-- set with, its defaults, where each parameter sits in the world's
-- parameter array, and the scene keys that set them with the values they
-- take. The page's engine object carries the slots, the defaults and the
-- scene keys with their ranges and messages, generated from here
-- ("Manifold.Stage.EngineScript"); the page's scene reader checks a scene
-- with them.
module Manifold.Params
  ( Params (..)
  , defaultParams
  , paramValue
  , setParam
  , writeParams
    -- * Scene keys
  , SceneKey (..)
  , Range (..)
  , Control (..)
  , sceneKeys
  , perStepDefault
  , materialKeys
  , bodyKeys
  ) where

import qualified Data.Vector.Unboxed.Mutable as MV

import Manifold.World (Param (..), WorldArrays (..))

-- | The engine's parameters.
data Params = Params
  { pDt :: Double
  , pGravity :: Bool
  , pSubsteps :: Int -- ^ sub-steps a step (each: gravity, warm start, solve, move, relax)
  , pIterations :: Int -- ^ solves with the bias in each sub-step
  , pFriction :: Double
  , pRestitution :: Double
  , pContactHertz :: Double -- ^ a contact's stiffness, as a spring's frequency (twice this against static bodies and walls)
  , pDampingRatio :: Double -- ^ a contact spring's damping ratio
  , pPushout :: Double -- ^ the fastest a contact pushes overlapping bodies apart
  , pSlop :: Double -- ^ the overlap left alone, as a fraction of the smaller body's size
  , pSpeculative :: Double -- ^ how far apart outlines make contact rows, as a fraction of the smaller body's size
  , pBounceThreshold :: Double -- ^ approach speeds below this do not bounce
  , pWarmStart :: Bool -- ^ start each contact from its last step's impulses
  , pPolygonStep :: Double -- ^ bodies up to this size walk their outline in one geodesic step (0: never)
  , pJointHertz :: Double -- ^ how stiff a rigid joint row is, as a spring's frequency (at most a quarter of the sub-step rate)
  , pJointDampingRatio :: Double -- ^ a rigid joint row's damping ratio
  , pSleep :: Bool -- ^ islands at rest fall asleep ("Manifold.Sleep")
  , pSleepSpeed :: Double -- ^ a body moving slower than this many of its sizes a second (and turning slower than this many radians) is calm
  , pSleepTime :: Double -- ^ how long an island's bodies are calm before it sleeps (s)
  , pKeepContacts :: Bool -- ^ a pair that has hardly moved keeps last step's contact points ("Manifold.Collide")
  } deriving (Show, Eq)

-- | What a world starts with and a scene gets for a key it leaves out
-- (but see 'perStepDefault'): four sub-steps of one solve each, and
-- contacts as springs of 60 Hz with a damping ratio of 10: Box2D v3's 30 Hz
-- and 10 made as stiff, for a body's size, as they are in Box2D's units (a
-- spring's sag under weight, g/ω², against 1 m boxes under 10 m/s² there,
-- 0.03–0.2 here under 4; see docs/decisions/soft-step.md).
defaultParams :: Params
defaultParams = Params
  { pDt = 0.01, pGravity = True, pSubsteps = 4, pIterations = 1, pFriction = 0.4, pRestitution = 0
  , pContactHertz = 60, pDampingRatio = 10, pPushout = 0.5, pSlop = 0.001, pSpeculative = 0.02
  , pBounceThreshold = 0.5, pWarmStart = True, pPolygonStep = 0.05
  , pJointHertz = 120, pJointDampingRatio = 2
  , pSleep = True, pSleepSpeed = 0.05, pSleepTime = 0.5, pKeepContacts = True }

-- | A parameter as the world's parameter array holds it (a switch is 1 or 0).
paramValue :: Params -> Param -> Double
paramValue p = \case
  Dt -> pDt p
  GravityOn -> switch (pGravity p)
  Substeps -> fromIntegral (pSubsteps p)
  Iterations -> fromIntegral (pIterations p)
  Friction -> pFriction p
  Restitution -> pRestitution p
  ContactHertz -> pContactHertz p
  DampingRatio -> pDampingRatio p
  Pushout -> pPushout p
  Slop -> pSlop p
  Speculative -> pSpeculative p
  BounceThreshold -> pBounceThreshold p
  WarmStart -> switch (pWarmStart p)
  PolygonStep -> pPolygonStep p
  JointHertz -> pJointHertz p
  JointDampingRatio -> pJointDampingRatio p
  Sleep -> switch (pSleep p)
  SleepSpeed -> pSleepSpeed p
  SleepTime -> pSleepTime p
  KeepContacts -> switch (pKeepContacts p)
  where switch b = if b then 1 else 0

-- | A parameter set to a value as the parameter array would hold it (the
-- inverse of 'paramValue'; a switch is on above 0, a count is rounded).
setParam :: Param -> Double -> Params -> Params
setParam k x p = case k of
  Dt -> p { pDt = x }
  GravityOn -> p { pGravity = x > 0 }
  Substeps -> p { pSubsteps = round x }
  Iterations -> p { pIterations = round x }
  Friction -> p { pFriction = x }
  Restitution -> p { pRestitution = x }
  ContactHertz -> p { pContactHertz = x }
  DampingRatio -> p { pDampingRatio = x }
  Pushout -> p { pPushout = x }
  Slop -> p { pSlop = x }
  Speculative -> p { pSpeculative = x }
  BounceThreshold -> p { pBounceThreshold = x }
  WarmStart -> p { pWarmStart = x > 0 }
  PolygonStep -> p { pPolygonStep = x }
  JointHertz -> p { pJointHertz = x }
  JointDampingRatio -> p { pJointDampingRatio = x }
  Sleep -> p { pSleep = x > 0 }
  SleepSpeed -> p { pSleepSpeed = x }
  SleepTime -> p { pSleepTime = x }
  KeepContacts -> p { pKeepContacts = x > 0 }

-- | Set a world's parameter array.
writeParams :: WorldArrays (MV.IOVector Double) -> Params -> IO ()
writeParams w p = mapM_ (\k -> MV.write (wParams w) (fromEnum k) (paramValue p k)) [minBound .. maxBound]

-- Scene keys -----------------------------------------------------------------

-- | A key of a scene file that sets a parameter.
data SceneKey = SceneKey
  { keyName :: String
  , keyParam :: Param
  , keyRange :: Range
  , keyControl :: Maybe Control -- ^ the page's control for it, if the page offers one
  } deriving (Show, Eq)

-- | The values a scene key takes.
data Range
  = Switch -- ^ @true@ or @false@
  | Positive -- ^ a number above 0
  | NonNegative -- ^ a number, 0 or above
  | Fraction -- ^ a number from 0 to 1
  | Count Int -- ^ a whole number from 1 to this
  deriving (Show, Eq)

-- | How the page offers a key: a checkbox for a switch, a slider for a
-- number (its ends and step; the key's 'Range' still decides what
-- @setSimulation@ and a scene may set).
data Control = Control
  { controlLabel :: String -- ^ what the control is called
  , controlHelp :: String -- ^ what it does (the control's tooltip)
  , controlSlider :: Maybe (Double, Double, Double) -- ^ a number's slider: from, to, step
  } deriving (Show, Eq)

-- | The parameters a scene sets, in the order a scene is written (and the
-- page shows their controls); a key left out keeps its 'defaultParams'
-- value.
sceneKeys :: [SceneKey]
sceneKeys =
  [ SceneKey "dt" Dt Positive Nothing
  , SceneKey "gravity" GravityOn Switch (Just (Control "Gravity" "the space's gravity, projected onto the surface" Nothing))
  , SceneKey "substeps" Substeps (Count 64)
      (slider "Sub-steps" "sub-steps a step, each moving the bodies once: more hold taller stacks, at their cost" 1 16 1)
  , SceneKey "iterations" Iterations (Count 1000) Nothing
  , SceneKey "friction" Friction NonNegative (slider "Friction" "Coulomb friction coefficient of contacts" 0 1 0.05)
  , SceneKey "restitution" Restitution Fraction (slider "Restitution" "bounciness of contacts (0: none, 1: elastic)" 0 1 0.05)
  , SceneKey "contactHertz" ContactHertz Positive
      (slider "Contact Hz" "how stiff a contact is, as a spring's frequency (twice this against static bodies and walls)" 1 120 1)
  , SceneKey "dampingRatio" DampingRatio NonNegative (slider "Damping" "a contact spring's damping ratio" 0 20 0.5)
  , SceneKey "pushout" Pushout Positive (slider "Push-out" "the fastest a contact pushes overlapping bodies apart" 0.05 5 0.05)
  , SceneKey "slop" Slop Fraction Nothing
  , SceneKey "jointHertz" JointHertz Positive
      (slider "Joint Hz" "how stiff a joint is, as a spring's frequency (at most a quarter of the sub-step rate)" 10 400 5)
  , SceneKey "jointDampingRatio" JointDampingRatio NonNegative Nothing
  , SceneKey "sleep" Sleep Switch (Just (Control "Sleep" "islands of bodies at rest fall asleep, costing nothing until touched" Nothing))
  , SceneKey "sleepSpeed" SleepSpeed NonNegative Nothing
  , SceneKey "sleepTime" SleepTime Positive Nothing
  , SceneKey "keepContacts" KeepContacts Switch Nothing
  ]
  where slider label help lo hi step = Just (Control label help (Just (lo, hi, step)))

-- | The default of a scene key that follows the scene's step, as so many
-- of it a step: the contact stiffness, 0.6 cycles a step (60 Hz at the
-- default step of 0.01). A scene scaled by @k@ with its step by @√k@ (the
-- same @g·dt²@ against its bodies' size, as the Solver2D scenes are set at
-- any scale) then has contacts as stiff for its bodies, and behaves alike;
-- a fixed 60 Hz was half as stiff as Box2D's at the scale of 0.05, where
-- Box2D's stacks stand and these sank (docs/decisions/contact-stiffness-per-step.md).
--
-- >>> maybe 0 (/ pDt defaultParams) (perStepDefault ContactHertz) == pContactHertz defaultParams
-- True
perStepDefault :: Param -> Maybe Double
perStepDefault = \case
  ContactHertz -> Just 0.6
  _ -> Nothing

-- | The scene keys a body may give too, as its own material (its friction
-- coefficient and restitution, which it then has instead of the scene's):
-- a body's value takes the scene key's range.
materialKeys :: [SceneKey]
materialKeys = [ k | k <- sceneKeys, keyParam k `elem` [Friction, Restitution] ]

-- | The keys of a scene's body, in the order a saved body lists them (the
-- scene format's, "Manifold.SceneFormat").
bodyKeys :: [String]
bodyKeys = ["shape", "size", "density"] ++ map keyName materialKeys
  ++ ["static", "p", "v", "angle", "omega", "axis", "normal", "impulses", "awake", "island", "sleepTime"]
