{-# LANGUAGE OverloadedStrings #-}
-- | The @manifold@ command, run as a process.
module CliSpec (spec) where

import Control.Monad (forM_, (>=>))
import Data.Aeson ((.:))
import qualified Data.Aeson as A
import qualified Data.Aeson.Types as A
import qualified Data.ByteString.Char8 as BC
import qualified Data.ByteString.Lazy as BL
import Data.List (isInfixOf, isPrefixOf, sort)
import Linear.Metric (dot)
import Linear.V3 (V3 (..), cross)
import System.Directory (createDirectoryIfMissing, doesDirectoryExist)
import System.Exit (ExitCode (..))
import System.FilePath ((</>))
import System.IO.Temp (withSystemTempDirectory)
import Test.Hspec

import Manifold
import Manifold.Bench (benchScene)
import Manifold.Scene (BodySpec (..), Scene (..), parseScene, sceneJSON)
import TestUtil

data SpaceInfo = SpaceInfo
  { siName :: String
  , siDescription :: String
  , siQuotient :: String
  , siMetric :: String
  , siHasBoundary :: Bool
  } deriving (Show, Eq)

instance A.FromJSON SpaceInfo where
  parseJSON = A.withObject "space" $ \o ->
    SpaceInfo <$> o .: "name" <*> o .: "description" <*> o .: "quotient" <*> o .: "metric" <*> o .: "hasBoundary"

data GeodesicOut = GeodesicOut
  { goPoints :: [[Double]]
  , goEnd :: [Double]
  , goEndDir :: [Double]
  } deriving (Show, Eq)

instance A.FromJSON GeodesicOut where
  parseJSON = A.withObject "geodesic" $ \o ->
    GeodesicOut <$> o .: "points" <*> o .: "end" <*> o .: "endDir"

-- | How many rounds a result of @manifold bench --json@ kept the fastest of.
newtype BenchRounds = BenchRounds Int deriving (Show, Eq)

instance A.FromJSON BenchRounds where
  parseJSON = A.withObject "bench result" $ \o -> BenchRounds <$> o .: "rounds"

-- | What a bench result says of how its scene was settled (null: timed as read).
newtype BenchSettle = BenchSettle (Maybe Int) deriving (Show, Eq)

instance A.FromJSON BenchSettle where
  parseJSON = A.withObject "bench result" $ \o -> BenchSettle <$> o .: "settle"

-- | What a bench result says of the contact settings and warm-up it was timed with.
data BenchContacts = BenchContacts
  { bcSubsteps :: Int, bcIterations :: Int, bcSlop :: Double, bcSize :: Double, bcWarmup :: Int, bcRows :: Double }
  deriving (Show, Eq)

instance A.FromJSON BenchContacts where
  parseJSON = A.withObject "bench result" $ \o ->
    BenchContacts <$> o .: "substeps" <*> o .: "iterations" <*> o .: "slop" <*> o .: "size" <*> o .: "warmup" <*> o .: "contacts"

expectedNames :: [String]
expectedNames =
  [ "plane", "sphere", "torus", "trumpet", "cube", "hemisphere", "disc", "rectangle"
  , "projective-plane", "klein-bottle", "moebius", "funnel", "flat-torus", "flat-klein"
  , "hyperbolic-plane", "bolza" ]

toV3 :: [Double] -> Maybe (V3 Double)
toV3 [x, y, z] = Just (V3 x y z)
toV3 _ = Nothing

csv :: V3 Double -> String
csv (V3 x y z) = show x ++ "," ++ show y ++ "," ++ show z

-- | The direction given to every geodesic (projected by the command).
cliDir :: V3 Double
cliDir = V3 1 0.2 0.7

cliLength, cliStep :: Double
cliLength = 1
cliStep = 0.01

spec :: Spec
spec = do
  exe <- runIO findManifoldExe
  runIO (putStrLn ("manifold executable: " ++ exe))
  -- stdout as UTF-8 bytes, stderr as a String of its bytes (the checks on
  -- it are about ASCII names and line counts).
  let run args = do
        (code, out, err) <- runBytes exe args
        pure (code, out, BC.unpack err)

  describe "manifold spaces" $ do
    it "--json lists exactly the spaces of the catalogue, with name, description, quotient, metric and hasBoundary" $ do
      (code, out, err) <- run ["spaces", "--json"]
      code `shouldBe` ExitSuccess
      err `shouldBe` ""
      case A.eitherDecode out :: Either String [SpaceInfo] of
        Left e -> expectationFailure ("spaces --json does not parse: " ++ e ++ "\n" ++ show out)
        Right infos -> do
          map siName infos `shouldBe` expectedNames
          forM_ infos $ \i -> do
            siDescription i `shouldSatisfy` (not . null)
            siQuotient i `shouldSatisfy` (`elem` ["none", "antipodal", "translations", "glide", "octagon"])
          -- Against what is known of the spaces (independently of the library).
          [siName i | i <- infos, siQuotient i == "antipodal"]
            `shouldBe` ["projective-plane", "klein-bottle", "moebius"]
          [(siName i, siQuotient i) | i <- infos, siQuotient i `elem` ["translations", "glide"]]
            `shouldBe` [("flat-torus", "translations"), ("flat-klein", "glide")]
          sort [siName i | i <- infos, siHasBoundary i]
            `shouldBe` sort ["hemisphere", "disc", "rectangle", "moebius", "funnel"]
          [siName i | i <- infos, siMetric i /= "euclidean"] `shouldBe` ["hyperbolic-plane", "bolza"]
          [siMetric i | i <- infos, siName i `elem` ["hyperbolic-plane", "bolza"]] `shouldBe` ["minkowski", "minkowski"]
          [siName i | i <- infos, siQuotient i == "octagon"] `shouldBe` ["bolza"]
    it "the library's catalogue has the same names" $
      spaceNames `shouldBe` expectedNames
    it "without --json prints one line per space, starting with its name" $ do
      (code, out, _) <- run ["spaces"]
      code `shouldBe` ExitSuccess
      let ls = BC.lines (BL.toStrict out)
      length ls `shouldBe` length expectedNames
      and (zipWith isPrefixOf expectedNames (map BC.unpack ls)) `shouldBe` True

  describe "manifold geodesic --json" $
    forM_ catalogue $ \s -> do
      let from = firstPlacement s
      it (spaceName s ++ ": from the first body of the scene " ++ showV3 from ++ " along " ++ showV3 cliDir) $ do
        let args = [ "geodesic", "--space", spaceName s, "--from", csv from, "--dir", csv cliDir
                   , "--length", show cliLength, "--step", show cliStep, "--json" ]
        (code, out, err) <- run args
        (unwords args, code, err) `shouldSatisfy` (\(_, c, _) -> c == ExitSuccess)
        case A.eitherDecode out of
          Left e -> expectationFailure ("geodesic --json does not parse: " ++ e ++ "\n" ++ show (BL.take 300 out))
          Right g -> do
            let Just pts = mapM toV3 (goPoints g)
                Just end = toV3 (goEnd g)
                Just endDir = toV3 (goEndDir g)
                f = spaceField s
                m = spaceMetric s
                start = projectToSurface f from
            length pts `shouldSatisfy` (>= 2)
            -- End is the last point, exactly.
            goEnd g `shouldBe` last (goPoints g)
            -- Every point is on the surface.
            maximum (map (abs . evalField s) pts) `shouldSatisfy` (< 1e-9)
            -- It starts at the projected start point.
            vecDist (head pts) start `shouldSatisfy` (< 1e-9)
            -- It is a polyline of the requested length under the space's metric (to 1 %).
            let len = sum (zipWith (\a b -> normIn m (b - a)) pts (tail pts))
            (len, relErr cliLength len) `shouldSatisfy` ((< 0.01) . snd)
            -- The end direction is a unit tangent vector.
            normIn m endDir `shouldSatisfy` closeAbs 1e-9 1
            abs (inner m (unitNormal m f end) endDir) `shouldSatisfy` (< 1e-9)

  it "geodesic on the sphere stays on the great circle of its start and direction" $ do
    (code, out, _) <- run [ "geodesic", "--space", "sphere", "--from", "0,0,2", "--dir", "1,1,0"
                          , "--length", "3", "--step", "0.01", "--json" ]
    code `shouldBe` ExitSuccess
    case A.eitherDecode out of
      Left e -> expectationFailure e
      Right g -> do
        let Just pts = mapM toV3 (goPoints g)
            nrm = V3 0 0 1 `cross` V3 1 1 0
        maximum [abs (p `dot` nrm) | p <- pts] `shouldSatisfy` (< 1e-9)
        -- length 3 along the great circle from the north pole (0,0,1)
        vecDist (last pts) (V3 (sin 3 / sqrt 2) (sin 3 / sqrt 2) (cos 3)) `shouldSatisfy` (< 1e-3)

  describe "manifold geodesic errors: exit code 2 and a one-line message on stderr" $ do
    let failsWith args check = do
          (code, out, err) <- run args
          code `shouldBe` ExitFailure 2
          out `shouldBe` BL.empty
          (err, length (lines err)) `shouldSatisfy` ((== 1) . snd)
          err `shouldSatisfy` check
    it "unknown space (the message lists the valid names)" $
      failsWith ["geodesic", "--space", "nowhere", "--from", "0,1,0", "--dir", "1,0,0", "--length", "1"] $ \err ->
        "nowhere" `isInfixOf` err && all (`isInfixOf` err) expectedNames
    it "malformed number in --from" $
      failsWith ["geodesic", "--space", "sphere", "--from", "0,abc,0", "--dir", "1,0,0", "--length", "1"]
        ("abc" `isInfixOf`)
    it "malformed --from (two components)" $
      failsWith ["geodesic", "--space", "sphere", "--from", "0,1", "--dir", "1,0,0", "--length", "1"]
        (const True)
    it "malformed number in --length" $
      failsWith ["geodesic", "--space", "sphere", "--from", "0,1,0", "--dir", "1,0,0", "--length", "1.2.3"]
        ("1.2.3" `isInfixOf`)
    it "malformed number in --step" $
      failsWith ["geodesic", "--space", "sphere", "--from", "0,1,0", "--dir", "1,0,0", "--length", "1", "--step", "x"]
        (const True)
    it "non-finite number (NaN)" $
      failsWith ["geodesic", "--space", "sphere", "--from", "0,1,0", "--dir", "NaN,0,0", "--length", "1"]
        (const True)
    it "zero direction" $
      failsWith ["geodesic", "--space", "sphere", "--from", "0,1,0", "--dir", "0,0,0", "--length", "1"]
        ("--dir" `isInfixOf`)
    it "direction normal to the surface" $
      failsWith ["geodesic", "--space", "sphere", "--from", "0,1,0", "--dir", "0,3,0", "--length", "1"]
        ("--dir" `isInfixOf`)
    it "start where the gradient vanishes (the sphere's centre)" $
      failsWith ["geodesic", "--space", "sphere", "--from", "0,0,0", "--dir", "1,0,0", "--length", "1"]
        ("--from" `isInfixOf`)
    it "negative length and non-positive step" $ do
      failsWith ["geodesic", "--space", "sphere", "--from", "0,1,0", "--dir", "1,0,0", "--length=-1"] (const True)
      failsWith ["geodesic", "--space", "sphere", "--from", "0,1,0", "--dir", "1,0,0", "--length", "1", "--step", "0"] (const True)

  describe "manifold build" $
    -- (what a build writes, the preset scenes with the rest, is checked in
    -- "byte stability and manifold build", from the builds made there)
    it "refuses a bad preset or a missing --scenes with exit code 2, writing nothing" $
      withSystemTempDirectory "manifold-build" $ \dir -> do
        let scenes = dir </> "scenes"
            out = dir </> "fresh"
        createDirectoryIfMissing True scenes
        BL.writeFile (scenes </> "sphere-rain.json") "{\"space\": \"torus\"}"
        forM_ [ (["build", "--out", out, "--scenes", scenes], "scenes/sphere-rain.json: a scene of torus, but the name says sphere")
              , (["build", "--out", out, "--scenes", dir </> "none"], "no such directory") ] $ \(args, message) -> do
          (c, o, e) <- run args
          (args, c, o, message `isInfixOf` e, length (lines e)) `shouldBe` (args, ExitFailure 2, "", True, 1)
          doesDirectoryExist out `shouldReturn` False
  describe "manifold sim" $ do
    let frameSteps :: BL.ByteString -> Either String [Int]
        frameSteps = A.eitherDecode >=> A.parseEither (A.withObject "sim" $ \o -> o .: "frames" >>= mapM (A.withObject "frame" (.: "step")))
        lastBodies :: BL.ByteString -> Either String A.Value
        lastBodies = A.eitherDecode >=> A.parseEither (A.withObject "sim" $ \o -> o .: "frames" >>= \fs -> case reverse fs of
          f : _ -> A.withObject "frame" (.: "bodies") f
          [] -> fail "no frames")
    it "prints a frame every M steps and the last, and refuses bad input with exit code 2 and nothing on standard output" $
      withSystemTempDirectory "manifold-sim" $ \dir -> do
        let file = dir </> "scene.json"
        BL.writeFile file (A.encode (sceneJSON (benchScene torus 10)))
        (code, out, err) <- run ["sim", file, "--steps", "5", "--every", "2"]
        (code, err) `shouldBe` (ExitSuccess, "")
        frameSteps out `shouldBe` Right [0, 2, 4, 5]
        BL.writeFile (dir </> "bad.json") "{\"space\": \"torus\", \"bodies\": [{\"shape\": \"circle\", \"size\": -1, \"p\": [1.3, 0, 0]}]}"
        forM_ [ (["sim", dir </> "bad.json", "--steps", "5"], "$.bodies[0].size: must be positive")
              , (["sim", dir </> "none.json", "--steps", "5"], "no such scene file")
              , (["sim", file, "--steps", "-1"], "--steps: must not be negative")
              , (["sim", file, "--steps", "5", "--every", "0"], "--every: must be at least 1")
              , (["sim", file, "--steps", "5", "--save", dir </> "missing" </> "out.json"], "--save: the directory") ] $ \(args, message) -> do
          (c, o, e) <- run args
          (args, c, o, message `isInfixOf` e, length (lines e)) `shouldBe` (args, ExitFailure 2, "", True, 1)
    it "--save writes the scene after the last step, and running it on is running on: 200 + 100 steps of a pile are 300 steps, bit for bit, flat or curved" $
      forM_ [rectangle, sphere] $ \sp -> withSystemTempDirectory "manifold-sim" $ \dir -> do
        let file = dir </> "scene.json"
            mid = dir </> "mid.json"
        BL.writeFile file (A.encode (sceneJSON (benchScene sp 100)))
        (code1, _, _) <- run ["sim", file, "--steps", "200", "--every", "200", "--save", mid]
        (code2, split, _) <- run ["sim", mid, "--steps", "100", "--every", "100"]
        (code3, whole, _) <- run ["sim", file, "--steps", "300", "--every", "300"]
        (code1, code2, code3) `shouldBe` (ExitSuccess, ExitSuccess, ExitSuccess)
        saved <- BL.readFile mid >>= either (\e -> fail ("mid.json: " ++ e)) pure . parseScene
        -- the pile has formed: its bodies remember their contacts
        length (concatMap bsImpulses (sceneBodies saved)) `shouldSatisfy` (> 100)
        lastBodies split `shouldBe` lastBodies whole
        lastBodies whole `shouldSatisfy` either (const False) (const True)
        (code4, hashSplit, _) <- run ["sim", mid, "--steps", "100", "--hash"]
        (code5, hashWhole, _) <- run ["sim", file, "--steps", "300", "--hash"]
        (code4, code5, hashSplit) `shouldBe` (ExitSuccess, ExitSuccess, hashWhole)
    it "--hash prints only the state's hash: the golden file's for a golden scene, another one step later (scenes still moving: a sleeping one stays put)" $
      withSystemTempDirectory "manifold-sim" $ \dir -> do
        (code, _, _) <- run ["hashes", "--scenes", dir]
        code `shouldBe` ExitSuccess
        golden <- lines <$> readFile "test/golden/hashes"
        let wanted = [ (name, steps, hash) | l <- golden, [name, steps, hash] <- [words l], name `elem` ["torus-default", "sphere-chain"] ]
        length wanted `shouldBe` 2
        forM_ wanted $ \(name, steps, hash) -> do
          (c, out, err) <- run ["sim", dir </> (name ++ ".json"), "--steps", steps, "--hash"]
          (c, err, out) `shouldBe` (ExitSuccess, "", BL.fromStrict (BC.pack (hash ++ "\n")))
          (_, later, _) <- run ["sim", dir </> (name ++ ".json"), "--steps", show (read steps + 1 :: Int), "--hash"]
          later `shouldNotBe` out
    it "hashes refuses bad input with exit code 2 and nothing on standard output" $
      forM_ [ (["hashes", "--steps", "-1"], "--steps: must not be negative")
            , (["hashes", "--scenes", "/nonexistent/dir"], "--scenes: the directory") ] $ \(args, message) -> do
        (c, o, e) <- run args
        (args, c, o, message `isInfixOf` e, length (lines e)) `shouldBe` (args, ExitFailure 2, "", True, 1)

  describe "manifold dump-step and manifold bench" $ do
    it "dump-step prints a space's compiled step as Haskell: every phase and subroutine, over the world's arrays (a flat space's without self-contact)" $ do
      let definedIn out = [ takeWhile (/= ' ') l | l <- lines (BC.unpack (BL.toStrict out)), " :: Arr -> " `isInfixOf` l ]
      (code, out, err) <- run ["dump-step", "torus"]
      (code, err) `shouldBe` (ExitSuccess, "")
      let defined = definedIn out
      defined `shouldBe` ["stepWake", "stepCollide", "keepContacts", "pairCircles", "pairHulls", "pairOutlines", "selfContacts", "markTouched", "stepPrepare", "prepareJoint", "stepSubsteps", "substepGravity", "warmStartJoints", "warmStart", "mouseJoint", "solveJoints", "solveSweep", "substepMove", "relaxJoints", "relaxSweep", "stepFinish", "restitution", "stepPolygonise", "walkAllCorners", "stepSleep"]
      -- a plane's rays never turn, so a flat space's step has no self-contact stage
      (codeFlat, outFlat, errFlat) <- run ["dump-step", "rectangle"]
      (codeFlat, errFlat) `shouldBe` (ExitSuccess, "")
      definedIn outFlat `shouldBe` filter (/= "selfContacts") defined
      (code', out', err') <- run ["dump-step", "bowl"]
      (code', out', "unknown space \"bowl\"; valid spaces: plane" `isInfixOf` err') `shouldBe` (ExitFailure 2, "", True)
    it "bench --json times a scene with the compiled step and with --generic" $
      forM_ [[], ["--generic"]] $ \extra -> do
        (code, out, _) <- run (["bench", "--spaces", "torus", "--sizes", "10", "--warmup", "0", "--steps", "2", "--json"] ++ extra)
        code `shouldBe` ExitSuccess
        case A.eitherDecode out :: Either String [A.Value] of
          Right [_] -> pure ()
          other -> expectationFailure ("bench " ++ unwords extra ++ ": expected one result, got " ++ show other)
    it "bench --rounds R times every scene R times and keeps its fastest round" $ do
      (code, out, err) <- run ["bench", "--spaces", "torus,plane", "--sizes", "10", "--warmup", "0", "--steps", "2", "--rounds", "2", "--json"]
      code `shouldBe` ExitSuccess
      length [l | l <- lines err, "round 2 of 2: plane" `isInfixOf` l, "timing" `isInfixOf` l] `shouldBe` 1
      A.eitherDecode out `shouldBe` Right [BenchRounds 2, BenchRounds 2]
      (code0, _, err0) <- run ["bench", "--spaces", "torus", "--sizes", "10", "--rounds", "0"]
      (code0, "--rounds: must be at least 1" `isInfixOf` err0) `shouldBe` (ExitFailure 2, True)
    it "bench --substeps N --iterations K --slop F times the scenes with those contact settings, and says so" $ do
      let timed extra = do
            (code, out, err) <- run (["bench", "--spaces", "sphere", "--sizes", "100", "--settle", "150", "--warmup", "40", "--steps", "3", "--rounds", "1", "--json"] ++ extra)
            (code, err) `shouldSatisfy` ((== ExitSuccess) . fst)
            case A.eitherDecode out of
              Right [r] -> pure (r :: BenchContacts)
              other -> fail ("bench " ++ unwords extra ++ ": " ++ show other)
      plain <- timed []
      (bcSubsteps plain, bcIterations plain, bcSlop plain, bcWarmup plain) `shouldBe` (4, 1, 0.001, 40)
      firm <- timed ["--substeps", "2", "--iterations", "3", "--slop", "0.25"]
      (bcSubsteps firm, bcIterations firm, bcSize firm) `shouldBe` (2, 3, bcSize plain)
      bcSlop firm `shouldBe` 0.25
      -- the settings reach the timed world: the same settled pile, warmed up
      -- under them, has other contacts
      bcRows firm `shouldSatisfy` (/= bcRows plain)
      forM_ [ (["--iterations", "0"], "--iterations: must be at least 1")
            , (["--substeps", "0"], "--substeps: must be at least 1")
            , (["--slop", "-0.5"], "--slop: must be a finite number, not negative")
            , (["--slop", "Infinity"], "--slop: must be a finite number, not negative") ] $ \(extra, message) -> do
        (code, _, err) <- run (["bench", "--spaces", "torus", "--sizes", "10"] ++ extra)
        (code, message `isInfixOf` err) `shouldBe` (ExitFailure 2, True)
      withSystemTempDirectory "manifold-scenes" $ \dir -> do
        (code, _, err) <- run ["bench", "--scenes", dir, "--sizes", "10", "--iterations", "4"]
        (code, "they apply to the timed steps" `isInfixOf` err) `shouldBe` (ExitFailure 2, True)
    it "bench --scenes DIR writes each scene after --settle K steps (as placed with --settle 0), and bench --from DIR times them" $
      withSystemTempDirectory "manifold-scenes" $ \dir -> do
        let write :: Int -> IO Scene
            write k = do
              (code, out, err) <- run ["bench", "--scenes", dir </> show k, "--spaces", "sphere", "--sizes", "10", "--settle", show k]
              (code, out) `shouldBe` (ExitSuccess, BL.fromStrict (BC.pack (dir </> show k </> "sphere-10.json\n")))
              ("settling " ++ show k ++ " steps") `shouldSatisfy` (`isInfixOf` err)
              text <- BL.readFile (dir </> show k </> "sphere-10.json")
              either (\e -> fail ("sphere-10.json: " ++ e)) pure (parseScene text)
        placed <- write 0
        settled <- write 300
        sceneBodies placed `shouldBe` sceneBodies (benchScene sphere 10)
        map (\b -> (bsShape b, bsSize b)) (sceneBodies settled) `shouldBe` map (\b -> (bsShape b, bsSize b)) (sceneBodies placed)
        -- the bodies have fallen: on the unit sphere with gravity along −y, lower than placed
        let height = sum . map ((\(V3 _ y _) -> y) . bsP) . sceneBodies
        height settled `shouldSatisfy` (< height placed - 1)
        (codeN, _, errN) <- run ["bench", "--spaces", "torus", "--sizes", "10", "--settle", "-1"]
        (codeN, "--settle: must not be negative" `isInfixOf` errN) `shouldBe` (ExitFailure 2, True)
        -- --from times the written scenes as they are: no settling
        (codeF, outF, errF) <- run ["bench", "--from", dir </> "300", "--spaces", "sphere", "--sizes", "10", "--warmup", "0", "--steps", "2", "--rounds", "1", "--json"]
        (codeF, "settling" `isInfixOf` errF) `shouldBe` (ExitSuccess, False)
        A.eitherDecode outF `shouldBe` Right [BenchSettle Nothing]
        (codeM, _, errM) <- run ["bench", "--from", dir </> "300", "--spaces", "torus", "--sizes", "10"]
        (codeM, "torus-10.json: no such scene file" `isInfixOf` errM) `shouldBe` (ExitFailure 2, True)
        (codeB, _, errB) <- run ["bench", "--from", dir </> "300", "--scenes", dir </> "x", "--sizes", "10"]
        (codeB, "not both" `isInfixOf` errB) `shouldBe` (ExitFailure 2, True)
