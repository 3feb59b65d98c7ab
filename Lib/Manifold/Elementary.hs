{-# LANGUAGE BangPatterns #-}
-- | The engine's own sine, cosine, arctangent and exponential: argument
-- reduction and polynomials over the operations every backend rounds as
-- IEEE 754 says (@+@, @−@, @×@, @÷@, @floor@ and a comparison), so that the
-- native steps and the page's JavaScript compute the same bits.
--
-- The platforms' own functions differ: glibc's libm (natively) and V8's
-- port of fdlibm (in the page) round some arguments differently in the last
-- bit, and a pile's contacts amplify a last-bit difference into another
-- run within a few hundred steps. The scalar class's 'Manifold.Field.sinF',
-- 'Manifold.Field.cosF', 'Manifold.Field.atanF' and 'Manifold.Field.expF'
-- are these kernels: natively at 'Double', printed once as functions of
-- the page's script, differentiated by the chain rule.
--
-- The kernels are written against 'Exact' (the floor and the comparison of
-- a scalar) rather than the scalar class, which is defined in terms of
-- them. Their constants are derived here from π and log 2 as exact
-- rationals, not typed in.
module Manifold.Elementary
  ( Exact (..)
  , exact
  , Polynomial
  , hornerVector
  , sinWith
  , cosWith
  , atanWith
  , expWith
  , expParts
  , splitBits
  , halfPiParts
  , ln2Parts
  ) where

import Data.List (foldl')
import Data.Ratio ((%))
import qualified Data.Vector.Unboxed as U

-- $setup
-- GHCi loads this module as object code (the scalar class, which imports
-- it, has unboxed tuples), so the examples see its exports through this
-- import:
--
-- >>> import Manifold.Elementary

-- | What the kernels need of a scalar beyond 'Fractional': an exact floor,
-- @select c t e@ (@t@ where @c > 0@, else @e@; see "Manifold.Field") and
-- a 'Double' constant as a scalar. The kernels' constants are 'Double's
-- computed once (natively they are plain numbers; staged, literals).
data Exact a = Exact
  { exactFloor :: a -> a
  , exactSelect :: a -> a -> a -> a
  , exactConstant :: Double -> a
  , exactPolynomial :: Polynomial -> a -> a -- ^ 'horner', as the scalar does it fastest
  }

-- | 'Exact' from a floor, a select and the constants, its polynomials by
-- 'hornerWith'.
exact :: Fractional a => (a -> a) -> (a -> a -> a -> a) -> (Double -> a) -> Exact a
{-# INLINE exact #-}
exact fl sel k = Exact fl sel k (hornerWith k . polyCoefficients)

-- | A polynomial's coefficients from the constant term up, also as an
-- unboxed vector (natively evaluated from that: 'hornerVector').
data Polynomial = Polynomial
  { polyCoefficients :: [Double]
  , polyVector :: U.Vector Double
  }

-- | The polynomial of these coefficients.
polynomial :: [Double] -> Polynomial
polynomial cs = Polynomial cs (U.fromList cs)

-- | 'horner' at 'Double' over the vector: the same operations in the same
-- order as 'hornerWith', in a loop of unboxed numbers.
hornerVector :: Polynomial -> Double -> Double
hornerVector p z = U.foldr' (\c acc -> c + z * acc) 0 (polyVector p)

-- | π to 70 digits.
piRational :: Rational
piRational = 31415926535897932384626433832795028841971693993751058209749445923078164 % (10 ^ (70 :: Int))

-- | log 2 to 70 digits.
ln2Rational :: Rational
ln2Rational = 6931471805599453094172321214581765680755001819295334415754375836930451 % (10 ^ (70 :: Int))

-- | @splitBits n k r@: @r@ (positive) as @k@ doubles, each of the first
-- @k − 1@ the next @n@ significant bits of what is left and the last the
-- rest rounded. A multiple @m·part@ of one of the first parts is exact for
-- whole @|m| < 2^(53 − n)@, which is what Cody and Waite's argument
-- reduction needs.
--
-- >>> let [a, b, c] = splitBits 33 3 (toRational (pi :: Double)) in a + b + c == (pi :: Double)
-- True
splitBits :: Int -> Int -> Rational -> [Double]
splitBits n k r
  | k <= 1 = [fromRational r]
  | otherwise =
      let e = magnitude r
          scale = 2 ^^ (n - e) :: Rational
          part = fromInteger (floor (r * scale)) / scale
      in fromRational part : splitBits n (k - 1) (r - part)
  where
    -- the e with 2^(e−1) <= r < 2^e
    magnitude x = head [e | e <- [-1100 :: Int ..], 2 ^^ e > x]

-- | π/2 in three parts of 33, 33 and 53 bits: an argument's multiple of π/2
-- comes off exactly for quadrants up to 2^20 (arguments to about 1.6e6).
halfPiParts :: (Double, Double, Double)
halfPiParts = case splitBits 33 3 (piRational / 2) of
  [a, b, c] -> (a, b, c)
  _ -> error "halfPiParts"

-- | log 2 in two parts, of 40 and 53 bits (multiples up to 2^13 exact).
ln2Parts :: (Double, Double)
ln2Parts = case splitBits 40 2 ln2Rational of
  [a, b] -> (a, b)
  _ -> error "ln2Parts"

factorial :: Integer -> Integer
factorial n = product [1 .. n]

-- | The Taylor coefficients of sine after the first, @−1/3!, 1/5!, …, 1/17!@
-- (the first left out is below 1e-19 of the value on [−π/4, π/4]).
sinCoefficients :: Polynomial
sinCoefficients = polynomial [fromRational ((-1) ^ k % factorial (2 * k + 1)) | k <- [1 .. 8 :: Integer]]

-- | Cosine's from the third on, @1/4!, −1/6!, …, −1/18!@.
cosCoefficients :: Polynomial
cosCoefficients = polynomial [fromRational ((-1) ^ k % factorial (2 * k)) | k <- [2 .. 9 :: Integer]]

-- | @horner [c0, c1, …] z = c0 + z·(c1 + z·(…))@.
horner :: Exact a -> Polynomial -> a -> a
{-# INLINE horner #-}
horner = exactPolynomial

-- | 'horner' by the constants' conversion: a recursion of its own that
-- captures nothing, so that natively a call allocates no closure.
hornerWith :: Fractional a => (Double -> a) -> [Double] -> a -> a
{-# SPECIALISE hornerWith :: (Double -> Double) -> [Double] -> Double -> Double #-}
hornerWith k (c : rest) z = let !acc = hornerWith k rest z in k c + z * acc
hornerWith _ [] _ = 0

-- | @2/π@, the quadrant's scale.
twoOverPi :: Double
twoOverPi = fromRational (2 / piRational)

-- | The argument reduced to @[−π/4, π/4]@ and its quadrant, 0 to 3.
reduceQuarter :: Fractional a => Exact a -> a -> (a, a)
{-# INLINE reduceQuarter #-}
reduceQuarter ops x =
  let k = exactConstant ops
      (p1, p2, p3) = halfPiParts
      n = exactFloor ops (x * k twoOverPi + 0.5)
      r = ((x - n * k p1) - n * k p2) - n * k p3
      quadrant = n - 4 * exactFloor ops (n * 0.25)
  in (r, quadrant)

-- | Sine and cosine of the reduced argument.
sinCosKernel :: Fractional a => Exact a -> a -> (a, a)
{-# INLINE sinCosKernel #-}
sinCosKernel ops r =
  let z = r * r
      s = r + r * z * horner ops sinCoefficients z
      -- 1 − z/2 rounded, then what that rounding lost added back with the tail
      half = 0.5 * z
      w = 1 - half
      c = w + (((1 - w) - half) + z * z * horner ops cosCoefficients z)
  in (s, c)

-- | One of four values by quadrant (0, 1, 2, 3).
byQuadrant :: Fractional a => Exact a -> a -> a -> a -> a -> a -> a
{-# INLINE byQuadrant #-}
byQuadrant ops q a b c d =
  let sel = exactSelect ops
  in sel (q - 2.5) d (sel (q - 1.5) c (sel (q - 0.5) b a))

-- | The sine.
--
-- >>> let ops = exact (fromInteger . floor) (\c t e -> if c > 0 then t else e) id
-- >>> map (sinWith ops) [0, pi / 6, 1e6] :: [Double]
-- [0.0,0.49999999999999994,-0.34999350217129294]
sinWith :: Fractional a => Exact a -> a -> a
{-# INLINE sinWith #-}
sinWith ops x =
  let (!r, !q) = reduceQuarter ops x
      (!s, !c) = sinCosKernel ops r
  in byQuadrant ops q s c (negate s) (negate c)

-- | The cosine.
cosWith :: Fractional a => Exact a -> a -> a
{-# INLINE cosWith #-}
cosWith ops x =
  let (!r, !q) = reduceQuarter ops x
      (!s, !c) = sinCosKernel ops r
  in byQuadrant ops q c (negate s) (negate c) s

-- | The arctangent's Taylor coefficients after the first, @−1/3, 1/5, …, −1/21@
-- (enough on @[−1/8, 1/8]@).
atanCoefficients :: Polynomial
atanCoefficients = polynomial [fromRational ((-1) ^ k % (2 * k + 1)) | k <- [1 .. 10 :: Integer]]

-- | @atan (i/4)@ for @i = 0 … 4@, each as a double and what it leaves off,
-- from the series of the exact rational (to far below a double's last bit).
atanQuarters :: [(Double, Double)]
atanQuarters = [hiLo (atanRational (i % 4)) | i <- [0 .. 4]]
  where
    hiLo v = let hi = fromRational v in (hi, fromRational (v - toRational hi))
    -- atan 1 = π/4; the others by their series, which converges for |t| < 1
    atanRational t
      | t == 1 = piRational / 4
      | otherwise = sum [(-1) ^ k * t ^ (2 * k + 1) / fromInteger (2 * k + 1) | k <- [0 .. 120 :: Integer]]

-- | For each quarter @i@: @i − 1/2@ (the arguments from which it is the
-- nearest), and its value's two parts.
atanTable :: [(Double, Double, Double)]
atanTable = [(fromInteger i - 0.5, hi, lo) | (i, (hi, lo)) <- zip [0 ..] atanQuarters]

-- | π/2 as a double and what it leaves off (twice @atan 1@'s parts).
halfPiHiLo :: (Double, Double)
halfPiHiLo = case atanQuarters of
  _ : _ : _ : _ : (qHi, qLo) : _ -> (2 * qHi, 2 * qLo)
  _ -> error "atanQuarters"

-- | The arctangent, in @[−π/2, π/2]@: @|t| > 1@ is turned into @1/|t|@
-- (@atan t = π/2 − atan (1/t)@), and what is left is taken from the
-- nearest quarter @c = i/4@ by @atan t = atan c + atan ((t − c)/(1 + t·c))@,
-- whose second argument is at most 1/8.
--
-- >>> let ops = exact (fromInteger . floor) (\c t e -> if c > 0 then t else e) id
-- >>> map (atanWith ops) [0, 1, -1e300] :: [Double]
-- [0.0,0.7853981633974483,-1.5707963267948966]
atanWith :: Fractional a => Exact a -> a -> a
{-# INLINE atanWith #-}
atanWith ops t =
  let sel = exactSelect ops
      k = exactConstant ops
      a = abs t
      big = a - 1
      u = sel big (1 / a) a
      i = exactFloor ops (4 * u + 0.5)
      c = i * 0.25
      v = (u - c) / (1 + u * c)
      -- the quarter's value: the last whose index i passes
      pickQuarter part = foldl' (\acc (from, hi, lo) -> sel (i - k from) (k (part hi lo)) acc) 0 atanTable
      small = pickQuarter const + (pickQuarter (\_ lo -> lo) + (v + v * (v * v) * horner ops atanCoefficients (v * v)))
      (halfPiHi, halfPiLo) = halfPiHiLo
      whole = sel big ((k halfPiHi - small) + k halfPiLo) small
  in sel (negate t) (negate whole) whole

-- | The exponential's Taylor coefficients, @1/0!, …, 1/14!@ (enough on
-- @[−log 2 / 2, log 2 / 2]@).
expCoefficients :: Polynomial
expCoefficients = polynomial [fromRational (1 % factorial k) | k <- [0 .. 14]]

-- | @1 / log 2@, the exponent's scale.
inverseLn2 :: Double
inverseLn2 = fromRational (1 / ln2Rational)

-- | @(2^(2^k), 2^(−2^k))@ for the bits @k = 0 … 9@ of an exponent.
powersOfTwo :: [(Double, Double)]
powersOfTwo = [(2 ^^ (2 ^ k :: Int), 2 ^^ negate (2 ^ k :: Int)) | k <- [0 .. 9 :: Int]]

-- | The exponential's two parts: @e^r@ (its series) and the whole @n@, with
-- @x = n·log 2 + r@ and @|r| <= log 2 / 2@ ('expWith' multiplies them by
-- @2^n@). Where @e^r·2^n@ is a normal number every product of that is
-- exact, so natively one multiplication by @2^n@ gives the same bits.
expParts :: Fractional a => Exact a -> a -> (a, a)
{-# INLINE expParts #-}
expParts ops x0 =
  let sel = exactSelect ops
      k = exactConstant ops
      clamped = sel (x0 - 710) 710 (sel (-746 - x0) (-746) x0)
      (l1, l2) = ln2Parts
      !n = exactFloor ops (clamped * k inverseLn2 + 0.5)
      !r = (clamped - n * k l1) - n * k l2
  in (horner ops expCoefficients r, n)

-- | The exponential: @x = n·log 2 + r@ with @|r| <= log 2 / 2@, the series
-- at @r@, then multiplied by @2^n@ bit by bit of @n@ (each factor a power
-- of two, so the products are exact while they are normal numbers).
-- Arguments beyond @[−746, 710]@, where the result is 0 or infinite, are
-- clamped to it first.
--
-- >>> let ops = exact (fromInteger . floor) (\c t e -> if c > 0 then t else e) id
-- >>> map (expWith ops) [0, 1, -1000, 1000] :: [Double]
-- [1.0,2.7182818284590455,0.0,Infinity]
expWith :: Fractional a => Exact a -> a -> a
{-# INLINE expWith #-}
expWith ops x0 =
  let sel = exactSelect ops
      fl = exactFloor ops
      k = exactConstant ops
      (!series, !n) = expParts ops x0
      -- the bits of |n| from the lowest, each times its factor: m is what
      -- is left of |n| above the bit
      scale y m ((up, down) : powers) =
        let m' = fl (m * 0.5)
            bit = m - 2 * m'
        in y `seq` m `seq` scale (sel (bit - 0.5) (y * sel n (k up) (k down)) y) m' powers
      scale y m [] = (y, m)
      (scaled, rest) = scale series (sel n n (negate n)) powersOfTwo
      -- 2^±1024 is no double: bit 10 is two factors of 2^±512
      half = sel (rest - 0.5) (sel n (k (2 ^^ (512 :: Int))) (k (2 ^^ (-512 :: Int)))) 1
  in scaled * half * half
