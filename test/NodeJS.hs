-- | A small harness for running generated JavaScript under @node@.
--
-- A test batch is ONE node process: the spec builds one script (the
-- generated code under test followed by a driver), this module writes it to
-- a temporary file, runs @node FILE@, and decodes the JSON the script prints
-- as the last line of its standard output.
--
-- Numbers cross the process boundary as IEEE-754 bit patterns (16 hex digits,
-- big-endian), in both directions, so NaN, the infinities and @-0@ survive
-- exactly and no decimal conversion can blur a comparison:
--
-- * Haskell → JS: 'jsDouble' prints @__fromBits("…")@, 'jsDoubles' an array;
-- * JS → Haskell: the driver calls @__emit(v)@, which replaces every number
--   in @v@ (deeply, through arrays and objects) by its bit string, and the
--   Haskell side decodes those with 'Bits';
-- * a world's arrays, both ways: 'runNodeOverArrays' hands them over as
--   little-endian doubles in a file and reads them back the same way
--   (exact, and quicker than text for the hundreds of thousands of numbers
--   a world holds).
module NodeJS
  ( nodePrelude
  , runNode
  , runNodeJSON
  , runNodeOverArrays
  , arraysScript
  , Bits (..)
  , jsDouble
  , jsDoubles
  , doubleBits
  , bitsDouble
  , findNode
  ) where

import Control.Exception (SomeException, try)
import qualified Data.Aeson as A
import qualified Data.Aeson.Types as A
import Data.Bits (shiftL, (.|.))
import qualified Data.ByteString as BS
import Data.ByteString.Builder (doubleLE, toLazyByteString)
import qualified Data.ByteString.Lazy.Char8 as BL
import qualified Data.Text as T
import Data.List (intercalate)
import Data.Word (Word64)
import GHC.Float (castDoubleToWord64, castWord64ToDouble)
import Numeric (readHex, showHex)
import System.Directory (findExecutable)
import System.Exit (ExitCode (..))
import System.FilePath ((</>))
import System.IO (IOMode (..), hClose, hPutStr, hSetEncoding, openFile, utf8)
import System.IO.Temp (withSystemTempDirectory)
import System.Process (readProcessWithExitCode)

-- | Helpers every batch script starts with: @__fromBits@, @__bits@ and
-- @__emit@.
nodePrelude :: String
nodePrelude = unlines
  [ "\"use strict\";"
  , "const __dv = new DataView(new ArrayBuffer(8));"
  , "function __fromBits(h) {"
  , "  __dv.setUint32(0, parseInt(h.slice(0, 8), 16));"
  , "  __dv.setUint32(4, parseInt(h.slice(8, 16), 16));"
  , "  return __dv.getFloat64(0);"
  , "}"
  , "function __bits(x) {"
  , "  __dv.setFloat64(0, x);"
  , "  return __dv.getUint32(0).toString(16).padStart(8, '0') + __dv.getUint32(4).toString(16).padStart(8, '0');"
  , "}"
  , "function __enc(v) {"
  , "  if (typeof v === 'number') return __bits(v);"
  , "  if (v instanceof Float64Array) return Array.from(v, __bits);"
  , "  if (Array.isArray(v)) return v.map(__enc);"
  , "  if (v !== null && typeof v === 'object') { const o = {}; for (const k of Object.keys(v)) o[k] = __enc(v[k]); return o; }"
  , "  return v;"
  , "}"
  , "function __emit(v) { process.stdout.write(JSON.stringify(__enc(v)) + '\\n'); }"
  ]

-- | The bit pattern of a double as 16 hex digits.
doubleBits :: Double -> String
doubleBits x = let h = showHex (castDoubleToWord64 x) "" in replicate (16 - length h) '0' ++ h

bitsDouble :: String -> Maybe Double
bitsDouble s
  | length s == 16, [(w, "")] <- readHex s = Just (castWord64ToDouble (w :: Word64))
  | otherwise = Nothing

-- | A JavaScript expression evaluating to exactly this double.
jsDouble :: Double -> String
jsDouble x = "__fromBits(\"" ++ doubleBits x ++ "\")"

-- | A JavaScript array of exactly these doubles.
jsDoubles :: [Double] -> String
jsDoubles xs = "[" ++ intercalate "," (map jsDouble xs) ++ "]"

-- | A double sent back by @__emit@.
newtype Bits = Bits { unBits :: Double }

instance Show Bits where
  show (Bits x) = show x

