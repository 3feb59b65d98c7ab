-- | Printing staged code as JavaScript, GLSL and Haskell text.
--
-- A set of root expressions is lowered ('lower') to a block of bindings
-- followed by the roots, as terms of "Manifold.Stage.Code": every node used more than once (within the block) is printed once as
-- a local binding, nodes already bound in an enclosing scope are referred to
-- by name, and every node used once is inlined where it is used (in Haskell,
-- so is an expensive node used only inside conditionals' arms: see
-- @onlyUnderConditions@ in the source). Names are
-- given in the order bindings are printed, so the same input prints the same
-- bytes whatever else the global node table holds.
module Manifold.Stage.Print
  ( Target (..)
  , Scope
  , emptyScope
  , Lowered (..)
  , lower
  , renderTerm
  , renderLiteral
  , FnType (..)
  , printFunction
  , printProcedure
  , renderIntTerm
  , indent
  ) where

import qualified Data.IntMap.Strict as IM
import qualified Data.IntSet as IS
import Data.List (foldl', intercalate)

import Manifold.Stage.Code
import Manifold.Stage.Expr

-- $setup
-- >>> let x = sym "x"; y = sym "y"

-- | Haskell is the native engine's compiled step ("Manifold.Compiled"),
-- printed for reading (@manifold dump-step@; what is compiled is the same
-- tree spliced by "Manifold.Stage.Splice"): expressions over 'Double' that
-- GHC compiles to unboxed arithmetic.
data Target = JavaScript | GLSL | Haskell
  deriving (Show, Eq)

-- | Nodes already bound to names where the code being printed sits.
type Scope = IM.IntMap String

-- | The scope of a function's top: nothing bound yet.
emptyScope :: Scope
emptyScope = IM.empty

-- | Roots lowered in a scope ('lower'): the block of bindings they need,
-- then the roots themselves.
data Lowered = Lowered
  { loweredBindings :: [(String, Term)] -- ^ name and right-hand side, in order
  , loweredRoots :: [Term] -- ^ each root as a term over the bindings
  , loweredScope :: Scope -- ^ the scope extended by the new bindings
  , loweredNext :: Int -- ^ the next fresh name's number
  }

-- | Lower roots in a scope, naming new bindings @prefix ++ show k@ from @next@.
lower :: Target -> String -> Int -> Scope -> [E] -> Lowered
lower target prefix next scope roots0 =
  let -- the page's script computes the engine's own functions in line
      roots = if target == JavaScript then expandElementary roots0 else roots0
      rootIds = map nodeId roots
      (order, counts) = foldl' visit ([], IM.empty) rootIds
      visit (ord, cnt) i
        | IM.member i scope = (ord, cnt)
        | IM.member i cnt = (ord, IM.adjust (+ 1) i cnt)
        | otherwise =
            let (ord', cnt') = foldl' visit (ord, IM.insert i (1 :: Int) cnt) (children (nodeById i))
            in (i : ord', cnt')
      -- JavaScript's pow names its operands twice (see 'binary')
      powOperands = IS.fromList
        [ o | target == JavaScript, i <- IM.keys counts, Bin Pow a b <- [nodeById i], o <- [a, b] ]
      shared i = compound (nodeById i) && (IM.findWithDefault 0 i counts > 1 || IS.member i powOperands)
      bound = case target of
        Haskell -> IS.fromList (filter shared order) `IS.difference` onlyUnderConditions order rootIds
        _ -> IS.fromList (filter shared order)
      bind (bs, sc, k) i
        | IS.member i bound =
            let name = prefix ++ show k
            in ((name, term sc i) : bs, IM.insert i name sc, k + 1)
        | otherwise = (bs, sc, k)
      -- 'order' lists every node after its operands' visits: reversed, it is
      -- a post-order (operands first).
      (revBindings, scope', next') = foldl' bind ([], scope, next) (reverse order)
  in Lowered (reverse revBindings) (map (term scope') rootIds) scope' next'

-- | The shared nodes of a Haskell block that are expensive (a division, a
-- root, a transcendental) and used only inside the arms of conditionals:
-- they are printed where they are used, not bound at the top of the block.
--
-- LLVM turns a printed conditional whose arms are cheap into a branch-free
-- select, which waits for both arms; a division bound at the top then sits
-- on the path of every conditional that uses it, taken or not (each
-- iteration of a Newton projection that has already converged, say). V8
-- branches instead and skips the untaken arm. Inside the arm, the division
-- makes the arm expensive, LLVM keeps the branch, and the division is done
-- only where the arm is taken. The values are the same operations on the
-- same operands, so the results are too.
onlyUnderConditions :: [Int] -> [Int] -> IS.IntSet
onlyUnderConditions order rootIds = IS.fromList [ i | i <- order, IM.member i guardedAll ]
  where
    -- every reference to each node: its parent and whether it is an arm
    refs :: IM.IntMap [(Int, Bool)]
    refs = IM.fromListWith (++)
      [ (c, [(p, isArm)])
      | p <- order
      , (c, isArm) <- case nodeById p of
          Sel c t e -> [(c, False), (t, True), (e, True)]
          n -> map (, False) (children n)
      ]
    roots = IS.fromList rootIds
    counts i = length (IM.findWithDefault [] i refs) + (if IS.member i roots then 1 else 0)
    -- parents come before their operands in 'order', so one pass decides,
    -- for each node, whether it is printed as its own binding and, if
    -- not, whether every place it is printed lies inside a conditional's arm
    (guardedAll, _) = foldl decide (IM.empty, IS.empty) order
    decide (guarded, boundSet) i
      | IS.member i roots = (guarded, IS.insert i boundSet)
      | otherwise =
          let rs = IM.findWithDefault [] i refs
              underArm (p, isArm) = isArm || (not (IS.member p boundSet) && IM.member p guarded)
              allGuarded = not (null rs) && all underArm rs
              ownBinding = compound (nodeById i) && counts i > 1 && not (allGuarded && expensive (nodeById i))
          in if ownBinding then (guarded, IS.insert i boundSet)
             else if allGuarded then (IM.insert i () guarded, boundSet)
             else (guarded, boundSet)
    expensive = \case
      Bin op _ _ -> op == Div || op == Pow
      Un op _ -> op `notElem` [Neg, Abs, Sign, Floor]
      _ -> False

compound :: Node -> Bool
compound = \case
  Lit _ -> False
  Sym _ -> False
  _ -> True

-- | A node as a term, its unbound operands inlined.
term :: Scope -> Int -> Term
term scope i = case IM.lookup i scope of
  Just name -> TVar name
  Nothing -> case nodeById i of
    Lit w -> TLit w
    Sym s -> TVar s
    Un op a -> TUn op (go a)
    Bin op a b -> TBin op (go a) (go b)
    Sel c t e -> TSel (go c) (go t) (go e)
  where go = term scope

-- | A term as an expression of the target language.
renderTerm :: Target -> Term -> String
renderTerm target = go
  where
    go = \case
      TLit w -> renderLiteral target (termLiteral w)
      TVar s -> s
      TUn op a -> unary target op (go a)
      TBin op a b -> binary target op (go a) (go b)
      TSel c t e -> case target of
        JavaScript -> "(" ++ go c ++ " > 0 ? " ++ go t ++ " : " ++ go e ++ ")"
        GLSL -> "(" ++ go c ++ " > 0.0 ? " ++ go t ++ " : " ++ go e ++ ")"
        Haskell -> "(if " ++ go c ++ " > 0 then " ++ go t ++ " else " ++ go e ++ ")"
      TCounter i -> case target of
        Haskell -> "(fromIntegral " ++ i ++ " :: Double)"
        _ -> i

unary :: Target -> Op1 -> String -> String
unary target op a = case (op, target) of
  (Neg, Haskell) -> "(negate " ++ a ++ ")"
  (Neg, _) -> "(-" ++ a ++ ")"
  (Recip, JavaScript) -> "(1 / " ++ a ++ ")"
  (Recip, GLSL) -> "(1.0 / " ++ a ++ ")"
  (Recip, Haskell) -> "(recip " ++ a ++ ")"
  -- the engine's own functions: the native step calls them; the page's
  -- script has them in line ('lower', 'Manifold.Stage.Expr.expandElementary');
  -- GLSL, which only draws, takes the GPU's
  (op', JavaScript) | op' `elem` [SinF, CosF, AtanF, ExpF] -> error ("Manifold.Stage.Print: " ++ show op' ++ " reached the JavaScript printer unexpanded")
  (SinF, Haskell) -> "(sinF " ++ a ++ ")"
  (CosF, Haskell) -> "(cosF " ++ a ++ ")"
  (AtanF, Haskell) -> "(atanF " ++ a ++ ")"
  (ExpF, Haskell) -> "(expF " ++ a ++ ")"
  (_, JavaScript) -> "Math." ++ fname ++ "(" ++ a ++ ")"
  (_, GLSL) -> fname ++ "(" ++ a ++ ")"
  -- the functions 'Manifold.Stage.Expr.evalOp1' folds constants with
  (Sign, Haskell) -> "(signum " ++ a ++ ")"
  (Floor, Haskell) -> "(floorF " ++ a ++ ")"
  (_, Haskell) -> "(" ++ fname ++ " " ++ a ++ ")"
  where
    fname = case op of
      Abs -> "abs"; Sign -> "sign"; Sqrt -> "sqrt"; Exp -> "exp"; Log -> "log"
      Sin -> "sin"; Cos -> "cos"; Tan -> "tan"; Asin -> "asin"; Acos -> "acos"
      Atan -> "atan"; Sinh -> "sinh"; Cosh -> "cosh"; Tanh -> "tanh"
      Asinh -> "asinh"; Acosh -> "acosh"; Atanh -> "atanh"; Floor -> "floor"
      SinF -> "sin"; CosF -> "cos"; AtanF -> "atan"; ExpF -> "exp"
      Neg -> "-"; Recip -> "1/"

binary :: Target -> Op2 -> String -> String -> String
binary target op a b = case op of
  Add -> infx "+"
  Sub -> infx "-"
  Mul -> infx "*"
  Div -> infx "/"
  Pow -> case target of
    -- Math.pow(1, NaN) and Math.pow(-1, ±Infinity) are NaN; C's pow, and so
    -- Haskell's (**), gives 1. The operands are names or literals here.
    JavaScript -> "((" ++ a ++ " === 1 || (" ++ a ++ " === -1 && (" ++ b ++ " === Infinity || " ++ b ++ " === -Infinity))) ? 1 : Math.pow(" ++ a ++ ", " ++ b ++ "))"
    GLSL -> "pow(" ++ a ++ ", " ++ b ++ ")"
    Haskell -> "(" ++ a ++ " ** " ++ b ++ ")"
  where infx o = "(" ++ a ++ " " ++ o ++ " " ++ b ++ ")"

-- | A 'Double' literal that the target reads back as the same number (JS) or
-- the nearest float (GLSL, which has no literals for NaN and infinities).
--
-- >>> map (renderLiteral JavaScript) [1 / 0, -0, 0 / 0, 0.1]
-- ["Infinity","(-0)","NaN","0.1"]
-- >>> map (renderLiteral GLSL) [1 / 0, -0, 0 / 0, 0.1]
-- ["uintBitsToFloat(0x7f800000u)","0.0","uintBitsToFloat(0x7fc00000u)","0.1"]
renderLiteral :: Target -> Double -> String
renderLiteral JavaScript x
  | isNaN x = "NaN"
  | isInfinite x = if x > 0 then "Infinity" else "(-Infinity)"
  | isNegativeZero x = "(-0)"
  | x < 0 = "(" ++ show x ++ ")"
  | otherwise = show x
renderLiteral Haskell x
  | isNaN x = "(0 / 0)"
  | isInfinite x = if x > 0 then "(1 / 0)" else "(-1 / 0)"
  | isNegativeZero x = "(-0.0)"
  | x < 0 = "(" ++ show x ++ ")"
  | otherwise = show x
renderLiteral GLSL x
  | isNaN x = "uintBitsToFloat(0x7fc00000u)"
  | isInfinite x || abs x > 3.4e38 = if x > 0 then "uintBitsToFloat(0x7f800000u)" else "(-uintBitsToFloat(0x7f800000u))"
  | abs x < 1e-37 = "0.0"
  | x < 0 = "(" ++ show x ++ ")"
  | otherwise = show x

-- | A line of a block, indented one level (two spaces).
indent :: String -> String
indent = ("  " ++)

-- | The type of a printed pure function: how many results, and for GLSL
-- whether the three coordinates come in as a @vec3 p@.
data FnType = FnType
  { fnParams :: [String] -- ^ scalar parameters (the 'sym's the roots use)
  , fnGlslVec3 :: Bool -- ^ GLSL: take @vec3 p@ and name its components @x, y, z@
  }

-- | A whole function returning the roots: one number, or an array (JS) /
-- vector (GLSL) of them. What the roots share is bound once:
--
-- >>> let r2 = x * x + y * y
-- >>> putStr (printFunction JavaScript "f" (FnType ["x", "y"] False) [sqrt r2 * r2, x / 2])
-- function f(x, y) {
--   const t0 = ((x * x) + (y * y));
--   return [(Math.sqrt(t0) * t0), (x / 2.0)];
-- }
-- >>> putStr (printFunction GLSL "f" (FnType ["x", "y"] False) [sqrt r2 * r2])
-- float f(float x, float y) {
--   float t0 = ((x * x) + (y * y));
--   return (sqrt(t0) * t0);
-- }
printFunction :: Target -> String -> FnType -> [E] -> String
printFunction target name ty roots =
  let Lowered bs ts _ _ = lower target "t" 0 emptyScope roots
      rs = map (renderTerm target) ts
      result = case rs of
        [r] -> r
        _ -> case target of
          JavaScript -> "[" ++ intercalate ", " rs ++ "]"
          GLSL -> "vec" ++ show (length rs) ++ "(" ++ intercalate ", " rs ++ ")"
          Haskell -> "(" ++ intercalate ", " rs ++ ")"
  in case target of
    Haskell -> unlines $
      (name ++ " :: " ++ concatMap (const "Double -> ") (fnParams ty)
         ++ (case rs of [_] -> "Double"; _ -> "(" ++ intercalate ", " (map (const "Double") rs) ++ ")"))
      : (name ++ concatMap (" " ++) (fnParams ty) ++ " =")
      : map (\(n, e) -> indent ("let !" ++ n ++ " = " ++ renderTerm target e ++ " in")) bs
      ++ [indent result]
    JavaScript -> unlines $
      ("function " ++ name ++ "(" ++ intercalate ", " (fnParams ty) ++ ") {")
      : map (\(n, e) -> indent ("const " ++ n ++ " = " ++ renderTerm target e ++ ";")) bs
      ++ [indent ("return " ++ result ++ ";"), "}"]
    GLSL ->
      let rty = case rs of
            [_] -> "float"
            _ -> "vec" ++ show (length rs)
          (params, prologue)
            | fnGlslVec3 ty = ("vec3 p", [indent ("float " ++ v ++ " = p." ++ v ++ ";") | v <- fnParams ty])
            | otherwise = (intercalate ", " ["float " ++ v | v <- fnParams ty], [])
      in unlines $
        (rty ++ " " ++ name ++ "(" ++ params ++ ") {")
        : prologue
        ++ map (\(n, e) -> indent ("float " ++ n ++ " = " ++ renderTerm target e ++ ";")) bs
        ++ [indent ("return " ++ result ++ ";"), "}"]

-- | A staged procedure or subroutine as a function of the target language:
-- JavaScript over @Float64Array@s, or Haskell in 'IO' over the arrays (the
-- definitions "Manifold.Compiled.Runtime" provides: @loopI@, @chkI@,
-- @rdU@, @wrU@, @floorF@ and the array type @Arr@), as
-- @manifold dump-step@ shows the compiled step.
printProcedure :: Target -> Function Check -> String
printProcedure target (Function name arrays scalars body) = unlines $ case target of
  Haskell ->
    ( name ++ " :: " ++ concatMap (const "Arr -> ") arrays ++ concatMap (const "Double -> ") scalars ++ "IO ()" )
    -- strict parameters: each array is evaluated once, here, rather than
    -- wherever the body reads it, and the numbers arrive unboxed
    : (unwords (name : map ('!' :) (arrays ++ scalars)) ++ " = do")
    : haskellBlock 1 body
  _ ->
    -- each number parameter is first made a number: V8 types a parameter as
    -- anything, and where a select merged one with a computed number (the
    -- pair's image shift against its negation, −0 for the identity) it
    -- boxed the result, a heap number for every touching pair
    ("function " ++ name ++ "(" ++ intercalate ", " (arrays ++ scalars) ++ ") {")
    : ["  " ++ s ++ " = +" ++ s ++ ";" | s <- scalars]
    ++ concatMap (scriptStmt 1) body ++ ["}"]
  where
    at d l = replicate (2 * d) ' ' ++ l
    js = renderTerm JavaScript
    hs = renderTerm Haskell
    scriptStmt :: Int -> Stmt Check -> [String]
    scriptStmt d = \case
      Let n t -> [at d ("const " ++ n ++ " = " ++ js t ++ ";")]
      Load n a i -> [at d ("const " ++ n ++ " = " ++ a ++ "[" ++ scriptIndex i ++ "];")]
      Store a i t -> [at d (a ++ "[" ++ scriptIndex i ++ "] = " ++ js t ++ ";")]
      Declare v t -> [at d ("let " ++ v ++ " = " ++ js t ++ ";")]
      Assign v t -> [at d (v ++ " = " ++ js t ++ ";")]
      For i lo hi b ->
        at d ("for (let " ++ i ++ " = " ++ js lo ++ "; " ++ i ++ " < " ++ js hi ++ "; " ++ i ++ "++) {")
        : concatMap (scriptStmt (d + 1)) b ++ [at d "}"]
      If c t e ->
        at d ("if (" ++ js c ++ " > 0) {") : concatMap (scriptStmt (d + 1)) t
        ++ (if null e then [at d "}"] else at d "} else {" : concatMap (scriptStmt (d + 1)) e ++ [at d "}"])
      Call f as ts -> [at d (f ++ "(" ++ intercalate ", " (as ++ map js ts) ++ ");")]
      RowCheck {} -> error "printProcedure: a row check in JavaScript"
    scriptIndex = \case
      NumberIndex t -> scriptWhole t
      IntIndex {} -> error "printProcedure: an Int index in JavaScript"
    -- An index in 32-bit integers, each stored number in it truncated as
    -- the native index truncates it (@ITrunc@): a body's index read from a
    -- contact is a double, and V8 made every index computed from it a
    -- double checked at each access (a sixth of the relaxing sweep's time
    -- on the peer benchmark's pyramid).
    scriptWhole = \case
      TLit w -> renderLiteral JavaScript (termLiteral w)
      TBin op a b | op `elem` [Add, Sub, Mul] -> binary JavaScript op (scriptWhole a) (scriptWhole b)
      t -> "(" ++ js t ++ " | 0)"
    -- a Haskell block is a do block: it ends with @pure ()@, so that it
    -- never ends with a @let@
    haskellBlock :: Int -> [Stmt Check] -> [String]
    haskellBlock d b = concatMap (haskellStmt d) b ++ [at d "pure ()"]
    haskellStmt :: Int -> Stmt Check -> [String]
    haskellStmt d = \case
      Let n (TCounter i) -> [at d ("let !" ++ n ++ " = fromIntegral " ++ i ++ " :: Double")]
      Let n t -> [at d ("let !" ++ n ++ " = " ++ hs t)]
      Load n a i -> [at d (n ++ " <- rdU " ++ a ++ " " ++ haskellIndex i)]
      Store a i t -> [at d ("wrU " ++ a ++ " " ++ haskellIndex i ++ " " ++ hs t)]
      For i lo hi b -> at d ("loopI " ++ hs lo ++ " " ++ hs hi ++ " $ \\" ++ i ++ " -> do") : haskellBlock (d + 1) b
      If c t e -> at d ("if " ++ hs c ++ " > 0 then do") : haskellBlock (d + 1) t ++ at d "else do" : haskellBlock (d + 1) e
      RowCheck a base (lo, hi) -> [at d (unwords ["chkI", a, renderLinear base, intLiteral lo, intLiteral hi])]
      Call f as ts -> [at d (unwords (f : as ++ map hs ts))]
      Declare {} -> error "printProcedure: a mutable local in Haskell (they are slots of the locals array)"
      Assign {} -> error "printProcedure: a mutable local in Haskell (they are slots of the locals array)"
    haskellIndex = \case
      IntIndex base offset
        | offset == 0 -> renderLinear base
        | null base -> intLiteral offset
        | otherwise -> "(" ++ renderLinear base ++ " + " ++ intLiteral offset ++ ")"
      NumberIndex t -> "(truncate " ++ hs t ++ ")"

-- | The base of a native index as 'Int' arithmetic (@0@ for none).
renderLinear :: LinearIndex -> String
renderLinear = \case
  [] -> "0"
  [t] -> linearTerm t
  ts -> "(" ++ intercalate " + " (map linearTerm ts) ++ ")"
  where
    linearTerm (atom, 1) = renderIntTerm atom
    linearTerm (atom, c) = "(" ++ intLiteral c ++ " * " ++ renderIntTerm atom ++ ")"

-- | 'Int' arithmetic as Haskell.
renderIntTerm :: IntTerm -> String
renderIntTerm = \case
  ILit v -> intLiteral v
  ICounter i -> i
  ITrunc t -> "(truncate " ++ renderTerm Haskell t ++ ")"
  IAdd a b -> "(" ++ renderIntTerm a ++ " + " ++ renderIntTerm b ++ ")"
  ISub a b -> "(" ++ renderIntTerm a ++ " - " ++ renderIntTerm b ++ ")"
  IMul a b -> "(" ++ renderIntTerm a ++ " * " ++ renderIntTerm b ++ ")"
  INeg a -> "(negate " ++ renderIntTerm a ++ ")"

intLiteral :: Int -> String
intLiteral k = if k < 0 then "(" ++ show k ++ ")" else show k
