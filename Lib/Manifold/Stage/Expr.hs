{-# OPTIONS_GHC -fno-full-laziness -fno-cse #-}
-- (The global node table is read and written with unsafePerformIO; these
-- flags keep GHC from sharing one read of it between calls.)
-- | The code-building scalar: expressions as a hash-consed DAG.
--
-- 'E' is an instance of the scalar class, so every distance field, its AD
-- gradient and every geometry function can be run at 'E' unchanged; the
-- result is a graph of operations, not a number. Sharing is recovered by
-- hash-consing: a node is interned in one global table the moment it is built,
-- so structurally equal subexpressions (which forward AD produces in masses)
-- are the same node, whatever route built them. Constants are folded with the
-- same 'Double' arithmetic the native interpretation uses, and the 0/1
-- identities that AD produces (@0·x@, @x·1@, @x + 0@, ...) are removed.
--
-- The folding treats @0·x@ as @0@ for every @x@: it assumes the values it
-- drops are finite, as a compiler's fast-math mode does.
module Manifold.Stage.Expr
  ( E
  , Node (..)
  , Op1 (..)
  , Op2 (..)
  , nodeOf
  , nodeById
  , nodeId
  , sym
  , lit
  , literalValue
  , children
  , evalOp1
  , evalOp2
  , expandElementary
  ) where

import Data.IORef
import Data.List (foldl')
import qualified Data.IntMap.Strict as IM
import qualified Data.Map.Strict as M
import Data.Word (Word64)
import GHC.Float (castDoubleToWord64, castWord64ToDouble)
import System.IO.Unsafe (unsafePerformIO)

import Manifold.Elementary (atanWith, cosWith, exact, expWith, sinWith)
import Manifold.Field

-- | The one-operand operations: the scalar class's, 'Floor' and the
-- engine's own elementary functions ('SinF' … 'ExpF', "Manifold.Elementary")
-- included.
data Op1
  = Neg | Abs | Sign | Recip | Sqrt | Exp | Log | Sin | Cos | Tan
  | Asin | Acos | Atan | Sinh | Cosh | Tanh | Asinh | Acosh | Atanh | Floor
  | SinF | CosF | AtanF | ExpF
  deriving (Show, Eq, Ord, Enum, Bounded)

-- | The two-operand operations.
data Op2 = Add | Sub | Mul | Div | Pow
  deriving (Show, Eq, Ord, Enum, Bounded)

-- | A node refers to its operands by node id. Literals are kept by bit
-- pattern, so NaN is a key like any other and @-0@ differs from @0@.
data Node
  = Lit !Word64 -- ^ a literal, by its bit pattern
  | Sym !String -- ^ a parameter or a variable bound by generated code
  | Un !Op1 !Int -- ^ an operation on the node of this id
  | Bin !Op2 !Int !Int -- ^ an operation on two nodes
  | Sel !Int !Int !Int -- ^ @c > 0 ? t : e@
  deriving (Show, Eq, Ord)

-- | A staged scalar: the id of a node in the global table. Equal
-- expressions are one node, however they were built:
--
-- >>> nodeId (sym "x" * sym "y") == nodeId (sym "x" * sym "y")
-- True
-- >>> nodeOf (sym "x" * 1 + 0)
-- Sym "x"
-- >>> literalValue (sqrt (lit 2) * sqrt 2)
-- Just 2.0000000000000004
newtype E = E Int

-- | The expression's node id (ids depend on what else the table holds: a
-- printer names nodes in its own order, never by id).
nodeId :: E -> Int
nodeId (E i) = i

instance Show E where
  show e = "E#" ++ show (nodeId e) ++ " " ++ show (nodeOf e)

-- | The nodes by content and by id, and how many there are (the next
-- id: 'IM.size' counts an IntMap's entries one by one, and asked at every
-- new node it made printing the catalogue quadratic in its nodes).
data Table = Table !(M.Map Node Int) !(IM.IntMap Node) !Int

table :: IORef Table
table = unsafePerformIO (newIORef (Table M.empty IM.empty 0))
{-# NOINLINE table #-}

-- | The id of a node, inserting it if new. Nodes are immutable once in the
-- table, so reading and interning from pure code is safe.
--
-- The node is forced first: its operands may be unevaluated nodes whose own
-- interning must not run inside this table update.
intern :: Node -> E
intern !n = unsafePerformIO $ atomicModifyIORef' table $ \t@(Table byNode byId count) ->
  case M.lookup n byNode of
    Just i -> (t, E i)
    Nothing -> (Table (M.insert n count byNode) (IM.insert count n byId) (count + 1), E count)
{-# NOINLINE intern #-}

-- | The node an expression is.
nodeOf :: E -> Node
nodeOf (E i) = nodeById i

-- | The node of an id (an operand of another node).
nodeById :: Int -> Node
nodeById !i = unsafePerformIO $ do
  Table _ byId _ <- readIORef table
  pure (byId IM.! i)
{-# NOINLINE nodeById #-}

-- | A node's operands, by id.
children :: Node -> [Int]
children = \case
  Un _ a -> [a]
  Bin _ a b -> [a, b]
  Sel c t e -> [c, t, e]
  _ -> []

-- | A named value: a parameter of the printed function, or a variable the
-- generated code binds.
sym :: String -> E
sym = intern . Sym

-- | A literal ('constant').
lit :: Double -> E
lit = intern . Lit . castDoubleToWord64

-- | The number an expression is, if it folded to a literal.
--
-- >>> literalValue (lit 2 + 3 * lit 4)
-- Just 14.0
-- >>> literalValue (sym "x" * 0)
-- Just 0.0
-- >>> literalValue (sym "x" + 1)
-- Nothing
literalValue :: E -> Maybe Double
literalValue e = case nodeOf e of
  Lit w -> Just (castWord64ToDouble w)
  _ -> Nothing

-- | The native meaning of each operation; constant folding uses it, so a
-- folded constant is the number the native interpretation computes.
evalOp1 :: Op1 -> Double -> Double
evalOp1 = \case
  Neg -> negate; Abs -> abs; Sign -> signum; Recip -> recip; Sqrt -> sqrt
  Exp -> exp; Log -> log; Sin -> sin; Cos -> cos; Tan -> tan
  Asin -> asin; Acos -> acos; Atan -> atan; Sinh -> sinh; Cosh -> cosh
  Tanh -> tanh; Asinh -> asinh; Acosh -> acosh; Atanh -> atanh; Floor -> floorF
  SinF -> sinF; CosF -> cosF; AtanF -> atanF; ExpF -> expF

-- | The native meaning of each two-operand operation (see 'evalOp1').
evalOp2 :: Op2 -> Double -> Double -> Double
evalOp2 = \case
  Add -> (+); Sub -> (-); Mul -> (*); Div -> (/); Pow -> (**)

isLit :: Double -> E -> Bool
isLit v e = case literalValue e of
  Just x -> castDoubleToWord64 x == castDoubleToWord64 v
  Nothing -> False

un :: Op1 -> E -> E
un op a = case (op, literalValue a, nodeOf a) of
  (_, Just x, _) -> lit (evalOp1 op x)
  (Neg, _, Un Neg b) -> E b
  (Abs, _, Un Abs _) -> a
  _ -> intern (Un op (nodeId a))

bin :: Op2 -> E -> E -> E
bin op a b = case (literalValue a, literalValue b) of
  (Just x, Just y) -> lit (evalOp2 op x y)
  _ -> simplify op
  where
    zero e = isLit 0 e || isLit (-0) e
    simplify Add | zero b = a | zero a = b
    simplify Sub | zero b = a | zero a = un Neg b
    simplify Mul | zero a || zero b = lit 0
                 | isLit 1 a = b | isLit 1 b = a
                 | isLit (-1) a = un Neg b | isLit (-1) b = un Neg a
    simplify Div | isLit 1 b = a | zero a = lit 0 | isLit (-1) b = un Neg a
    simplify Pow | isLit 1 b = a
                 | isLit 2 b = bin Mul a a
                 | isLit 3 b = bin Mul (bin Mul a a) a
    simplify _ = intern (Bin op (nodeId a) (nodeId b))

sel :: E -> E -> E -> E
sel c t e
  | nodeId t == nodeId e = t
  | Just x <- literalValue c = if x > 0 then t else e
  | otherwise = intern (Sel (nodeId c) (nodeId t) (nodeId e))

instance Num E where
  (+) = bin Add
  (-) = bin Sub
  (*) = bin Mul
  negate = un Neg
  abs = un Abs
  signum = un Sign
  fromInteger = lit . fromInteger

instance Fractional E where
  (/) = bin Div
  recip = un Recip
  fromRational = lit . fromRational

instance Floating E where
  pi = lit pi
  exp = un Exp
  log = un Log
  sqrt = un Sqrt
  sin = un Sin
  cos = un Cos
  tan = un Tan
  asin = un Asin
  acos = un Acos
  atan = un Atan
  sinh = un Sinh
  cosh = un Cosh
  tanh = un Tanh
  asinh = un Asinh
  acosh = un Acosh
  atanh = un Atanh
  (**) = bin Pow
  logBase b x = log x / log b

instance Field E where
  constant = lit
  select = sel
  floorF = un Floor
  sinF = un SinF
  cosF = un CosF
  atanF = un AtanF
  expF = un ExpF

-- | The expressions with the engine's own elementary functions ('SinF',
-- 'CosF', 'AtanF', 'ExpF') written out as their kernels' operations
-- ("Manifold.Elementary"), for the page's JavaScript: the same operations
-- as a call of the kernel, in line. V8 inlines no function as large as the
-- exponential, and a call it does not inline returns its number boxed on
-- the heap: in line, the step allocates nothing. Equal subexpressions stay
-- one node (a sine and a cosine of one angle share their reduction).
expandElementary :: [E] -> [E]
expandElementary roots = reverse (fst (foldl' root ([], IM.empty) roots))
  where
    root (acc, memo) r = let (e, memo') = go memo (nodeId r) in (e : acc, memo')
    ops = exact floorF select constant
    go memo i = case IM.lookup i memo of
      Just e -> (e, memo)
      Nothing ->
        let (e, memo') = case nodeById i of
              Un op a ->
                let (a', m1) = go memo a
                in (expand op a', m1)
              Bin op a b ->
                let (a', m1) = go memo a
                    (b', m2) = go m1 b
                in (rebuild (Bin op (nodeId a') (nodeId b')), m2)
              Sel c t f ->
                let (c', m1) = go memo c
                    (t', m2) = go m1 t
                    (f', m3) = go m2 f
                in (rebuild (Sel (nodeId c') (nodeId t') (nodeId f')), m3)
              _ -> (E i, memo)
        in (e, IM.insert i e memo')
      where
        rebuild n = if n == nodeById i then E i else intern n
        expand op a = case op of
          SinF -> sinWith ops a
          CosF -> cosWith ops a
          AtanF -> atanWith ops a
          ExpF -> expWith ops a
          _ -> rebuild (Un op (nodeId a))
