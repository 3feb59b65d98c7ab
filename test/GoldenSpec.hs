-- | The golden runs ("Manifold.Golden"): each catalogue scene, run by the
-- compiled native step, by the generic one (all but the benchmark piles)
-- and by the page's engine under node (all but four of the 1000-body
-- piles), ends on the state hash
-- test/golden/hashes holds, bit for bit; and
-- so does a run saved halfway (as a scene file) and loaded again, in both
-- engines, on every space.
module GoldenSpec (spec) where

import Control.Monad (forM, forM_, replicateM_)
import qualified Data.Aeson as A
import qualified Data.ByteString.Lazy.Char8 as BL
import Data.List (isSuffixOf)
import System.FilePath ((</>))
import System.IO.Temp (withSystemTempDirectory)
import System.Process (readProcess)
import Test.Hspec

import Manifold.Build (generatedFilesWith, writeGenerated)
import Manifold.Engine (stateHash, stepNative)
import Manifold.Golden
import Manifold.Scene (loadScene, parseScene, sceneJSON, sceneOfWorld)
import Manifold.Spaces (catalogue)
import Manifold.StateHash (showHash)
import TestUtil (scriptOf)

-- | Where the golden hashes are kept, relative to the repository.
goldenFile :: FilePath
goldenFile = "test/golden/hashes"

-- | The golden file's lines: name, steps, hash.
readGolden :: IO [(String, (String, String))]
readGolden = do
  text <- readFile goldenFile
  pure [ (name, (steps, hash)) | l <- lines text, [name, steps, hash] <- [words l] ]

-- | What to do when a hash changed: it names the command.
changed :: String -> String -> String -> String -> String
changed engine name want got =
  engine ++ ": " ++ name ++ " ended on " ++ got ++ ", the golden hash is " ++ want
    ++ " (the physics changed; if that is meant, run scripts/regolden and commit test/golden/hashes)"

-- | Compare one engine's lines for every golden run with the golden file.
compareWith :: String -> [(String, String, String)] -> IO ()
compareWith engine got = do
  golden <- readGolden
  map (\(name, _, _) -> name) got `shouldBe` map fst golden
  compareSome (changed engine) engine got

-- | Compare the lines of some of the runs with the golden file; a hash
-- that differs gets @mismatch name want got@.
compareSome :: (String -> String -> String -> String) -> String -> [(String, String, String)] -> IO ()
compareSome mismatch engine got = do
  golden <- readGolden
  forM_ got $ \(name, steps, hash) -> case lookup name golden of
    Just (steps', want)
      | steps /= steps' -> expectationFailure (engine ++ ": " ++ name ++ " ran " ++ steps ++ " steps, the golden file says " ++ steps')
      | hash /= want -> expectationFailure (mismatch name want hash)
      | otherwise -> pure ()
    Nothing -> expectationFailure (engine ++ ": " ++ name ++ " is not in " ++ goldenFile ++ " (run scripts/regolden)")

-- | The native engine's lines.
nativeLines :: Bool -> IO [(String, String, String)]
nativeLines generic = forM (if generic then genericRuns else goldenRuns) $ \run -> do
  r <- runHash generic (grSteps run) (grScene run)
  case r of
    Left e -> fail (grName run ++ ": " ++ e)
    Right h -> pure (grName run, show (grSteps run), showHash h)

-- | The runs the generic step checks: all but the benchmark piles (the
-- compiled step's code at more bodies, 95 % of the generic step's time
-- over every run: 111 s of the suite), and the rectangle's 300-body pile
-- (contacts, islands and sleep at scale, walls).
genericRuns :: [GoldenRun]
genericRuns = filter (\run -> grName run == "rectangle-300" || not (any (`isSuffixOf` grName run) ["-300", "-1000"])) goldenRuns

