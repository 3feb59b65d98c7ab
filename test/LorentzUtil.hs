-- | What the hyperbolic specs (DiscSpec, BolzaSpec) measure boosts and
-- points with: the Minkowski inner product, how far a matrix (nine numbers,
-- row by row) is from keeping it, and matrices compared.
module LorentzUtil
  ( minkowski
  , lorentzDefect
  , identity
  , maxDiff
  ) where

import Linear.V3 (V3 (..))

-- | @a_x b_x − a_y b_y + a_z b_z@.
minkowski :: V3 Double -> V3 Double -> Double
minkowski (V3 a b c) (V3 d e f) = a * d - b * e + c * f

-- | The Lorentz defect of a matrix: the largest entry of Mᵀ J M − J.
lorentzDefect :: [Double] -> Double
lorentzDefect m = maximum [ abs (minkowski (col i) (col j) - jay i j) | i <- [0 .. 2], j <- [0 .. 2] ]
  where
    col j = V3 (m !! j) (m !! (3 + j)) (m !! (6 + j))
    jay i j
      | i /= j = 0
      | i == 1 = -1
      | otherwise = 1

-- | The identity, as nine numbers.
identity :: [Double]
identity = [1, 0, 0, 0, 1, 0, 0, 0, 1]

-- | The largest difference between two matrices' entries.
maxDiff :: [Double] -> [Double] -> Double
maxDiff a b = maximum (zipWith (\x y -> abs (x - y)) a b)
