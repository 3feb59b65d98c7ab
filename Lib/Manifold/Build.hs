-- | Writing generated files: atomically (a temporary file, then a rename), and
-- never over a file that @manifold build@ did not write.
module Manifold.Build
  ( GeneratedFile (..)
  , generatedFiles
  , generatedFilesWith
  , writeGenerated
  , BuildError (..)
  ) where

import Control.Exception (Exception, throwIO)
import Control.Monad (forM_, unless, when)
import Data.List (isPrefixOf)
import System.Directory (createDirectoryIfMissing, doesFileExist, renameFile)
import System.FilePath ((</>))
import System.IO (IOMode (..), hGetLine, hIsEOF, hPutStr, hSetEncoding, utf8, withFile)

import Manifold.Space (Space)
import Manifold.Stage.Kernels

-- | A file @manifold build@ writes.
data GeneratedFile = GeneratedFile
  { genPath :: FilePath -- ^ relative to the output directory
  , genContents :: String -- ^ starting with 'generatedMarker'
  }

-- | Why nothing was written: a target that exists and is not a generated
-- file.
newtype BuildError = BuildError String
  deriving Show

instance Exception BuildError

-- | Every file @manifold build@ writes for a catalogue.
generatedFiles :: [Space] -> [GeneratedFile]
generatedFiles = generatedFilesWith spaceScript

-- | 'generatedFiles' with each space's script as given (one printed
-- before, say).
generatedFilesWith :: (Space -> String) -> [Space] -> [GeneratedFile]
generatedFilesWith script spaces =
  GeneratedFile "spaces.js" (spaceIndexScript spaces)
    : GeneratedFile comparisonScriptFile comparisonScript
    : [GeneratedFile (spaceScriptFile s) (script s) | s <- spaces]

-- | Write all files into a directory. Every target is checked before any is
-- written, so a refusal leaves the directory as it was.
writeGenerated :: FilePath -> [GeneratedFile] -> IO ()
writeGenerated dir files = do
  createDirectoryIfMissing True dir
  forM_ files $ \f -> do
    let path = dir </> genPath f
    exists <- doesFileExist path
    when exists $ do
      ours <- startsWithMarker path
      unless ours $ throwIO (BuildError (path ++ " exists and was not written by manifold build; move it away or choose another --out"))
  forM_ files $ \f -> do
    let path = dir </> genPath f
        tmp = path ++ ".tmp"
    withFile tmp WriteMode $ \h -> hSetEncoding h utf8 >> hPutStr h (genContents f)
    renameFile tmp path

startsWithMarker :: FilePath -> IO Bool
startsWithMarker path = withFile path ReadMode $ \h -> do
  hSetEncoding h utf8
  eof <- hIsEOF h
  if eof then pure False else (generatedMarker `isPrefixOf`) <$> hGetLine h
