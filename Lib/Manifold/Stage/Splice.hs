{-# LANGUAGE TemplateHaskellQuotes #-}
-- | Staged functions ("Manifold.Stage.Code", made for the
-- 'Manifold.Stage.Print.Haskell' target)
-- as Template Haskell declarations: what the compiled native step splices.
-- The declarations say what 'Manifold.Stage.Print.printProcedure' prints
-- for Haskell, over the definitions of "Manifold.Compiled.Runtime" (loops,
-- row checks, unchecked reads and writes of primitive arrays); every name
-- they use from elsewhere is a global name, so a splice needs no imports.
module Manifold.Stage.Splice
  ( functionDecs
  , termExp
  ) where

import qualified Data.Set as S
import Language.Haskell.TH hiding (Stmt)
import qualified Language.Haskell.TH as TH

import Manifold.Compiled.Runtime (Arr, chkI, loopI, rdU, wrU)
import Manifold.Field (Field (atanF, cosF, expF, floorF, sinF))
import Manifold.Stage.Code
import Manifold.Stage.Expr (Op1 (..), Op2 (..))

-- | A function's signature and definition. @callee@ names the function a
-- call statement calls (a subroutine defined beside it, or elsewhere).
--
-- A name the function binds and never uses is bound as @_@ (the staged
-- step reads whole rows and binds every loop's counter as a number), so
-- the splice compiles without warnings.
functionDecs :: (String -> Name) -> Function Check -> [Dec]
functionDecs callee (Function name arrays scalars body) =
  [ SigD n (foldr arrow (AppT (ConT ''IO) (TupleT 0)) (map (const (ConT ''Arr)) arrays ++ map (const (ConT ''Double)) scalars))
  -- strict parameters: each array is evaluated once, on entry, and the
  -- numbers arrive unboxed
  , FunD n [Clause (map (BangP . binder) (arrays ++ scalars)) (NormalB (doBlock binder callee body)) []]
  ]
  where
    n = mkName name
    arrow a r = AppT (AppT ArrowT a) r
    used = foldMap stmtNames body
    binder v = if S.member v used then VarP (mkName v) else WildP

-- | A block as a do block, ending with @pure ()@.
doBlock :: (String -> Pat) -> (String -> Name) -> [Stmt Check] -> Exp
doBlock binder callee b = DoE Nothing (map (statement binder callee) b ++ [NoBindS (AppE (VarE 'pure) (TupE []))])

statement :: (String -> Pat) -> (String -> Name) -> Stmt Check -> TH.Stmt
statement binder callee = \case
  Let n t -> LetS [ValD (BangP (binder n)) (NormalB (termExp t)) []]
  Load n a i -> BindS (binder n) (apps (VarE 'rdU) [var a, indexExp i])
  Store a i t -> NoBindS (apps (VarE 'wrU) [var a, indexExp i, termExp t])
  For i lo hi b -> NoBindS (apps (VarE 'loopI) [termExp lo, termExp hi, LamE [binder i] (doBlock binder callee b)])
  If c t e -> NoBindS (CondE (positive (termExp c)) (doBlock binder callee t) (doBlock binder callee e))
  RowCheck a base (lo, hi) -> NoBindS (apps (VarE 'chkI) [var a, linearExp base, intExp lo, intExp hi])
  Call f as ts -> NoBindS (apps (VarE (callee f)) (map var as ++ map termExp ts))
  Declare {} -> error "functionDecs: a mutable local (in Haskell they are slots of the locals array)"
  Assign {} -> error "functionDecs: a mutable local (in Haskell they are slots of the locals array)"

-- | The names a statement refers to (not those it binds).
stmtNames :: Stmt Check -> S.Set String
stmtNames = \case
  Let _ t -> termNames t
  Load _ a i -> S.insert a (indexNames i)
  Store a i t -> S.insert a (indexNames i <> termNames t)
  Declare _ t -> termNames t
  Assign v t -> S.insert v (termNames t)
  For _ lo hi b -> termNames lo <> termNames hi <> foldMap stmtNames b
  If c t e -> termNames c <> foldMap stmtNames t <> foldMap stmtNames e
  RowCheck a base _ -> S.insert a (foldMap (intNames . fst) base)
  Call _ as ts -> S.fromList as <> foldMap termNames ts
  where
    indexNames = \case
      IntIndex base _ -> foldMap (intNames . fst) base
      NumberIndex t -> termNames t
    intNames = \case
      ILit _ -> S.empty
      ICounter i -> S.singleton i
      ITrunc t -> termNames t
      IAdd a b -> intNames a <> intNames b
      ISub a b -> intNames a <> intNames b
      IMul a b -> intNames a <> intNames b
      INeg a -> intNames a
    termNames = \case
      TLit _ -> S.empty
      TVar v -> S.singleton v
      TUn _ a -> termNames a
      TBin _ a b -> termNames a <> termNames b
      TSel c t e -> termNames c <> termNames t <> termNames e
      TCounter i -> S.singleton i

var :: String -> Exp
var = VarE . mkName

apps :: Exp -> [Exp] -> Exp
apps = foldl AppE

infixOp :: Name -> Exp -> Exp -> Exp
infixOp o a b = InfixE (Just a) (VarE o) (Just b)

-- | @e > 0@
positive :: Exp -> Exp
positive e = infixOp '(>) e (LitE (RationalL 0))

-- | A term as a 'Double' expression.
termExp :: Term -> Exp
termExp = \case
  TLit w -> literal (termLiteral w)
  TVar s -> var s
  TUn op a -> AppE (VarE (unaryName op)) (termExp a)
  TBin op a b -> infixOp (binaryName op) (termExp a) (termExp b)
  TSel c t e -> CondE (positive (termExp c)) (termExp t) (termExp e)
  TCounter i -> SigE (AppE (VarE 'fromIntegral) (var i)) (ConT ''Double)

-- | A 'Double' literal that reads back as the same number.
literal :: Double -> Exp
literal x
  | isNaN x = infixOp '(/) (double 0) (double 0)
  | isInfinite x = infixOp '(/) (double (signum x)) (double 0)
  | isNegativeZero x || x < 0 = AppE (VarE 'negate) (double (negate x))
  | otherwise = double x
  where double v = SigE (LitE (RationalL (toRational (v :: Double)))) (ConT ''Double)

unaryName :: Op1 -> Name
unaryName = \case
  Neg -> 'negate; Abs -> 'abs; Sign -> 'signum; Recip -> 'recip; Sqrt -> 'sqrt
  Exp -> 'exp; Log -> 'log; Sin -> 'sin; Cos -> 'cos; Tan -> 'tan
  Asin -> 'asin; Acos -> 'acos; Atan -> 'atan; Sinh -> 'sinh; Cosh -> 'cosh
  Tanh -> 'tanh; Asinh -> 'asinh; Acosh -> 'acosh; Atanh -> 'atanh; Floor -> 'floorF
  SinF -> 'sinF; CosF -> 'cosF; AtanF -> 'atanF; ExpF -> 'expF

binaryName :: Op2 -> Name
binaryName = \case
  Add -> '(+); Sub -> '(-); Mul -> '(*); Div -> '(/); Pow -> '(**)

indexExp :: ArrayIndex -> Exp
indexExp = \case
  IntIndex base offset
    | offset == 0 -> linearExp base
    | null base -> intExp offset
    | otherwise -> infixOp '(+) (linearExp base) (intExp offset)
  NumberIndex t -> AppE (VarE 'truncate) (termExp t)

-- | The base of an index as 'Int' arithmetic.
linearExp :: LinearIndex -> Exp
linearExp = \case
  [] -> intExp 0
  ts -> foldl1 (infixOp '(+)) (map term ts)
  where
    term (atom, 1) = intTermExp atom
    term (atom, c) = infixOp '(*) (intExp c) (intTermExp atom)

intTermExp :: IntTerm -> Exp
intTermExp = \case
  ILit v -> intExp v
  ICounter i -> var i
  ITrunc t -> SigE (AppE (VarE 'truncate) (termExp t)) (ConT ''Int)
  IAdd a b -> infixOp '(+) (intTermExp a) (intTermExp b)
  ISub a b -> infixOp '(-) (intTermExp a) (intTermExp b)
  IMul a b -> infixOp '(*) (intTermExp a) (intTermExp b)
  INeg a -> AppE (VarE 'negate) (intTermExp a)

intExp :: Int -> Exp
intExp k
  | k < 0 = AppE (VarE 'negate) (intExp (negate k))
  | otherwise = SigE (LitE (IntegerL (fromIntegral k))) (ConT ''Int)