instance A.FromJSON Bits where
  parseJSON = A.withText "bit string" $ \t ->
    maybe (A.parseFail ("not a 16-digit bit string: " ++ T.unpack t)) (pure . Bits) (bitsDouble (T.unpack t))

findNode :: IO FilePath
findNode = findExecutable "node" >>= maybe (fail "node is not on PATH") pure

-- | Run a script (the prelude is prepended) in one node process; its
-- standard output. A non-zero exit fails with node's standard error.
runNode :: String -> IO String
runNode script = do
  node <- findNode
  withSystemTempDirectory "manifold-node" $ \dir -> do
    let file = dir </> "batch.js"
    writeUtf8 file (nodePrelude ++ script)
    r <- try (readProcessWithExitCode node [file] "")
           :: IO (Either SomeException (ExitCode, String, String))
    case r of
      Left e -> fail ("could not run node: " ++ show e)
      Right (ExitSuccess, out, _) -> pure out
      Right (ExitFailure c, out, err) ->
        fail ("node exited with " ++ show c ++ "\nstderr:\n" ++ take 4000 err ++ "\nstdout:\n" ++ take 2000 out)
  where
    writeUtf8 path s = do
      h <- openUtf8 path
      hPutStr h s >> hClose h
    openUtf8 path = do
      h <- openFile path WriteMode
      hSetEncoding h utf8
      pure h

-- | Run a script whose last line of output is one @__emit(...)@ and decode it.
runNodeJSON :: A.FromJSON a => String -> IO a
runNodeJSON script = do
  out <- runNode script
  case reverse (lines out) of
    [] -> fail "node printed nothing"
    (l : _) -> case A.eitherDecode (BL.pack l) of
      Right v -> pure v
      Left e -> fail ("cannot decode node's output: " ++ e ++ "\n" ++ take 2000 l)

-- | Write arrays of doubles to @file@ as little-endian doubles; the
-- JavaScript that reads them back, bit for bit, as @__arrays@
-- (Float64Arrays).
arraysScript :: FilePath -> [[Double]] -> IO String
arraysScript file arrays = do
  BL.writeFile file (toLazyByteString (foldMap (foldMap doubleLE) arrays))
  pure $ unlines
    [ "const __input = require('fs').readFileSync(" ++ show file ++ ");"
    , "const __bytes = __input.buffer.slice(__input.byteOffset, __input.byteOffset + __input.length);"
    , "let __offset = 0;"
    , "const __arrays = " ++ show (map length arrays) ++ ".map(n => { const x = new Float64Array(__bytes, 8 * __offset, n).slice(); __offset += n; return x; });"
    ]

-- | Run a script over arrays of doubles: the script (after the prelude)
-- finds them as @__arrays@ ('arraysScript') and ends with
-- @__emitArrays(xs)@; the arrays @xs@ it hands back. Both ways the numbers
-- go as little-endian doubles through a file, bit for bit.
runNodeOverArrays :: [[Double]] -> String -> IO [[Double]]
runNodeOverArrays initial script =
  withSystemTempDirectory "manifold-arrays" $ \dir -> do
    let output = dir </> "out.bin"
    input <- arraysScript (dir </> "in.bin") initial
    out <- runNode $ unlines
      [ input
      , "function __emitArrays(xs) {"
      , "  const b = Buffer.alloc(8 * xs.reduce((s, x) => s + x.length, 0));"
      , "  let o = 0;"
      , "  for (const x of xs) for (let i = 0; i < x.length; i++, o++) b.writeDoubleLE(x[i], 8 * o);"
      , "  require('fs').writeFileSync(" ++ show output ++ ", b);"
      , "  process.stdout.write(JSON.stringify(xs.map(x => x.length)) + '\\n');"
      , "}"
      , script
      ]
    lengths <- case reverse (lines out) of
      (l : _) | Just ns <- A.decode (BL.pack l) -> pure (ns :: [Int])
      _ -> fail ("node handed back no arrays: " ++ take 300 out)
    bytes <- BS.readFile output
    let double k = castWord64ToDouble (foldr (\b acc -> acc `shiftL` 8 .|. fromIntegral (BS.index bytes (8 * k + b))) 0 [0 .. 7])
        split _ [] = []
        split k (n : ns) = map double [k .. k + n - 1] : split (k + n) ns
    if BS.length bytes /= 8 * sum lengths
      then fail ("node wrote " ++ show (BS.length bytes) ++ " bytes for arrays of " ++ show lengths ++ " numbers")
      else pure (split 0 lengths)
