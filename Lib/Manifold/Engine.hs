{-# LANGUAGE FlexibleContexts #-}
-- | Running the world natively and printing it as the page's JavaScript.
module Manifold.Engine
  ( NativeWorld (..)
  , BodyInit (..)
  , newWorld
  , addBody
  , stepNative
  , Params (..)
  , defaultParams
  , setParams
  , contactCount
  , bodyCount
  , warningCount
  , readBody
  , BodyState (..)
  , engineScript
  , engineProcedures
  ) where

import Control.Monad (forM_)
import qualified Data.Vector.Unboxed.Mutable as MV
import Linear.Metric (norm)
import Linear.V3 (V3 (..))

import Manifold.Body
import Manifold.Space
import Manifold.Stage.Imp
import Manifold.Surface
import Manifold.Step (step)
import Manifold.World
import Data.Foldable (toList)

data NativeWorld = NativeWorld
  { nwSpace :: Space
  , nwLayout :: Layout
  , nwArrays :: WorldArrays NativeArray
  }

newWorld :: Space -> Layout -> IO NativeWorld
newWorld sp l = do
  let s = arraySizes l
      alloc n = MV.replicate n 0
  arrays <- traverse alloc s
  let w = NativeWorld sp l arrays
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
  } deriving (Show, Eq)

defaultParams :: Params
defaultParams = Params
  { pDt = 0.01, pGravity = True, pIterations = 8, pFriction = 0.4, pRestitution = 0
  , pBaumgarte = 0.1, pSlop = 0.002, pBounceThreshold = 0.5 }

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
-- Returns the body's index, or an error.
addBody :: NativeWorld -> BodyInit -> IO (Either String Int)
addBody w b = do
  let sp = nwSpace w
      f = spaceField sp
      a = nwArrays w
      p = projectToSurface f (biPos b)
      n = unitNormal f p
  i <- bodyCount w
  if i >= capacity (nwLayout w) then pure (Left ("the world is full (capacity " ++ show (capacity (nwLayout w)) ++ ")"))
  else if any isNaN p || norm n < 0.5 then pure (Left "the body's position does not project onto the surface")
  else do
    let v = tangentProjection n (biVel b)
        ax1 = tangentProjection n (V3 1 0 0)
        ax2 = tangentProjection n (V3 0 0 1)
        axis = safeNormalize (if norm ax1 > 0.5 then ax1 else ax2)
        MassProperties m inertia' = massProperties (biShape b) (biSize b) (biDensity b)
        inv x = if biStatic b || x <= 0 then 0 else 1 / x
        write3 :: NativeArray -> V3 Double -> IO ()
        write3 arr (V3 x y z) = forM_ (zip [0 ..] [x, y, z]) $ \(k, c) -> MV.write arr (3 * i + k) c
        setSlot :: Slot -> Double -> IO ()
        setSlot s x = MV.write (wScalars a) (scalarSlots * i + fromEnum s) x
    write3 (wPos a) p
    write3 (wVel a) (if biStatic b then V3 0 0 0 else v)
    write3 (wAxis a) axis
    write3 (wNormal a) n
    setSlot Angle (biAngle b)
    setSlot Omega (if biStatic b then 0 else biOmega b)
    setSlot InvMass (inv m)
    setSlot InvInertia (inv inertia')
    setSlot Size (biSize b)
    setSlot BoundRadius (biSize b)
    let Outline outline = shapeOutline (biShape b)
    runNative (outlineRadiiInto (nwLayout w) outline a i (biSize b))
    MV.write (wMeta a) (fromEnum BodyCount) (fromIntegral (i + 1))
    MV.write (wBodyPrev a) (2 * i + 1) 0
    runNative (polygoniseAll sp (nwLayout w) a)
    pure (Right i)

-- | One step of the world.
stepNative :: NativeWorld -> IO ()
stepNative w = runNative (stepN (nwSpace w) (nwLayout w) (nwArrays w))

stepN :: Space -> Layout -> WorldArrays NativeArray -> Native ()
stepN = step
{-# NOINLINE stepN #-}

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

stagedArrays :: WorldArrays StagedArray
stagedArrays = fmap StagedArray arrayNames

worldParams :: [String]
worldParams = toList arrayNames

-- | The engine's procedures for one space, as JavaScript functions over the
-- world's arrays.
engineProcedures :: Space -> Layout -> [String]
engineProcedures sp l =
  [ stageProcedure (JsProcedure "step" worldParams []) (\_ _ -> step sp l stagedArrays)
  , stageProcedure (JsProcedure "polygonise" worldParams []) (\_ _ -> polygoniseAll sp l stagedArrays)
  ]

engineScript :: Space -> Layout -> String
engineScript sp l = unlines (engineProcedures sp l)
