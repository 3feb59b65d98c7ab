{-# LANGUAGE OverloadedStrings #-}
-- | The @manifold@ command.
module Main (main) where

import Control.Exception (IOException, try)
import Network.Wai (Middleware, mapResponseHeaders, modifyResponse)
import qualified Network.Wai.Handler.Warp as Warp
import Network.Wai.Application.Static (defaultFileServerSettings, staticApp)
import System.Directory (createDirectoryIfMissing, doesDirectoryExist, doesFileExist)
import System.FilePath ((</>), takeDirectory)
import System.IO.Error (isAlreadyInUseError)
import Control.Monad (forM, forM_, unless, when)
import qualified Data.Aeson as A
import qualified Data.ByteString.Lazy.Char8 as BL
import Data.List (intercalate, isInfixOf, minimumBy, transpose)
import Data.Maybe (isJust, isNothing)
import Data.Ord (comparing)
import Data.String (fromString)
import Linear.Metric (norm)
import Linear.V3 (V3 (..))
import Options.Applicative
import System.Exit (exitWith, ExitCode (..))
import System.IO (hFlush, hPutStrLn, stderr, stdout)
import Text.Read (readMaybe)

import Manifold
import Manifold.Bench
import Manifold.Build
import Manifold.Compile (dumpStep)
import Manifold.Engine
import Manifold.Golden
import Manifold.Presets
import Manifold.Scene
import Manifold.StateHash (showHash)

data Command
  = Spaces Bool
  | Geodesic GeodesicArgs
  | Build FilePath FilePath
  | DumpStep String
  | Serve Int FilePath
  | Sim FilePath Int Int (Maybe FilePath) Bool
  | Bench BenchArgs
  | Hashes (Maybe Int) Bool (Maybe FilePath)

-- | @manifold bench@'s options, as given (checked by 'bench').
data BenchArgs = BenchArgs
  { bSpaces :: String -- ^ comma-separated space names
  , bSizes :: String -- ^ comma-separated body counts
  , bSettle :: Int -- ^ steps each scene runs once before it is saved
  , bWarmup :: Int -- ^ steps from the saved scene before the timed ones, every round
  , bSteps :: Int -- ^ steps timed
  , bRounds :: Int
  , bJson :: Bool
  , bScenes :: Maybe FilePath -- ^ write the settled scenes here instead of timing
  , bFrom :: Maybe FilePath -- ^ time the scenes written here instead of settling
  , bGeneric :: Bool -- ^ the generic step even where a compiled one exists
  , bSubsteps :: Maybe Int -- ^ solver sub-steps while timed, instead of the scenes'
  , bIterations :: Maybe Int -- ^ solver iterations a sub-step while timed, instead of the scenes'
  , bSlop :: Maybe Double -- ^ the slop while timed, as a fraction of the body size
  }

data GeodesicArgs = GeodesicArgs
  { gSpace :: String
  , gFrom :: String
  , gDir :: String
  , gLength :: String
  , gStep :: String
  , gJson :: Bool
  }

commandParser :: Parser Command
commandParser = hsubparser
  ( command "spaces" (info (Spaces <$> jsonFlag) (progDesc "List the spaces of the catalogue"))
 <> command "geodesic" (info (Geodesic <$> geodesicArgs) (progDesc "Walk a geodesic and print its polyline"))
 <> command "build" (info (Build <$> outDir <*> scenesDir) (progDesc "Emit the page's generated scripts (spaces, GLSL, the preset scenes) into web/gen"))
 <> command "sim" (info (Sim <$> strArgument (metavar "SCENE" <> help "Scene JSON file (- for standard input)")
                                 <*> option auto (long "steps" <> metavar "K" <> help "Steps to simulate")
                                 <*> option auto (long "every" <> metavar "M" <> value 1 <> help "Print every M-th step (default 1)")
                                 <*> optional (strOption (long "save" <> metavar "FILE" <> help "Also write the scene as it is after the last step to FILE (the format sim reads, with the contacts' impulses), to go on from there later"))
                                 <*> switch (long "hash" <> help "Print only the hash of the world's state after the last step (16 hex digits; the page's window.manifold.hash() gives the same for the same run)"))
                       (progDesc "Simulate a scene headless and print the bodies' states as JSON"))
 <> command "bench" (info (fmap Bench $ BenchArgs <$> strOption (long "spaces" <> metavar "A,B" <> value (intercalate "," (map spaceName benchSpaces)) <> help "Spaces (default: plane, sphere, torus, trumpet, projective-plane, rectangle)")
                                   <*> strOption (long "sizes" <> metavar "N,M" <> value (intercalate "," (map show benchSizes)) <> help "Body counts (default 10,100,300,1000,3000)")
                                   <*> option auto (long "settle" <> metavar "K" <> value defaultSettleSteps <> help ("Steps each scene runs once, from its placement, before it is saved and timed (default " ++ show defaultSettleSteps ++ ")"))
                                   <*> option auto (long "warmup" <> metavar "W" <> value 50 <> help "Steps run from the saved scene before the timed steps, in every round (default 50)")
                                   <*> option auto (long "steps" <> metavar "S" <> value 50 <> help "Steps timed (default 50)")
                                   <*> option auto (long "rounds" <> metavar "R" <> value 3 <> help "Time every scene R times, round after round, and keep its fastest round (default 3)")
                                   <*> switch (long "json" <> help "Print JSON")
                                   <*> optional (strOption (long "scenes" <> metavar "DIR" <> help "Write the settled scenes as JSON files DIR/SPACE-N.json (the format sim reads) instead of timing"))
                                   <*> optional (strOption (long "from" <> metavar "DIR" <> help "Time the scenes DIR/SPACE-N.json that --scenes wrote instead of settling them again"))
                                   <*> switch (long "generic" <> help "Time the generic step even where the space has a compiled one")
                                   <*> optional (option auto (long "substeps" <> metavar "N" <> help "Solver sub-steps from the warm-up on, instead of the scenes' (give the piles a long --warmup to settle)"))
                                   <*> optional (option auto (long "iterations" <> metavar "K" <> help "Solver iterations a sub-step from the warm-up on, instead of the scenes'"))
                                   <*> optional (option auto (long "slop" <> metavar "F" <> help "The contacts' slop from the warm-up on, as a fraction of the smaller body's size (default: the engine's)")))
                       (progDesc "Time the native engine's step on scenes of growing size"))
 <> command "hashes" (info (Hashes <$> optional (option auto (long "steps" <> metavar "K" <> help "Run every scene K steps instead of its own number"))
                                    <*> switch (long "generic" <> help "Run the generic step even where the space has a compiled one")
                                    <*> optional (strOption (long "scenes" <> metavar "DIR" <> help "Write the golden scenes as DIR/NAME.json (the format sim reads) instead of running them")))
                       (progDesc "Run the golden scenes (every space's default scene, the benchmark piles) and print each one's name, steps and state hash: the lines of test/golden/hashes"))
 <> command "dump-step" (info (DumpStep <$> strArgument (metavar "SPACE" <> help ("One of: " ++ intercalate ", " spaceNames)))
        (progDesc "Print a space's compiled native step as Haskell, for reading (the library splices the same code)"))
 <> command "serve" (info (Serve <$> port <*> webDir) (progDesc "Serve the page (web/) on 127.0.0.1 and print its URL"))
  )
  where
    outDir = strOption (long "out" <> metavar "DIR" <> value "web/gen" <> help "Output directory (default web/gen)")
    scenesDir = strOption (long "scenes" <> metavar "DIR" <> value "scenes" <> help "The preset scenes, SPACE-WHAT.json (default scenes)")
    port = option auto (long "port" <> metavar "P" <> value 8000 <> help "Port (default 8000)")
    webDir = strOption (long "dir" <> metavar "DIR" <> value "web" <> help "Directory to serve (default web)")
    jsonFlag = switch (long "json" <> help "Print JSON")
    geodesicArgs = GeodesicArgs
      <$> strOption (long "space" <> metavar "NAME" <> help ("One of: " ++ intercalate ", " spaceNames))
      <*> strOption (long "from" <> metavar "X,Y,Z" <> help "Start point (projected onto the surface)")
      <*> strOption (long "dir" <> metavar "DX,DY,DZ" <> help "Start direction (projected onto the tangent plane)")
      <*> strOption (long "length" <> metavar "L" <> help "Length of the geodesic")
      <*> strOption (long "step" <> metavar "H" <> value "0.01" <> help "Step length (default 0.01)")
      <*> jsonFlag

main :: IO ()
main = do
  cmd <- customExecParser (prefs showHelpOnEmpty)
           (info (commandParser <**> helper)
              (fullDesc <> progDesc "Rigid-body physics on curved surfaces" <> failureCode 2))
  case cmd of
    Spaces json -> listSpaces json
    Geodesic a -> either usageError id (geodesic a)
    Build dir scenes -> do
      found <- doesDirectoryExist scenes
      unless found $ usageError ("--scenes " ++ scenes ++ ": no such directory (the preset scenes; run from the repository's root or give --scenes DIR)")
      presets <- readPresets scenes >>= either usageError pure
      let files = generatedFiles catalogue ++ [GeneratedFile presetsScriptFile (presetsScript presets)]
      r <- try (writeGenerated dir files)
      case r of
        Left (BuildError msg) -> usageError msg
        Right () -> putStrLn ("wrote " ++ show (length files) ++ " files to " ++ dir)
    DumpStep name -> either usageError (putStr . dumpStep) (findSpace name)
    Serve p dir -> serve p dir
    Sim path steps every save hash -> simulate path steps every save hash
    Bench args -> bench args
    Hashes steps generic dir -> hashes steps generic dir

-- | A one-line error and exit code 2.
usageError :: String -> IO a
usageError msg = hPutStrLn stderr ("manifold: " ++ msg) >> exitWith (ExitFailure 2)

listSpaces :: Bool -> IO ()
listSpaces True = BL.putStrLn $ A.encode
  [ A.object [ "name" A..= spaceName s, "description" A..= spaceDescription s
             , "quotient" A..= quotientName (spaceQuotient s), "metric" A..= metricName (spaceMetric s)
             , "hasBoundary" A..= hasBoundary s ]
  | s <- catalogue ]
listSpaces False = mapM_ (\s -> putStrLn (pad (spaceName s) ++ "  " ++ spaceDescription s)) catalogue
  where
    width = maximum (map (length . spaceName) catalogue)
    pad n = n ++ replicate (width - length n) ' '

findSpace :: String -> Either String Space
findSpace n = maybe (Left ("unknown space " ++ show n ++ "; valid spaces: " ++ intercalate ", " spaceNames)) Right (lookupSpace n)

parseNumber :: String -> String -> Either String Double
parseNumber what s = case readMaybe (dropPlus s) of
  Just x | not (isNaN x || isInfinite x) -> Right x
  _ -> Left (what ++ ": " ++ show s ++ " is not a finite number")
  where dropPlus ('+' : r) = r
        dropPlus r = r

parseVector :: String -> String -> Either String (V3 Double)
parseVector what s = case splitOn ',' s of
  [a, b, c] -> V3 <$> parseNumber what a <*> parseNumber what b <*> parseNumber what c
  _ -> Left (what ++ ": " ++ show s ++ " is not three comma-separated numbers X,Y,Z")

splitOn :: Char -> String -> [String]
splitOn c s = case break (== c) s of
  (a, []) -> [a]
  (a, _ : rest) -> a : splitOn c rest

geodesic :: GeodesicArgs -> Either String (IO ())
geodesic a = do
  sp <- findSpace (gSpace a)
  from <- parseVector "--from" (gFrom a)
  dir <- parseVector "--dir" (gDir a)
  len <- parseNumber "--length" (gLength a)
  h <- parseNumber "--step" (gStep a)
  when (len < 0) (Left "--length: must not be negative")
  when (h <= 0) (Left "--step: must be positive")
  let f = spaceField sp
      degenerate q = let g = norm (fieldGradient f q) in isNaN g || g < 1e-12
  when (degenerate from) (Left ("--from: the gradient of " ++ spaceName sp ++ " vanishes at the start point, so it has no surface normal there; choose another point"))
  let start = projectToSurface f from
  when (degenerate start || any isNaN start) (Left "--from: the start point does not project onto the surface (the gradient vanishes on the way); choose a point nearer the surface")
  let metric = spaceMetric sp
      n = unitNormal metric f start
      tangentDir = tangentProjection metric n dir
  when (norm dir < 1e-12) (Left "--dir: the direction is zero")
  when (normIn metric tangentDir < 1e-9 * norm dir) (Left "--dir: the direction is normal to the surface at the start point, so it has no tangent part")
  let steps = max 1 (ceiling (len / h)) :: Int
      path = geodesicPath metric f steps start tangentDir len
      points = map fst path
      (end, endDir) = last path
  pure $ if gJson a
    then BL.putStrLn (A.encode (A.object
           [ "points" A..= map v3List points, "end" A..= v3List end, "endDir" A..= v3List endDir ]))
    else do
      mapM_ (putStrLn . unwords . map show . v3List) points
      putStrLn ("end: " ++ unwords (map show (v3List end)))
      putStrLn ("endDir: " ++ unwords (map show (v3List endDir)))

-- | Run a scene and print frames (or, with @hash@, only the state's hash at
-- the end); on any problem, a message and exit code 2, and nothing on
-- standard output.
simulate :: FilePath -> Int -> Int -> Maybe FilePath -> Bool -> IO ()
simulate path steps every save hash = do
  when (steps < 0) (usageError "--steps: must not be negative")
  when (every < 1) (usageError "--every: must be at least 1")
  forM_ save $ \out -> do
    let dir = takeDirectory out
    there <- doesDirectoryExist dir
    unless there (usageError ("--save: the directory " ++ dir ++ " does not exist"))
  text <- if path == "-" then BL.getContents else do
    exists <- doesFileExist path
    if exists then BL.readFile path else usageError (path ++ ": no such scene file")
  scene <- either (usageError . ((path ++ ": ") ++)) pure (parseScene text)
  loaded <- loadScene 0 scene
  w <- either (usageError . ((path ++ ": ") ++)) pure loaded
  n <- bodyCount w
  let frame k = do
        bodies <- mapM (readBody w) [0 .. n - 1]
        pure (A.object [ "step" A..= k, "bodies" A..= map bodyJson bodies ])
      bodyJson b = A.object [ "p" A..= v3List (bsPos b), "v" A..= v3List (bsVel b)
                            , "angle" A..= bsAngle b, "omega" A..= bsOmega b, "awake" A..= isNothing (bsAsleep b) ]
      run k acc
        | k > steps = pure (reverse acc)
        | otherwise = do
            f <- if not hash && (k `mod` every == 0 || k == steps) then (: []) <$> frame k else pure []
            when (k < steps) (stepNative w)
            run (k + 1) (f ++ acc)
  frames <- run 0 []
  warnings <- warningCount w
  forM_ save $ \out -> do
    final <- sceneOfWorld scene w >>= either usageError pure
    written <- try (BL.writeFile out (A.encode (sceneJSON final))) :: IO (Either IOException ())
    either (\e -> usageError ("--save: " ++ show e)) pure written
  if hash
    then stateHash w >>= putStrLn . showHash
    else BL.putStrLn (A.encode (A.object
      [ "space" A..= spaceName (sceneSpace scene), "dt" A..= pDt (sceneParams scene)
      , "warnings" A..= warnings, "frames" A..= frames ]))

-- | The golden runs' hashes, a line each as they finish (or, with a
-- directory, their scenes written there).
hashes :: Maybe Int -> Bool -> Maybe FilePath -> IO ()
hashes steps generic dir = do
  when (maybe False (< 0) steps) (usageError "--steps: must not be negative")
  case dir of
    Just d -> do
      there <- doesDirectoryExist d
      unless there (usageError ("--scenes: the directory " ++ d ++ " does not exist"))
      forM_ goldenRuns $ \run -> do
        let file = d </> (grName run ++ ".json")
        BL.writeFile file (A.encode (sceneJSON (grScene run)))
        putStrLn file
    Nothing -> forM_ goldenRuns $ \run -> do
      let run' = maybe run (\k -> run { grSteps = k }) steps
      r <- runHash generic (grSteps run') (grScene run')
      either (\e -> usageError (grName run ++ ": " ++ e)) (\h -> putStrLn (goldenLine run' h) >> hFlush stdout) r

-- | The native benchmark: progress on standard error, a table or JSON on
-- standard output.
--
-- Each scene is settled once ('settleScene') and saved; every round then
-- loads the saved scene, warms up and times it. Every scene is timed in each
-- of @rounds@ rounds (all scenes, then all again) and reported by its round
-- with the lowest median: on a shared machine, what others run only ever
-- adds time, and a slow spell of minutes would otherwise decide the scenes
-- it happens to fall on.
bench :: BenchArgs -> IO ()
bench BenchArgs { bSpaces = spacesArg, bSizes = sizesArg, bSettle = settle, bWarmup = warmup, bSteps = steps
                , bRounds = rounds, bJson = json, bScenes = scenesDir, bFrom = fromDir, bGeneric = generic
                , bSubsteps = substepCount, bIterations = iterations, bSlop = slop } = do
  spaces <- either usageError pure (mapM findSpace (splitOn ',' spacesArg))
  sizes <- either usageError pure (parseSizes sizesArg)
  when (settle < 0) (usageError "--settle: must not be negative")
  when (warmup < 0) (usageError "--warmup: must not be negative")
  when (steps < 1) (usageError "--steps: must be at least 1")
  when (rounds < 1) (usageError "--rounds: must be at least 1")
  when (maybe False (< 1) substepCount) (usageError "--substeps: must be at least 1")
  when (maybe False (< 1) iterations) (usageError "--iterations: must be at least 1")
  when (maybe False (\f -> isNaN f || isInfinite f || f < 0) slop) (usageError "--slop: must be a finite number, not negative")
  let overridden = isJust substepCount || isJust iterations || isJust slop
  let cases = [(sp, n) | sp <- spaces, n <- sizes]
      settled (sp, n) = do
        hPutStrLn stderr ("bench: " ++ spaceName sp ++ " " ++ show n ++ ": settling " ++ show settle ++ " steps")
        settleScene settle (benchScene sp n)
      sceneFile dir (sp, n) = dir </> (spaceName sp ++ "-" ++ show n ++ ".json")
      saved dir c = do
        let file = sceneFile dir c
        exists <- doesFileExist file
        text <- if exists then BL.readFile file else usageError (file ++ ": no such scene file (write the scenes with --scenes " ++ dir ++ ")")
        either (usageError . ((file ++ ": ") ++)) pure (parseScene text)
  case (scenesDir, fromDir) of
    (Just _, Just _) -> usageError "--scenes and --from: write the scenes or time them, not both"
    (Just _, _) | overridden -> usageError "--substeps, --iterations and --slop: they apply to the timed steps; --scenes writes the scenes as they settle"
    (Just dir, _) -> do
      createDirectoryIfMissing True dir
      forM_ cases $ \(sp, n) -> do
        scene <- settled (sp, n)
        BL.writeFile (sceneFile dir (sp, n)) (A.encode (sceneJSON scene))
        putStrLn (sceneFile dir (sp, n))
    (Nothing, Just dir) -> timeScenes =<< mapM (saved dir) cases
    (Nothing, Nothing) -> timeScenes =<< mapM settled cases
  where
    settings = ContactSettings substepCount iterations slop
    timeScenes scenes = do
      perRound <- forM [1 .. rounds] $ \k -> do
        let progress msg = hPutStrLn stderr ("bench: round " ++ show k ++ " of " ++ show rounds ++ ": " ++ msg)
        mapM (runBench progress generic settings warmup steps) scenes
      let results = map (minimumBy (comparing brMedianMs)) (transpose perRound)
      if json
        then BL.putStrLn (A.encode [ A.object [ "space" A..= brSpace r, "bodies" A..= brBodies r, "size" A..= brSize r
                                              , "contacts" A..= brContacts r, "medianMs" A..= brMedianMs r
                                              , "p10Ms" A..= brP10Ms r, "p90Ms" A..= brP90Ms r, "steps" A..= brSteps r
                                              , "substeps" A..= brSubsteps r, "iterations" A..= brIterations r, "slop" A..= brSlop r
                                              -- settle null: timed as read from --from's files
                                              , "rounds" A..= rounds, "settle" A..= (if isJust fromDir then Nothing else Just settle), "warmup" A..= warmup
                                              , "phaseMedianMs" A..= A.object [fromString k A..= v | (k, v) <- brPhases r] ]
                                   | r <- results ])
        else do
          let phaseNames = case results of
                r : _ -> map fst (brPhases r)
                [] -> []
          putStrLn (row (["space", "bodies", "size", "contacts", "median ms", "p10 ms", "p90 ms"] ++ phaseNames))
          mapM_ (\r -> putStrLn (row ([brSpace r, show (brBodies r), fixed 4 (brSize r), fixed 1 (brContacts r)
                                      , fixed 3 (brMedianMs r), fixed 3 (brP10Ms r), fixed 3 (brP90Ms r)]
                                      ++ map (fixed 3 . snd) (brPhases r)))) results
          putStrLn "(phase columns: median ms of each phase of the step)"
    row cols = intercalate " | " [c ++ replicate (w - length c) ' ' | (c, w) <- zip cols ([16, 7, 7, 9, 10, 10, 10] ++ repeat 10)]
    fixed k x = let s = show (fromIntegral (round (x * 10 ^ (k :: Int)) :: Integer) / 10 ^ k :: Double) in s

parseSizes :: String -> Either String [Int]
parseSizes arg = mapM (\s -> case readMaybe s of
  Just n | n > 0 -> Right (n :: Int)
  _ -> Left ("--sizes: " ++ show s ++ " is not a positive whole number")) (splitOn ',' arg)

-- | Serve a directory on the loopback interface only.
serve :: Int -> FilePath -> IO ()
serve p dir = do
  when (p < 1 || p > 65535) (usageError ("--port: " ++ show p ++ " is not a port number (1-65535)"))
  ok <- doesFileExist (dir </> "index.html")
  unless ok (usageError (dir </> "index.html" ++ " does not exist; run manifold serve from the repository root"))
  gen <- doesFileExist (dir </> "gen" </> "spaces.js")
  unless gen (hPutStrLn stderr ("manifold: warning: " ++ dir </> "gen" ++ " is not built; run manifold build first"))
  let settings = Warp.setHost "127.0.0.1" $ Warp.setPort p
               $ Warp.setBeforeMainLoop (putStrLn ("serving " ++ dir ++ " at http://127.0.0.1:" ++ show p ++ "/") >> hFlush stdout)
               Warp.defaultSettings
  r <- try (Warp.runSettings settings (crossOriginIsolated (staticApp (defaultFileServerSettings dir))))
  case r of
    Left (e :: IOException)
      | isAlreadyInUseError e || "resource busy" `isInfixOf` show e || "in use" `isInfixOf` show e ->
          usageError ("port " ++ show p ++ " is already in use; choose another with --port")
      | otherwise -> usageError ("cannot serve on port " ++ show p ++ ": " ++ show e)
    Right () -> pure ()

-- | Serves the page cross-origin isolated (COOP and COEP), so that it may
-- share memory with its physics worker (SharedArrayBuffer) and read a
-- fine clock; everything the page loads is its own (same origin).
crossOriginIsolated :: Middleware
crossOriginIsolated = modifyResponse (mapResponseHeaders (isolation ++))
  where
    isolation =
      [ ("Cross-Origin-Opener-Policy", "same-origin")
      , ("Cross-Origin-Embedder-Policy", "require-corp")
      ]

v3List :: V3 Double -> [Double]
v3List (V3 x y z) = [x, y, z]
