-- | The engine's own elementary functions ("Manifold.Elementary"): within
-- an ulp of libm, and bit for bit the same natively and in the JavaScript
-- the page runs (the kernels written out in line in its scripts).
module ElementarySpec (spec) where

import Control.Monad (forM_)
import Data.Int (Int64)
import GHC.Float (castDoubleToWord64)
import Data.Word (Word64)
import Test.Hspec

import Manifold.Field
import Manifold.Stage.Expr (E, sym)
import Manifold.Stage.Print (FnType (..), Target (..), printFunction)
import NodeJS

-- | How many doubles lie between two (0 when equal).
ulpsApart :: Double -> Double -> Integer
ulpsApart a b
  | a == b = 0
  | otherwise = abs (ordered a - ordered b)
  where
    ordered x =
      let w = toInteger (fromIntegral (castDoubleToWord64 x) :: Int64)
      in if w < 0 then negate (w + 2 ^ (63 :: Int)) else w

-- | The functions, their libm counterparts, the staged functions and the
-- argument ranges the test draws from.
functions :: [(String, Double -> Double, Double -> Double, E -> E, (Double, Double))]
functions =
  [ ("sine", sinF, sin, sinF, (-1000, 1000))
  , ("cosine", cosF, cos, cosF, (-1000, 1000))
  , ("arctangent", atanF, atan, atanF, (-1e4, 1e4))
  , ("exponential", expF, exp, expF, (-700, 700))
  ]

-- | 20,000 arguments spread over the range (a seeded linear congruential
-- sequence), then the special ones.
arguments :: (Double, Double) -> [Double]
arguments (lo, hi) = take 20000 (map unit (tail (iterate next 2026)))
  ++ [0, -0, 1, -1, 1e-300, 0.5, 2, 1e6, 0 / 0, 1 / 0, -1 / 0]
  where
    next :: Word64 -> Word64
    next w = w * 6364136223846793005 + 1442695040888963407
    unit w = lo + (hi - lo) * fromIntegral (w `div` 2048) / 2 ^ (53 :: Int)

spec :: Spec
spec = do
  it "keeps sine, cosine, arctangent and the exponential within 1 ulp of libm (20,000 seeded arguments each)" $
    forM_ functions $ \(name, own, libm, _, range) -> do
      let worst = maximum [ulpsApart (own x) (libm x) | x <- arguments range, not (isNaN x), not (isInfinite x)]
      (name, worst <= 1) `shouldBe` (name, True)
  it "gives the special values libm gives (NaN, the infinities, overflow and underflow)" $ do
    map (isNaN . sinF) [0 / 0, 1 / 0 :: Double] `shouldBe` [True, True]
    map expF [1 / 0, -1 / 0, 1000, -1000 :: Double] `shouldBe` [1 / 0, 0, 1 / 0, 0]
    map atanF [1 / 0, -1 / 0 :: Double] `shouldBe` [pi / 2, -pi / 2]
  it "computes the same bits in the generated JavaScript under node as natively" $
    forM_ functions $ \(name, own, _, js, range) -> do
      let xs = arguments range
      out <- runNodeJSON (printFunction JavaScript "f" (FnType ["x"] False) [js (sym "x")] ++ "__emit(" ++ jsDoubles xs ++ ".map(f));\n") :: IO [Bits]
      let differing = length [() | (x, Bits y) <- zip xs out, castDoubleToWord64 (own x) /= castDoubleToWord64 y]
      (name, length out, differing) `shouldBe` (name, length xs, 0)
