{-# LANGUAGE TypeFamilyDependencies, FlexibleContexts #-}
{-# LANGUAGE GeneralizedNewtypeDeriving #-}
-- | The imperative layer the engine is written in: bounded loops, a
-- conditional, array reads and writes, explicit sharing and mutable locals —
-- the size the physics step needs, no more.
--
-- It is a tagless-final class (after ivory and raw-feldspar's imperative
-- EDSLs) with two interpretations:
--
-- * 'Native': GHC runs the program directly in 'IO' over unboxed mutable
--   vectors of 'Double', so the native engine is ordinary compiled Haskell;
-- * 'Staged': the program builds its code as a tree ("Manifold.Stage.Code");
--   its scalars are staged expressions ('E'), so the geometry the program
--   calls (fields, AD gradients, projections) is inlined, with shared
--   subexpressions bound once. The tree is made for a 'Target': printed as
--   the page's JavaScript functions over @Float64Array@s, or, for Haskell,
--   spliced as the compiled native step ("Manifold.Stage.Splice") and
--   printed for reading.
module Manifold.Stage.Imp
  ( Imp (..)
  , whenPositive
  , forEach
  , modifyRef
    -- * Native
  , Native
  , runNative
  , NativeArray
    -- * Staged
  , Staged
  , StagedArray (..)
  , IxE
  , Procedure (..)
  , stageFunctions
  , stageProcedure
  , stageProcedures
  , stageProceduresFor
  , localSlots
  , localsArray
  ) where

import Control.Monad.State.Strict
import qualified Data.IntMap.Strict as IM
import qualified Data.Map.Strict as M
import Data.List (sortOn)
import qualified Data.Vector.Unboxed.Mutable as MV
import GHC.Float (castWord64ToDouble)

import Manifold.Field
import Manifold.Stage.Code
import Manifold.Stage.Expr
import Manifold.Stage.Print

-- $setup
-- >>> import qualified Data.Vector.Unboxed as V
-- >>> import qualified Data.Vector.Unboxed.Mutable as MV

-- | A monad that runs (or builds) imperative programs over arrays of
-- numbers. A program written once against it runs natively and prints as
-- code; here, the sum of an array:
--
-- >>> :{
-- let total xs out n = do
--       s <- newRef 0
--       forEach n (\i -> readArray xs i >>= \x -> modifyRef s (+ x))
--       readRef s >>= writeArray out 0
-- :}
--
-- >>> xs <- V.thaw (V.fromList [1, 2, 3, 4])
-- >>> out <- MV.replicate 1 0
-- >>> runNative (total xs out 4) >> MV.read out 0
-- 10.0
-- >>> putStr (stageProcedure (Procedure "total" ["xs", "out"] ["n"]) (\[xs, out] [n] -> total xs out (toIndex n)))
-- function total(xs, out, n) {
--   n = +n;
--   let v0 = 0.0;
--   for (let i1 = 0.0; i1 < n; i1++) {
--     const t2 = xs[(i1 | 0)];
--     const t3 = v0;
--     v0 = (t3 + t2);
--   }
--   const t4 = v0;
--   out[0.0] = t4;
-- }
class (Monad m, Field (Scalar m), Num (Index m)) => Imp m where
  -- | The numbers a program computes with: 'Double', or staged expressions.
  type Scalar m = s | s -> m
  -- | Array indices and loop counters.
  type Index m = i | i -> m
  -- | An array of numbers, as the program receives it.
  type Array m
  -- | A mutable local number.
  type Ref m
  -- | @forLoop lo hi body@ runs @body i@ for @lo <= i < hi@.
  forLoop :: Index m -> Index m -> (Index m -> m ()) -> m ()
  -- | @ifPositive c t e@ runs @t@ where @c > 0@, else @e@ (NaN runs @e@).
  ifPositive :: Scalar m -> m () -> m () -> m ()
  -- | An element of an array.
  readArray :: Array m -> Index m -> m (Scalar m)
  -- | Set an element of an array.
  writeArray :: Array m -> Index m -> Scalar m -> m ()
  -- | Compute a value once here and refer to it by name afterwards.
  share :: Scalar m -> m (Scalar m)
  -- | 'share' several values at once, so what they have in common is
  -- computed once too.
  shareAll :: Traversable t => t (Scalar m) -> m (t (Scalar m))
  -- | A new mutable local holding a value.
  newRef :: Scalar m -> m (Ref m)
  -- | A local's value now.
  readRef :: Ref m -> m (Scalar m)
  -- | Set a local.
  writeRef :: Ref m -> Scalar m -> m ()
  -- | An index as a number.
  toScalar :: Index m -> Scalar m
  -- | A scalar holding a whole number (a stored count or index) as an index.
  toIndex :: Scalar m -> Index m
  -- | @subroutine name args body@ runs @body args@ here. Staged, the body is
  -- printed once as a JavaScript function of its own (over the procedure's
  -- arrays and the arguments) and called: V8 does not optimise a function
  -- of more than 60 KB of bytecode, so the step's large parts are
  -- subroutines. The body may use only its arguments, the arrays and
  -- constants: a value staged outside it is out of scope there. One name,
  -- one body: printing two different bodies under a name is an error.
  subroutine :: String -> [Scalar m] -> ([Scalar m] -> m ()) -> m ()

-- | @whenPositive c t@ runs @t@ where @c > 0@ (not for NaN).
whenPositive :: Imp m => Scalar m -> m () -> m ()
{-# INLINE whenPositive #-}
whenPositive c t = ifPositive c t (pure ())

-- | @forEach n body@ runs @body i@ for @0 <= i < n@.
forEach :: Imp m => Index m -> (Index m -> m ()) -> m ()
{-# INLINE forEach #-}
forEach = forLoop 0

-- | Apply a function to a local's value.
modifyRef :: Imp m => Ref m -> (Scalar m -> Scalar m) -> m ()
{-# INLINE modifyRef #-}
modifyRef r f = readRef r >>= writeRef r . f

-- Native -------------------------------------------------------------------

-- | The native interpretation: the program runs in 'IO' over unboxed
-- mutable vectors, its scalars 'Double' and its indices 'Int'.
newtype Native a = Native (IO a)
  deriving (Functor, Applicative, Monad, MonadIO)

-- | Run a native program.
runNative :: Native a -> IO a
runNative (Native io) = io

-- | The native interpretation's arrays: the world's arrays as
-- "Manifold.Engine" holds them.
type NativeArray = MV.IOVector Double

-- | A mutable unboxed number (an 'Data.IORef.IORef' would box every write).
newtype NativeRef = NativeRef (MV.IOVector Double)

instance Imp Native where
  type Scalar Native = Double
  type Index Native = Int
  type Array Native = NativeArray
  type Ref Native = NativeRef
  forLoop lo hi body = go lo
    where go !i | i < hi = body i >> go (i + 1)
                | otherwise = pure ()
  {-# INLINE forLoop #-}
  ifPositive c t e = if c > 0 then t else e
  {-# INLINE ifPositive #-}
  readArray a i = Native (MV.read a i)
  {-# INLINE readArray #-}
  writeArray a i x = Native (MV.write a i x)
  {-# INLINE writeArray #-}
  -- strict, as the printed @const@ is: a shared value is computed where it
  -- is shared, not left as a thunk
  share !x = pure x
  {-# INLINE share #-}
  shareAll xs = foldr seq (pure xs) xs
  {-# INLINE shareAll #-}
  newRef !x = Native $ do
    r <- MV.unsafeNew 1
    MV.unsafeWrite r 0 x
    pure (NativeRef r)
  {-# INLINE newRef #-}
  readRef (NativeRef r) = Native (MV.unsafeRead r 0)
  {-# INLINE readRef #-}
  writeRef (NativeRef r) !x = Native (MV.unsafeWrite r 0 x)
  {-# INLINE writeRef #-}
  toScalar = fromIntegral
  toIndex = truncate
  subroutine _ args body = body args
  {-# INLINE subroutine #-}

-- Staged -------------------------------------------------------------------

-- | A staged index: a JavaScript number holding a whole number.
newtype IxE = IxE E

instance Num IxE where
  IxE a + IxE b = IxE (a + b)
  IxE a - IxE b = IxE (a - b)
  IxE a * IxE b = IxE (a * b)
  negate (IxE a) = IxE (negate a)
  abs (IxE a) = IxE (abs a)
  signum (IxE a) = IxE (signum a)
  fromInteger = IxE . fromInteger

-- | A staged array: the name of the array parameter it is.
newtype StagedArray = StagedArray String

-- | A mutable local: a slot of the locals array (Haskell) or a variable.
data StagedRef = SlotRef Int | VarRef String

data StageState = StageState
  { ssNext :: !Int -- ^ next fresh name
  , ssScope :: !Scope -- ^ nodes bound where the next statement goes
  , ssBlock :: [Stmt Int] -- ^ the current block, reversed
  , ssArrays :: [String] -- ^ the procedure's array parameters
  , ssSubroutines :: M.Map String (Function Check) -- ^ subroutines staged so far, by name
  , ssOrder :: [String] -- ^ their names, latest first
  , ssTarget :: !Target -- ^ JavaScript, or Haskell for the compiled native step
  , ssIntVars :: M.Map String String -- ^ Haskell: a loop's number and its 'Int' counter
  , ssChecks :: M.Map (String, LinearIndex) [(Int, Bool)]
    -- ^ Haskell: the index checks in force, by array and base index, and
    -- whether the current block made them (see @arrayAccess@)
  , ssCheckRanges :: IM.IntMap Check -- ^ each check's offsets, lowest and highest
  , ssNextCheck :: !Int
  , ssNextLocal :: !Int -- ^ Haskell: the next slot of the locals array (see 'localSlots')
  , ssInSubroutine :: !Bool
  }

-- | Haskell: the compiled step's mutable locals (the JavaScript @let@s) are
-- slots of a scratch array of this many numbers, which each phase call
-- allocates once ("Manifold.Compiled.Runtime"'s @newLocals@) and passes to
-- every function it calls, as the last array. A local of its own (a
-- one-number array) would be allocated on GHC's heap every time its
-- statement runs: the narrow phase's eighteen per pair and the solver's
-- five per contact row were most of what the native step allocated.
-- A procedure numbers its locals from 0 and a subroutine from
-- @subroutineLocals@ (32), so the locals of a procedure and of the subroutine it
-- calls are different slots; a subroutine calls no other. (The pair
-- narrow phase, which holds every pair kind's, needs the most: 45.)
localSlots :: Int
localSlots = 96

subroutineLocals :: Int
subroutineLocals = 32

-- | The array of locals as the compiled step names it.
localsArray :: String
localsArray = "locals"

-- | The arrays a staged function takes: the procedure's, and in Haskell
-- the locals array last.
printedArrays :: Target -> [String] -> [String]
printedArrays Haskell arrays = arrays ++ [localsArray]
printedArrays _ arrays = arrays

-- | Haskell: a fresh slot for a local, or an error once a function's slots
-- run out (a staging error, raised while the compiled step is spliced).
freshLocal :: Staged Int
freshLocal = do
  s <- Staged get
  let (kind, first, end)
        | ssInSubroutine s = ("subroutine", subroutineLocals, localSlots)
        | otherwise = ("procedure", 0, subroutineLocals)
  when (ssNextLocal s >= end) $
    error ("the compiled step's locals: a " ++ kind ++ " needs more than " ++ show (end - first)
           ++ " (Manifold.Stage.Imp.localSlots)")
  Staged (put s { ssNextLocal = ssNextLocal s + 1 })
  pure (ssNextLocal s)

-- | The staged interpretation: the program builds its code, for a
-- 'Target', as the statements of "Manifold.Stage.Code" ('stageFunctions');
-- its scalars are expressions ('E').
newtype Staged a = Staged (State StageState a)
  deriving (Functor, Applicative, Monad)

emit :: Stmt Int -> Staged ()
emit st = Staged $ modify' $ \s -> s { ssBlock = st : ssBlock s }

isHaskell :: Staged Bool
isHaskell = Staged (gets ((== Haskell) . ssTarget))

-- | Emit the bindings an expression needs and return it as a term.
expression :: E -> Staged Term
expression e = do
  s <- Staged get
  let Lowered bs [r] scope' next' = lower (ssTarget s) "t" (ssNext s) (ssScope s) [e]
  Staged (put s { ssNext = next', ssScope = scope' })
  mapM_ (emit . uncurry Let) bs
  pure r

-- | Emit the bindings several expressions need together (what they share is
-- bound once).
expressions :: [E] -> Staged [Term]
expressions es = do
  s <- Staged get
  let Lowered bs rs scope' next' = lower (ssTarget s) "t" (ssNext s) (ssScope s) es
  Staged (put s { ssNext = next', ssScope = scope' })
  mapM_ (emit . uncurry Let) bs
  pure rs

fresh :: String -> Staged String
fresh prefix = Staged $ state $ \s -> (prefix ++ show (ssNext s), s { ssNext = ssNext s + 1 })

-- | Bind an expression to a new name, remembered for this scope.
bindAs :: String -> E -> Staged E
bindAs prefix e = do
  rhs <- expression e
  case nodeOf e of
    Lit _ -> pure e
    Sym _ -> pure e
    _ -> do
      n <- fresh prefix
      emit (Let n rhs)
      Staged (modify' (\s -> s { ssScope = IM.insert (nodeId e) n (ssScope s) }))
      pure (sym n)

-- | A nested block: its bindings do not outlive it.
block :: Staged () -> Staged [Stmt Int]
block body = do
  outer <- Staged get
  Staged (put outer { ssBlock = [], ssChecks = M.map (map (\(c, _) -> (c, False))) (ssChecks outer) })
  body
  inner <- Staged get
  Staged (put inner { ssScope = ssScope outer, ssChecks = ssChecks outer, ssBlock = ssBlock outer })
  pure (reverse (ssBlock inner))

instance Imp Staged where
  type Scalar Staged = E
  type Index Staged = IxE
  type Array Staged = StagedArray
  type Ref Staged = StagedRef
  forLoop (IxE lo) (IxE hi) body = do
    lo' <- expression lo
    hi' <- bindAs "n" hi >>= expression
    i <- fresh "i"
    hs <- isHaskell
    if hs
      then do
        -- the counter is an Int (array indices are computed from it in Int
        -- arithmetic, see 'arrayAccess'); the loop body sees it as a
        -- number, as the staged program does
        let d = 'd' : drop 1 i
        Staged (modify' (\s -> s { ssIntVars = M.insert d i (ssIntVars s) }))
        b <- block (emit (Let d (TCounter i)) >> body (IxE (sym d)))
        emit (For i lo' hi' b)
      else do
        b <- block (body (IxE (sym i)))
        emit (For i lo' hi' b)
  ifPositive c t e = do
    c' <- expression c
    t' <- block t
    e' <- block e
    emit (If c' t' e')
  readArray (StagedArray a) (IxE i) = do
    i' <- index a i
    t <- fresh "t"
    emit (Load t a i')
    pure (sym t)
  writeArray (StagedArray a) (IxE i) x = do
    i' <- index a i
    x' <- expression x
    emit (Store a i' x')
  share = bindAs "s"
  shareAll xs = do
    _ <- expressions (foldr (:) [] xs)
    traverse (bindAs "s") xs
  newRef x = do
    x' <- expression x
    hs <- isHaskell
    if hs
      then do
        k <- freshLocal
        emit (Store localsArray (IntIndex [] k) x')
        pure (SlotRef k)
      else do
        v <- fresh "v"
        emit (Declare v x')
        pure (VarRef v)
  readRef r = do
    t <- fresh "t"
    emit $ case r of
      SlotRef k -> Load t localsArray (IntIndex [] k)
      VarRef v -> Let t (TVar v)
    pure (sym t)
  writeRef r x = do
    x' <- expression x
    emit $ case r of
      SlotRef k -> Store localsArray (IntIndex [] k) x'
      VarRef v -> Assign v x'
  toScalar (IxE e) = e
  toIndex = IxE
  subroutine name args body = do
    args' <- mapM expression args
    st <- Staged get
    when (ssInSubroutine st && ssTarget st == Haskell) $
      error ("subroutine " ++ name ++ " called from a subroutine: their locals would share slots")
    let params = ["a" ++ show k | k <- [0 .. length args - 1]]
        Staged m = body (map sym params)
        inner = execState m st
          { ssNext = 0, ssScope = emptyScope, ssBlock = [], ssChecks = M.empty
          , ssNextLocal = subroutineLocals, ssInSubroutine = True }
        fn = finishFunction inner name (ssArrays st) params subroutineLocals
    case M.lookup name (ssSubroutines inner) of
      Just old | old /= fn -> error ("subroutine " ++ name ++ ": two different bodies under one name")
      _ -> pure ()
    Staged $ put st
      { ssSubroutines = M.insert name fn (ssSubroutines inner)
      , ssOrder = if M.member name (ssSubroutines inner) then ssOrder inner else name : ssOrder inner }
    emit (Call name (ssArrays st) args')

-- | The staged function: the statements of its state, their row checks
-- completed, after (in Haskell) the check that the locals array holds the
-- function's slots, numbered from @first@.
finishFunction :: StageState -> String -> [String] -> [String] -> Int -> Function Check
finishFunction s name arrays params first = Function name arrays params (localsCheck ++ body)
  where
    body = map (fmap (ssCheckRanges s IM.!)) (reverse (ssBlock s))
    localsCheck
      | ssTarget s /= Haskell || ssNextLocal s == first = []
      | otherwise = [RowCheck localsArray [] (first, ssNextLocal s - 1)]

-- | An array index: a number in JavaScript, checked 'Int' arithmetic in
-- Haskell (@arrayAccess@).
index :: String -> E -> Staged ArrayIndex
index a i = do
  hs <- isHaskell
  if hs then arrayAccess a i else NumberIndex <$> expression i

-- | Sums and products of whole numbers, loop counters and stored whole
-- numbers: an index computed exactly in 'Int' arithmetic.
wholeIndex :: Int -> Bool
wholeIndex i = case nodeById i of
  Lit w -> isWhole (castWord64ToDouble w)
  Sym _ -> True
  Bin op a b -> op `elem` [Add, Sub, Mul] && wholeIndex a && wholeIndex b
  Un Neg a -> wholeIndex a
  _ -> False
  where isWhole v = v == fromIntegral (truncate v :: Int) && abs v < 2 ^ (52 :: Int)

-- | Haskell: an array index, checked. The compiled step reads a row of an
-- array (a contact's thirty numbers, a body's three coordinates) at one
-- base index plus constant offsets; the first access to a row in a block
-- makes one check (@chkI array base lowest highest@) that covers every
-- offset the block later reads or writes at that base, and the accesses
-- themselves go unchecked. A check per access (the vector library's)
-- made the solver phase half as slow again. An access inside a nested
-- block (under a condition, in a loop) is covered by an enclosing block's
-- check only within the offsets that block reads anyway; beyond them it gets
-- its own check: one made before the condition must not fail for an access
-- the condition would skip.
-- The base is made of names that are bound once, so the same base is the
-- same number throughout the block. An index of sums and products of
-- whole numbers, loop counters and stored whole numbers is 'Int' arithmetic
-- (exact, and no conversion at every access); any other is computed as a
-- number and truncated.
arrayAccess :: String -> E -> Staged ArrayIndex
arrayAccess arr e = do
  counters <- Staged (gets ssIntVars)
  (base, offset) <-
    if wholeIndex (nodeId e)
      then let (terms, k) = linearIndex (nodeId e) in pure (orderTerms counters terms, k)
      else (\d -> ([(ITrunc d, 1)], 0)) <$> expression e
  let key = (arr, base)
  checks <- Staged (gets ssChecks)
  ranges <- Staged (gets ssCheckRanges)
  let covered c = maybe False (\(lo, hi) -> lo <= offset && offset <= hi) (IM.lookup c ranges)
      inForce = M.findWithDefault [] key checks
  case (any (covered . fst) inForce, [ c | (c, True) <- inForce ]) of
    (True, _) -> pure ()
    (False, c : _) -> Staged $ modify' $ \st ->
      st { ssCheckRanges = IM.adjust (\(lo, hi) -> (min lo offset, max hi offset)) c (ssCheckRanges st) }
    (False, []) -> do
      c <- Staged $ state $ \st ->
        ( ssNextCheck st
        , st { ssNextCheck = ssNextCheck st + 1
             , ssChecks = M.insertWith (++) key [(ssNextCheck st, True)] (ssChecks st)
             , ssCheckRanges = IM.insert (ssNextCheck st) (offset, offset) (ssCheckRanges st) } )
      emit (RowCheck arr base c)
  pure (IntIndex base offset)

-- | A whole-number index as a sum of terms (a node that is not a sum,
-- difference or multiple, with its whole coefficient) and a constant, so
-- that @3 * (97 * i + 4 * j + 3)@ is @291 * i + 12 * j@ plus 9 and shares a
-- check with its neighbours at @+ 10@ and @+ 11@. Exact: the staged
-- arithmetic on whole numbers is exact below 2^53, and so is 'Int's.
linearIndex :: Int -> (M.Map Int Int, Int)
linearIndex i = case nodeById i of
  Lit w -> (M.empty, truncate (castWord64ToDouble w))
  Bin Add a b -> plus (linearIndex a) (linearIndex b)
  Bin Sub a b -> plus (linearIndex a) (scale (-1) (linearIndex b))
  Un Neg a -> scale (-1) (linearIndex a)
  Bin Mul a b
    | (ta, ka) <- linearIndex a, M.null ta -> scale ka (linearIndex b)
    | (tb, kb) <- linearIndex b, M.null tb -> scale kb (linearIndex a)
  _ -> (M.singleton i 1, 0)
  where
    plus (ta, ka) (tb, kb) = (M.filter (/= 0) (M.unionWith (+) ta tb), ka + kb)
    scale c (t, k) = (M.filter (/= 0) (M.map (c *) t), c * k)

-- | The terms of a @linearIndex@ as 'Int' arithmetic, in the order of
-- their printed text: node ids depend on what else the global table
-- holds, and the compiled step must not.
orderTerms :: M.Map String String -> M.Map Int Int -> LinearIndex
orderTerms counters terms = sortOn (renderIntTerm . fst) [ (intTerm counters node, c) | (node, c) <- M.toList terms ]

-- | A whole-number expression (a node) as 'Int' arithmetic: loop numbers by
-- their counters, other names (stored whole numbers) truncated.
intTerm :: M.Map String String -> Int -> IntTerm
intTerm counters = go
  where
    go i = case nodeById i of
      Lit w -> ILit (truncate (castWord64ToDouble w))
      Sym n -> maybe (ITrunc (TVar n)) ICounter (M.lookup n counters)
      Bin Add a b -> IAdd (go a) (go b)
      Bin Sub a b -> ISub (go a) (go b)
      Bin Mul a b -> IMul (go a) (go b)
      Un Neg a -> INeg (go a)
      n -> error ("intTerm: not whole-number arithmetic: " ++ show n)

-- | A procedure to stage: its name, its array and scalar parameters.
data Procedure = Procedure
  { procName :: String
  , procArrays :: [String] -- ^ the arrays' names, as the program's 'StagedArray's
  , procScalars :: [String] -- ^ the number parameters' names, as its 'sym's
  }

-- | Print a procedure as a JavaScript function (returning nothing; results go
-- into its arrays), followed by the subroutines it calls.
stageProcedure :: Procedure -> ([StagedArray] -> [E] -> Staged ()) -> String
stageProcedure p body = concat (stageProcedures [(p, body)])

-- | Print procedures as JavaScript functions, each subroutine they call once
-- (after the first procedure that calls it); a name that two of them stage
-- differently is an error.
stageProcedures :: [(Procedure, [StagedArray] -> [E] -> Staged ())] -> [String]
stageProcedures = stageProceduresFor JavaScript

-- | 'stageFunctions' printed.
stageProceduresFor :: Target -> [(Procedure, [StagedArray] -> [E] -> Staged ())] -> [String]
stageProceduresFor target = map (printProcedure target) . stageFunctions target

-- | Stage procedures for a target: each procedure's function, followed by
-- the subroutines it calls that no earlier procedure called (each once; a
-- name that two procedures stage differently is an error). In Haskell
-- each function takes the locals array last (see 'localSlots').
stageFunctions :: Target -> [(Procedure, [StagedArray] -> [E] -> Staged ())] -> [Function Check]
stageFunctions target = go M.empty
  where
    go _ [] = []
    go seen ((p, body) : rest) =
      let Staged m = body (map StagedArray (procArrays p)) (map sym (procScalars p))
          arrays = printedArrays target (procArrays p)
          s0 = StageState 0 emptyScope [] arrays M.empty [] target M.empty M.empty IM.empty 0 0 False
          s1 = execState m s0
          main = finishFunction s1 (procName p) arrays (procScalars p) 0
          new = [ (n, f) | n <- reverse (ssOrder s1), let f = ssSubroutines s1 M.! n
                         , case M.lookup n seen of
                             Nothing -> True
                             Just f' | f' == f -> False
                                     | otherwise -> error ("subroutine " ++ n ++ ": two different bodies under one name") ]
      in main : map snd new ++ go (M.union seen (M.fromList new)) rest
