{-# LANGUAGE DeriveFunctor #-}
-- | The printed code as data: what the staged interpretation of
-- "Manifold.Stage.Imp" produces and what every printer consumes — the
-- JavaScript and Haskell text printers of "Manifold.Stage.Print" and the
-- Template Haskell of "Manifold.Stage.Splice".
--
-- A staged expression graph ('Manifold.Stage.Expr.E') is lowered to a
-- 'Term': nodes bound to names are 'TVar's, the rest are inlined. Statements
-- are what the 'Manifold.Stage.Imp.Imp' class can do: bind, read, write,
-- loop, branch, call. A tree is made for one kind of output (a
-- 'Manifold.Stage.Print.Target'):
-- the page's JavaScript keeps its mutable locals as variables and indexes
-- arrays with numbers; the native code keeps locals as slots of an array,
-- indexes with 'Int' arithmetic and checks each row of an array once.
module Manifold.Stage.Code
  ( Term (..)
  , IntTerm (..)
  , LinearIndex
  , ArrayIndex (..)
  , Stmt (..)
  , Function (..)
  , Check
  , calledNames
  , literalTerm
  , termLiteral
  ) where

import Data.Word (Word64)
import GHC.Float (castDoubleToWord64, castWord64ToDouble)

import Manifold.Stage.Expr (Op1, Op2)

-- | A number-valued expression.
data Term
  = TLit !Word64 -- ^ a literal, by bit pattern (so NaN equals itself and -0 is not 0)
  | TVar String -- ^ a parameter or a name bound earlier
  | TUn Op1 Term
  | TBin Op2 Term Term
  | TSel Term Term Term -- ^ @c > 0 ? t : e@
  | TCounter String -- ^ a loop's 'Int' counter as a number (native code only)
  deriving (Show, Eq, Ord)

-- | A literal term of a 'Double' (by its bits: 'TLit').
--
-- >>> literalTerm (0 / 0) == literalTerm (0 / 0)
-- True
-- >>> literalTerm 0 == literalTerm (-0)
-- False
literalTerm :: Double -> Term
literalTerm = TLit . castDoubleToWord64

-- | The 'Double' a 'TLit' holds.
termLiteral :: Word64 -> Double
termLiteral = castWord64ToDouble

-- | Whole-number arithmetic in 'Int' (native array indices).
data IntTerm
  = ILit Int
  | ICounter String -- ^ a loop's counter
  | ITrunc Term -- ^ a number holding a whole number, truncated
  | IAdd IntTerm IntTerm
  | ISub IntTerm IntTerm
  | IMul IntTerm IntTerm
  | INeg IntTerm
  deriving (Show, Eq, Ord)

-- | A sum of terms with whole coefficients, in printing order: the base of
-- a row of an array, which one check covers at several offsets.
type LinearIndex = [(IntTerm, Int)]

-- | An array index.
data ArrayIndex
  = NumberIndex Term -- ^ JavaScript: the index as a number (printed in 32-bit integers)
  | IntIndex LinearIndex Int -- ^ native: a base and a constant offset
  deriving (Show, Eq, Ord)

-- | A statement. @c@ is what a row check holds: an identifier while the
-- function is being staged (its offsets are known only once its block is
-- complete), then the lowest and highest offset it covers ('Check').
data Stmt c
  = Let String Term -- ^ a constant: @const n = e;@, @let !n = e@
  | Load String String ArrayIndex -- ^ @n@ is read from an array
  | Store String ArrayIndex Term -- ^ an array element is written
  | Declare String Term -- ^ a mutable local (JavaScript's @let@)
  | Assign String Term -- ^ a mutable local is written
  | For String Term Term [Stmt c] -- ^ counter, from, below, body
  | If Term [Stmt c] [Stmt c] -- ^ where the term is positive, else
  | RowCheck String LinearIndex c -- ^ native: the array holds the row's offsets
  | Call String [String] [Term] -- ^ a subroutine, with the arrays and arguments
  deriving (Show, Eq, Functor)

-- | The subroutines a function calls, by name, in order (with repeats).
calledNames :: Function c -> [String]
calledNames = concatMap calls . fnBody
  where
    calls (Call n _ _) = [n]
    calls (For _ _ _ body) = concatMap calls body
    calls (If _ t e) = concatMap calls t ++ concatMap calls e
    calls _ = []

-- | A completed row check: the offsets it covers, lowest and highest.
type Check = (Int, Int)

-- | A printed function over arrays and number parameters (returning
-- nothing: its results go into the arrays).
data Function c = Function
  { fnName :: String
  , fnArrays :: [String]
  , fnScalars :: [String]
  , fnBody :: [Stmt c]
  } deriving (Show, Eq, Functor)