-- | The runs the page's engine checks: all but four of the 1000-body
-- benchmark piles, of which the flat and the curved one are kept (the
-- others are the 300-body piles' code on the same spaces, at more bodies,
-- and took 16 s of node's time; the compiled native step runs them all).
pageRuns :: [GoldenRun]
pageRuns = filter (\run -> grName run `elem` ["plane-1000", "sphere-1000"] || not ("-1000" `isSuffixOf` grName run)) goldenRuns

-- | The runs saved and continued: every run but the benchmark piles, of
-- which the flat and the curved 300-body ones (the others are the same
-- code on other spaces, or at more bodies; every space's default scene is
-- saved and continued).
splitRuns :: [GoldenRun]
splitRuns = filter (\run -> grName run `elem` ["rectangle-300", "sphere-300"] || not (any (`isSuffixOf` grName run) ["-300", "-1000"])) goldenRuns

-- | Where a run is saved: after about two fifths of its steps (an odd
-- number, mid-pile).
splitAt' :: GoldenRun -> Int
splitAt' run = 2 * grSteps run `div` 5 + 1

-- | The native lines of the runs saved after 'splitAt'' steps, as JSON
-- text, loaded again and run on.
nativeSplitLines :: IO [(String, String, String)]
nativeSplitLines = forM splitRuns $ \run -> do
  let orFail = either (fail . ((grName run ++ ": ") ++)) pure
  w <- loadScene 0 (grScene run) >>= orFail
  replicateM_ (splitAt' run) (stepNative w)
  saved <- sceneOfWorld (grScene run) w >>= orFail
  again <- orFail (parseScene (A.encode (sceneJSON saved)))
  w' <- loadScene 0 again >>= orFail
  replicateM_ (grSteps run - splitAt' run) (stepNative w')
  h <- stateHash w'
  pure (grName run, show (grSteps run), showHash h)

-- | The page's engine's lines (node running test/hashes.mjs over the
-- generated scripts and the golden scenes written to a temporary
-- directory), whole or saved after 'splitAt'' steps.
pageLines :: Bool -> [GoldenRun] -> IO [(String, String, String)]
pageLines split runs =
  withSystemTempDirectory "manifold-golden" $ \dir -> do
    let gen = dir </> "gen"
    writeGenerated gen (generatedFilesWith scriptOf catalogue)
    forM_ runs $ \run -> BL.writeFile (dir </> (grName run ++ ".json")) (A.encode (sceneJSON (grScene run)))
    out <- readProcess "node" (["test/hashes.mjs", gen, dir] ++
             [ grName run ++ ":" ++ show (grSteps run) ++ (if split then ":" ++ show (splitAt' run) else "") | run <- runs ]) ""
    pure [ (name, steps, hash) | l <- lines out, [name, steps, hash] <- [words l] ]

-- | What a saved and continued run that ends elsewhere gets.
splitMismatch :: String -> String -> String -> String -> String
splitMismatch engine name want got =
  engine ++ ": " ++ name ++ ", saved and continued, ended on " ++ got ++ ", the uninterrupted run on " ++ want

spec :: Spec
spec = describe "golden state hashes (test/golden/hashes)" $ do
  it "lists every golden run, each once" $ do
    golden <- readGolden
    map fst golden `shouldBe` map grName goldenRuns
  it "the compiled native step ends every golden run on its hash" $
    nativeLines False >>= compareWith "compiled native step"
  it "the generic native step ends every golden run but the benchmark piles (one of them kept) on its hash" $ do
    got <- nativeLines True
    length got `shouldBe` length genericRuns
    compareSome (changed "generic native step") "generic native step" got
  it "the page's engine (under node) ends every golden run but four of the 1000-body piles on its hash" $ do
    got <- pageLines False pageRuns
    length got `shouldBe` length pageRuns
    compareSome (changed "page's engine") "page's engine" got
  it "a run saved as a scene and loaded again ends where the uninterrupted run does, natively, on every space" $ do
    got <- nativeSplitLines
    length got `shouldBe` length splitRuns
    compareSome (splitMismatch "native step") "native step" got
  it "a run saved by the page (scene(), JSON) and loaded again ends where the uninterrupted run does, on every space" $ do
    got <- pageLines True splitRuns
    length got `shouldBe` length splitRuns
    compareSome (splitMismatch "page's engine") "page's engine" got
