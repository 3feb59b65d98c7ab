-- | The engine's parameters: the record a native world is set with, its
-- defaults, and where each parameter sits in the world's parameter array
-- (the page's engine object lists the same slots and defaults, generated
-- from here).
module Manifold.Params
  ( Params (..)
  , defaultParams
  , paramValue
  , writeParams
  ) where

import qualified Data.Vector.Unboxed.Mutable as MV

import Manifold.World (Param (..), WorldArrays (..))

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

-- | What a world starts with and a scene gets for a key it leaves out.
defaultParams :: Params
defaultParams = Params
  { pDt = 0.01, pGravity = True, pIterations = 8, pFriction = 0.4, pRestitution = 0
  , pBaumgarte = 0.1, pSlop = 0.002, pBounceThreshold = 0.5, pWarmStart = True
  , pMaxCorrection = 0.5, pPolygonStep = 0.05 }

-- | A parameter as the world's parameter array holds it (a switch is 1 or 0).
paramValue :: Params -> Param -> Double
paramValue p = \case
  Dt -> pDt p
  GravityOn -> switch (pGravity p)
  Iterations -> fromIntegral (pIterations p)
  Friction -> pFriction p
  Restitution -> pRestitution p
  Baumgarte -> pBaumgarte p
  Slop -> pSlop p
  BounceThreshold -> pBounceThreshold p
  WarmStart -> switch (pWarmStart p)
  MaxCorrection -> pMaxCorrection p
  PolygonStep -> pPolygonStep p
  where switch b = if b then 1 else 0

-- | Set a world's parameter array.
writeParams :: WorldArrays (MV.IOVector Double) -> Params -> IO ()
writeParams w p = mapM_ (\k -> MV.write (wParams w) (fromEnum k) (paramValue p k)) [minBound .. maxBound]
