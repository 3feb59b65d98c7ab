{-# LANGUAGE FlexibleContexts #-}
-- | Running the world natively and printing it as the page's JavaScript.
module Manifold.Engine
  ( NativeWorld (..)
  , BodyInit (..)
  , newWorld
  , addBody
  , stepNative
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
import Manifold.World

data NativeWorld = NativeWorld
  { nwSpace :: Space
  , nwLayout :: Layout
  , nwArrays :: WorldArrays NativeArray
  }

newWorld :: Space -> Layout -> IO NativeWorld
newWorld sp l = do
  let s = arraySizes l
      alloc n = MV.replicate n 0
  arrays <- WorldArrays <$> alloc (wMeta s) <*> alloc (wPos s) <*> alloc (wVel s) <*> alloc (wAxis s)
                        <*> alloc (wNormal s) <*> alloc (wScalars s) <*> alloc (wRadii s) <*> alloc (wVerts s)
  pure (NativeWorld sp l arrays)

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

bodyCount :: NativeWorld -> IO Int
bodyCount w = truncate <$> MV.read (wMeta (nwArrays w)) 0

warningCount :: NativeWorld -> IO Int
warningCount w = truncate <$> MV.read (wMeta (nwArrays w)) 1

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
    MV.write (wMeta a) 0 (fromIntegral (i + 1))
    runNative (polygoniseAll sp (nwLayout w) a)
    pure (Right i)

-- | One step of time @dt@.
stepNative :: NativeWorld -> Double -> Bool -> IO ()
stepNative w dt gravityOn = runNative $ do
  stepFree (nwSpace w) (nwArrays w) dt (if gravityOn then 1 else 0)
  polygoniseAll (nwSpace w) (nwLayout w) (nwArrays w)

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
stagedArrays = let n = arrayNames in
  WorldArrays (StagedArray (wMeta n)) (StagedArray (wPos n)) (StagedArray (wVel n)) (StagedArray (wAxis n))
              (StagedArray (wNormal n)) (StagedArray (wScalars n)) (StagedArray (wRadii n)) (StagedArray (wVerts n))

worldParams :: [String]
worldParams = let n = arrayNames in [wMeta n, wPos n, wVel n, wAxis n, wNormal n, wScalars n, wRadii n, wVerts n]

-- | The engine's procedures for one space, as JavaScript functions.
engineProcedures :: Space -> Layout -> [String]
engineProcedures sp l =
  [ stageProcedure (JsProcedure "stepFree" worldParams ["dt", "gravityOn"])
      (\_ [dt, g] -> stepFree sp stagedArrays dt g)
  , stageProcedure (JsProcedure "polygonise" worldParams [])
      (\_ _ -> polygoniseAll sp l stagedArrays)
  ]

engineScript :: Space -> Layout -> String
engineScript sp l = unlines (engineProcedures sp l)
