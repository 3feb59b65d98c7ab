{-# LANGUAGE FlexibleContexts #-}
-- | The imperative layer: programs written once against 'Imp', run natively
-- ('runNative', unboxed mutable vectors) and staged ('stageProcedure', run
-- under node on @Float64Array@s). Both interpretations perform the same
-- floating-point operations in the same order, so the arrays they leave
-- must be bit-for-bit identical.
module ImpSpec (spec) where

import Control.Exception (evaluate, try, IOException)
import Control.Monad (forM_, unless, when)
import Data.List (intercalate, isInfixOf)
import qualified Data.Vector.Unboxed as V
import qualified Data.Vector.Unboxed.Mutable as MV
import GHC.Float (castDoubleToWord64)
import Test.Hspec
import Test.QuickCheck
import Test.QuickCheck.Gen (unGen)
import Test.QuickCheck.Random (mkQCGen)
import Text.Printf (printf)

import Manifold.Compiled.Runtime (chkI, primitiveArray)
import Manifold.Field
import Manifold.Stage.Imp
import Manifold.Stage.Print (Target (..))

import NodeJS

-- The programs --------------------------------------------------------------------

-- | @out[i] = inp[0] + … + inp[i]@ for @i < meta[0]@ (a running sum in a
-- mutable ref, each partial sum shared).
prefixSum :: Imp m => Array m -> Array m -> Array m -> m ()
prefixSum meta inp out = do
  n <- toIndex <$> readArray meta 0
  acc <- newRef 0
  forEach n $ \i -> do
    v <- readArray inp i
    a <- readRef acc
    s <- share (a + v)
    writeArray out i s
    writeRef acc s

-- | Segments with bounds read from an array: for each @k < meta[0]@,
-- @out[k] = fold (\a v -> a/2 + v·w) 0 inp[off[k] .. off[k+1]-1]@ with a
-- weight depending on the position (a nested loop whose bounds are data).
segmented :: Imp m => Array m -> Array m -> Array m -> Array m -> m ()
segmented meta off inp out = do
  nseg <- toIndex <$> readArray meta 0
  forEach nseg $ \k -> do
    lo <- toIndex <$> readArray off k
    hi <- toIndex <$> readArray off (k + 1)
    acc <- newRef 0
    forLoop lo hi $ \j -> do
      v <- readArray inp j
      w <- share (1 + toScalar (j - lo) / 8)
      modifyRef acc (\a -> a / 2 + v * w)
    readRef acc >>= writeArray out k

-- | Projected Gauss–Seidel for the 1D obstacle problem
-- @−x'' = b, x >= obs@ on @meta[0]@ nodes (fixed end values), @meta[1]@
-- sweeps, @meta[2] = h²@:
-- @x[i] ← max(obs[i], (h²·b[i] + x[i−1] + x[i+1]) / 2)@, the max taken with
-- an if/else (contact: clamp and count; else: the Gauss–Seidel value).
-- @stats[0]@ = contacts counted over all sweeps, @stats[1]@ = free updates,
-- @stats[2 + s]@ = the largest change in sweep @s@.
gaussSeidel :: Imp m => Array m -> Array m -> Array m -> Array m -> Array m -> m ()
gaussSeidel meta x b obs stats = do
  n <- toIndex <$> readArray meta 0
  sweeps <- toIndex <$> readArray meta 1
  h2 <- readArray meta 2
  contacts <- newRef 0
  free <- newRef 0
  change <- newRef 0
  forEach sweeps $ \s -> do
    writeRef change 0
    forLoop 1 (n - 1) $ \i -> do
      xl <- readArray x (i - 1)
      xr <- readArray x (i + 1)
      bi <- readArray b i
      o <- readArray obs i
      old <- readArray x i
      gs <- share ((h2 * bi + xl + xr) / 2)
      ifPositive (o - gs)
        (writeArray x i o >> modifyRef contacts (+ 1))
        (writeArray x i gs >> modifyRef free (+ 1))
      new <- readArray x i
      modifyRef change (\c -> maxF c (abs (new - old)))
    readRef change >>= writeArray stats (2 + s)
  readRef contacts >>= writeArray stats 0
  readRef free >>= writeArray stats 1

-- | Conditionals at their edges: for @i < meta[0]@, with @v = inp[i]@,
-- @out[i] = 2v@ where @v > 0@, else @3@ where @−v > 0@, else @7@ (so 0, −0
-- and NaN give 7), and @out2[i] = v·v + 1@. The value @v·v + 1@ is also
-- shared inside the first branch: after the conditional it must be
-- computed afresh, not referred to by a name bound in the branch's block.
signs :: Imp m => Array m -> Array m -> Array m -> Array m -> m ()
signs meta inp out out2 = do
  n <- toIndex <$> readArray meta 0
  forEach n $ \i -> do
    v <- readArray inp i
    ifPositive v
      (do _ <- share (v * v + 1)
          writeArray out i (2 * v))
      (ifPositive (negate v) (writeArray out i 3) (writeArray out i 7))
    writeArray out2 i (v * v + 1)

-- | Rows scaled by a subroutine: @out[r·m + c] = mat[r·m + c] · (r + 1) + k@
-- for every row, with @k@ read from meta; then row 0 once more through the
-- same subroutine from another call site (so it adds k twice there).
-- Staged, "scaleRow" must be printed once and called from both places.
scaleRows :: Imp m => Array m -> Array m -> Array m -> m ()
scaleRows meta mat out = do
  n <- readArray meta 0
  m <- readArray meta 1
  let row r cols = subroutine "scaleRow" [r, cols] $ \case
        [r', m'] -> do
          k <- readArray meta 2
          forEach (toIndex m') $ \c -> do
            let ix = toIndex (r' * m') + c
            x <- readArray mat ix
            writeArray out ix (x * (r' + 1) + k)
        _ -> error "arity"
  forEach (toIndex n) $ \r -> row (toScalar r) m
  whenPositive n $ do
    k <- readArray meta 2
    row 0 m
    forEach (toIndex m) $ \c -> readArray out c >>= \x -> writeArray out c (x + k)

-- Instances ------------------------------------------------------------------------

-- | A procedure's array arguments.
type Instance = [[Double]]

genPrefix :: Gen Instance
genPrefix = do
  n <- choose (0, 60)
  inp <- vectorOf n (oneof [choose (-1, 1), (* 1e8) <$> choose (-1, 1), (* 1e-8) <$> choose (-1, 1)])
  pure [[fromIntegral n], inp, replicate n 0]

genSigns :: Gen Instance
genSigns = do
  n <- choose (0, 20)
  inp <- vectorOf n (frequency [ (3, choose (-2, 2))
                               , (2, elements [0, -0, 0 / 0, 5e-324, -5e-324, 1 / 0, -1 / 0]) ])
  pure [[fromIntegral n], inp, replicate n 0, replicate n 0]

genRows :: Gen Instance
genRows = do
  n <- choose (0, 6)
  m <- choose (1, 5)
  k <- choose (-1, 1)
  mat <- vectorOf (n * m) (choose (-10, 10))
  pure [[fromIntegral n, fromIntegral m, k], mat, replicate (n * m) 0]

genSegmented :: Gen Instance
genSegmented = do
  nseg <- choose (0, 8)
  lens <- vectorOf nseg (choose (0, 7))
  let offs = scanl (+) 0 lens
  inp <- vectorOf (last offs) (choose (-10, 10))
  pure [[fromIntegral nseg], map fromIntegral offs, inp, replicate nseg (-1)]

genGaussSeidel :: Gen Instance
genGaussSeidel = do
  n <- choose (3, 30)
  sweeps <- choose (1, 6)
  let h = 1 / fromIntegral (n - 1)
  load <- choose (-40, -5) -- pushes x down onto the obstacle
  b <- vectorOf n ((+ load) <$> choose (-5, 5))
  -- An uneven obstacle: above the iterate at some nodes (contact), below
  -- at others (free), so both branches run in most instances.
  level <- choose (-0.1, 0.1)
  obs <- vectorOf n ((+ level) <$> choose (-0.25, 0.25))
  x0 <- vectorOf n (choose (0, 0.3))
  pure [[fromIntegral n, fromIntegral sweeps, h * h], x0, b, obs, replicate (2 + sweeps) 0]

-- Running ---------------------------------------------------------------------------

runNativeOn :: ([NativeArray] -> Native ()) -> Instance -> IO Instance
runNativeOn prog inst = do
  arrs <- mapM (V.thaw . V.fromList) inst
  runNative (prog arrs)
  mapM (fmap V.toList . V.freeze) arrs

-- | A staged procedure over named arrays.
staged :: String -> [String] -> ([StagedArray] -> Staged ()) -> String
staged name arrays prog = stageProcedure (Procedure name arrays []) (\as _ -> prog as)

-- | Rows of three: reads two of a row, then under a condition one of them
-- again and one beyond the row, and writes the third.
rowsOfThree :: Imp m => Array m -> Array m -> m ()
rowsOfThree meta a = do
  n <- toIndex <$> readArray meta 0
  forEach n $ \i -> do
    x <- readArray a (3 * i)
    y <- readArray a (3 * i + 1)
    whenPositive x $ do
      y' <- readArray a (3 * i + 1)
      z <- readArray a (3 * i + 5)
      writeArray a (3 * i + 1) (y' + z)
    writeArray a (3 * i + 2) (x + y)

bitsEq :: [[Double]] -> [[Double]] -> Bool
bitsEq a b = map (map castDoubleToWord64) a == map (map castDoubleToWord64) b

spec :: Spec
spec = do
  let prefixJs = staged "prefixSum" ["meta", "inp", "out"] (\case
        [m, i, o] -> prefixSum m i o
        _ -> error "arity")
      segJs = staged "segmented" ["meta", "off", "inp", "out"] (\case
        [m, f, i, o] -> segmented m f i o
        _ -> error "arity")
      gsJs = staged "gaussSeidel" ["meta", "x", "b", "obs", "stats"] (\case
        [m, x, b, o, s] -> gaussSeidel m x b o s
        _ -> error "arity")
      signsJs = staged "signs" ["meta", "inp", "out", "out2"] (\case
        [m, i, o, o2] -> signs m i o o2
        _ -> error "arity")
      nativeSigns = \case [m, i, o, o2] -> signs m i o o2; _ -> error "arity"
      nativePrefix = \case [m, i, o] -> prefixSum m i o; _ -> error "arity"
      nativeSeg = \case [m, f, i, o] -> segmented m f i o; _ -> error "arity"
      nativeGs = \case [m, x, b, o, s] -> gaussSeidel m x b o s; _ -> error "arity"

  it "prints a subroutine once, calls it from each place, and runs it as natively" $ do
    let rowsJs = staged "scaleRows" ["meta", "mat", "out"] (\case
          [m, a, o] -> scaleRows m a o
          _ -> error "arity")
        insts = unGen (vectorOf 30 genRows) (mkQCGen 99) 30
        calls = "[" ++ intercalate ",\n" [ "(() => { const a = [" ++ intercalate "," (map jsDoubles inst)
                                            ++ "].map(v => Float64Array.from(v)); scaleRows(...a); return a; })()" | inst <- insts ] ++ "]"
    length (filter ("function scaleRow(" `isInfixOf`) (lines rowsJs)) `shouldBe` 1
    length (filter (\ln -> "scaleRow(meta, mat, out, " `isInfixOf` ln && not ("function" `isInfixOf` ln)) (lines rowsJs)) `shouldBe` 2
    js <- runNodeJSON (rowsJs ++ "__emit(" ++ calls ++ ");\n") :: IO [[[Bits]]]
    nat <- mapM (runNativeOn (\case [m, a, o] -> scaleRows m a o; _ -> error "arity")) insts
    forM_ (zip3 insts nat js) $ \(inst, n, j) -> do
      unless (bitsEq n (map (map unBits) j)) $ expectationFailure ("scaleRows differs on " ++ show inst)
      let [[rows, cols, k], mat, _] = inst
          expected = [ x * (fromIntegral r + 1) + k + (if r == 0 then k else 0)
                     | (idx, x) <- zip [0 :: Int ..] mat, let r = idx `div` round cols ]
      unless (rows == 0 || and (zipWith (\a b -> abs (a - b) < 1e-12) (n !! 2) expected)) $
        expectationFailure ("scaleRows is wrong on " ++ show inst ++ ": " ++ show (n !! 2))

  it "checks a Haskell row's indices once per block: what the block reads anyway covers its conditions" $ do
    let printed = lines (concat (stageProceduresFor Haskell
          [(Procedure "rows" ["meta", "a"] [], \as _ -> case as of
              [m, a] -> rowsOfThree m a
              _ -> error "arity")]))
        checks = [ words ln | ln <- printed, "chkI" `elem` words ln ]
    -- the row's check covers offsets 0 to 2 (the write at +2 comes after
    -- the condition); the condition's +1 needs none, its +5 its own
    checks `shouldBe` [["chkI", "meta", "0", "0", "0"], ["chkI", "a", "(3", "*", "i1)", "0", "2"], ["chkI", "a", "(3", "*", "i1)", "5", "5"]]
    filter (\ln -> "rdI" `isInfixOf` ln || "wrI" `isInfixOf` ln) printed `shouldBe` []

  it "prints a Haskell procedure's locals as slots from 0 and its subroutine's from 32 of one array, checked once on entry" $ do
    let haskell = lines (concat (stageProceduresFor Haskell
          [(Procedure "outer" ["a"] [], \as _ -> case as of
              [a] -> do
                r <- newRef 1
                s <- newRef 2
                subroutine "inner" [] (\_ -> do
                  q <- newRef 3
                  readRef q >>= writeArray a 1)
                (+) <$> readRef r <*> readRef s >>= writeArray a 0
              _ -> error "arity")]))
        js = concat (stageProceduresFor JavaScript [(Procedure "outer" ["a"] [], \as _ -> case as of
              [a] -> newRef 1 >>= readRef >>= writeArray a 0
              _ -> error "arity")])
        trimmed = map (unwords . words) haskell
    trimmed `shouldContain` ["outer !a !locals = do", "chkI locals 0 0 1", "wrU locals 0 1.0", "wrU locals 1 2.0", "inner a locals"]
    trimmed `shouldContain` ["inner !a !locals = do", "chkI locals 0 32 32", "wrU locals 32 3.0"]
    filter (\ln -> any (`isInfixOf` ln) ["newR", "getR", "setR"]) haskell `shouldBe` []
    js `shouldSatisfy` (not . ("locals" `isInfixOf`))

  it "refuses a Haskell procedure with more locals than its slots, and a subroutine called from a subroutine" $ do
    let tooMany = stageProceduresFor Haskell [(Procedure "many" ["a"] [], \as _ -> case as of
          [a] -> mapM_ (\k -> newRef (fromIntegral k) >>= readRef >>= writeArray a 0) [1 .. 33 :: Int]
          _ -> error "arity")]
        nested = stageProceduresFor Haskell [(Procedure "nest" ["a"] [], \as _ -> case as of
          [a] -> subroutine "one" [] (\_ -> subroutine "two" [] (\_ -> writeArray a 0 1))
          _ -> error "arity")]
    evaluate (length (concat tooMany)) `shouldThrow` errorCall "the compiled step's locals: a procedure needs more than 32 (Manifold.Stage.Imp.localSlots)"
    evaluate (length (concat nested)) `shouldThrow` errorCall "subroutine two called from a subroutine: their locals would share slots"

  it "a failed index check is an error naming the indices, before any access" $ do
    arr <- primitiveArray <$> MV.replicate 4 (0 :: Double)
    chkI arr 1 0 2
    chkI arr 0 0 3
    outside <- try (chkI arr 2 0 2) :: IO (Either IOException ())
    either show (const "passed") outside `shouldSatisfy` ("indices 2 to 4 outside an array of 4" `isInfixOf`)
    below <- try (chkI arr 1 (-2) 0) :: IO (Either IOException ())
    either show (const "passed") below `shouldSatisfy` ("indices -1 to 1 outside an array of 4" `isInfixOf`)

  it "refuses two different bodies under one subroutine name" $ do
    let clash = staged "clash" ["a"] (\case
          [a] -> do
            subroutine "body" [] (\_ -> writeArray a 0 1)
            subroutine "body" [] (\_ -> writeArray a 0 2)
          _ -> error "arity")
    evaluate (length clash) `shouldThrow` errorCall "subroutine body: two different bodies under one name"

  it "prints the conditional with both branches and the loops nested" $ do
    gsJs `shouldSatisfy` ("} else {" `isInfixOf`)
    length (filter ("for (let" `isInfixOf`) (lines gsJs)) `shouldBe` 2
    length (filter ("for (let" `isInfixOf`) (lines segJs)) `shouldBe` 2

  it "prefix sums, segmented sums and projected Gauss-Seidel: native and node arrays are identical" $ do
    let gen = (,,,) <$> vectorOf 40 genPrefix <*> vectorOf 40 genSegmented <*> vectorOf 60 genGaussSeidel
                        <*> vectorOf 30 genSigns
        (prefixes, segs, gss, sgs) = unGen gen (mkQCGen 777) 30
        jsArr xs = "[" ++ intercalate ",\n" xs ++ "]"
        -- Each instance: its arrays as Float64Arrays, the procedure called
        -- on them, the arrays returned.
        callAll fn insts = jsArr [ "(() => { const a = " ++ jsArr (map jsDoubles inst)
                                     ++ ".map(v => Float64Array.from(v)); " ++ fn ++ "(...a); return a; })()"
                                 | inst <- insts ]
        script = prefixJs ++ segJs ++ gsJs ++ signsJs
          ++ "__emit([" ++ intercalate ",\n" [ callAll "prefixSum" prefixes, callAll "segmented" segs
                                               , callAll "gaussSeidel" gss, callAll "signs" sgs ] ++ "]);\n"
    [jsP, jsS, jsG, jsC] <- runNodeJSON script :: IO [[[[Bits]]]]
    natP <- mapM (runNativeOn nativePrefix) prefixes
    natS <- mapM (runNativeOn nativeSeg) segs
    natG <- mapM (runNativeOn nativeGs) gss
    natC <- mapM (runNativeOn nativeSigns) sgs
    let compareAll what nats jss insts = do
          length jss `shouldBe` length nats
          forM_ (zip3 insts nats jss) $ \(inst, nat, js) ->
            unless (bitsEq nat (map (map unBits) js)) $ expectationFailure $
              what ++ " differs on input " ++ show inst ++ "\nnative: " ++ show nat ++ "\nnode:   " ++ show js
    compareAll "prefixSum" natP jsP prefixes
    compareAll "segmented" natS jsS segs
    compareAll "gaussSeidel" natG jsG gss
    compareAll "signs" natC jsC sgs
    -- The native results are right (so the comparison is not between two
    -- equally broken programs).
    forM_ (zip prefixes natP) $ \(inst, res) -> res !! 2 `shouldBe` tail (scanl (+) 0 (inst !! 1))
    forM_ (zip sgs natC) $ \(inst, res) ->
      res !! 2 `shouldBe` [ if v > 0 then 2 * v else if negate v > 0 then 3 else 7 | v <- inst !! 1 ]
    -- Both branches of the conditional were taken, in most instances both
    -- within the same run.
    let counts = [ (c, f) | [_, _, _, _, c : f : _] <- natG ]
        both = length [ () | (c, f) <- counts, c > 0, f > 0 ]
    printf "gauss-seidel: %d instances, %d take both branches; contacts %.0f, free updates %.0f\n"
      (length counts) both (sum (map fst counts)) (sum (map snd counts))
    sum (map fst counts) `shouldSatisfy` (> 0)
    sum (map snd counts) `shouldSatisfy` (> 0)
    both `shouldSatisfy` (>= length counts `div` 2)
    -- Gauss–Seidel did its work: x >= obs everywhere after the sweeps.
    forM_ (zip gss natG) $ \(inst, res) ->
      let x = res !! 1; obs = inst !! 3
      in when (or (zipWith (<) (init (tail x)) (init (tail obs)))) $
           expectationFailure ("x below the obstacle: " ++ show inst)
