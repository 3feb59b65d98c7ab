-- | The preset scenes: the scene files of the repository's @scenes/@, each
-- named @SPACE-WHAT.json@ (@trumpet-jam.json@: the trumpet's bodies jamming
-- in its neck). @manifold build@ reads them, checks each as a scene of the
-- space its name starts with, and writes them into the page's generated
-- @presets.js@, so that the page offers them and loads one by its name
-- (@#scene=trumpet-jam@), served or opened from disk. A preset that names
-- no camera opens with the view "Manifold.Framing" chooses for its bodies.
module Manifold.Presets
  ( Preset (..)
  , presetOf
  , readPresets
  , presetsScriptFile
  , presetsScript
  ) where

import Control.Monad (forM)
import qualified Data.Aeson as A
import qualified Data.Aeson.Key as K
import qualified Data.Aeson.KeyMap as KM
import qualified Data.ByteString.Lazy as BL
import qualified Data.ByteString.Lazy.Char8 as BLC
import Data.Char (isAsciiLower, isDigit)
import Data.List (isPrefixOf, isSuffixOf, sort, sortOn)
import Data.Maybe (fromMaybe)
import Data.Ord (Down (..))
import System.Directory (listDirectory)
import System.FilePath (dropExtension, (</>))

import Linear.V3 (V3 (..))

import Manifold.Framing (frameBodies)
import Manifold.Scene (BodySpec (..), Scene (..), parseScene)
import Manifold.Space (Camera (..), spaceName)
import Manifold.Spaces (spaceNames)
import Manifold.Stage.Kernels (generatedMarker)

-- | A preset: its name (the file's, without @.json@), the space it is of,
-- what it shows (the rest of the name, in words), the scene's JSON as the
-- file gives it, and the view it opens with (the file's camera, or the one
-- "Manifold.Framing" chooses for its bodies).
data Preset = Preset
  { presetName :: String
  , presetSpace :: String
  , presetTitle :: String
  , presetScene :: A.Value
  , presetCamera :: Camera
  } deriving (Show, Eq)

-- | A preset from its file's name and text, or what is wrong with it (the
-- file named): a name that is not @SPACE-WHAT@ of a catalogue space in
-- lower-case words, a scene that does not parse, or one of another space.
--
-- (The examples are test/PresetSpec.hs's: this module imports the scene
-- parser, and with it the compiled steps doctest cannot load in time.)
presetOf :: FilePath -> BL.ByteString -> Either String Preset
presetOf file text = do
  let name = dropExtension file
      here msg = Left ("scenes/" ++ file ++ ": " ++ msg)
      -- the longest space name that, with a hyphen, starts the file's name
      spaces = sortOn (Down . length) [s | s <- spaceNames, (s ++ "-") `isPrefixOf` name]
      word c = isAsciiLower c || isDigit c || c == '-'
  case spaces of
    [] -> here ("the name must be SPACE-WHAT.json with SPACE one of " ++ unwords spaceNames)
    sp : _ -> do
      let what = drop (length sp + 1) name
      if null what || not (all word what) || "-" `isPrefixOf` what || "-" `isSuffixOf` what
        then here "the part after the space's name must be lower-case words joined by hyphens"
        else do
          scene <- either here pure (parseScene text)
          let named = spaceName (sceneSpace scene)
          if named /= sp
            then here ("a scene of " ++ named ++ ", but the name says " ++ sp)
            else do
              value <- maybe (here "not JSON") pure (A.decode text)
              let framed = frameBodies (sceneSpace scene) [(bsP b, bsSize b) | b <- sceneBodies scene]
              pure (Preset name sp (map (\c -> if c == '-' then ' ' else c) what) value (fromMaybe framed (sceneCamera scene)))

-- | Every preset of a directory's @.json@ files, by name; the first problem
-- found, if any, instead.
readPresets :: FilePath -> IO (Either String [Preset])
readPresets dir = do
  files <- sort . filter (".json" `isSuffixOf`) <$> listDirectory dir
  presets <- forM files $ \f -> presetOf f <$> BL.readFile (dir </> f)
  pure (sequence presets)

-- | The name of 'presetsScript' among the generated files.
presetsScriptFile :: FilePath
presetsScriptFile = "presets.js"

-- | The page's script of the presets: @Manifold.presets@, each
-- @{name, space, title, scene}@, the scene with its 'presetCamera'.
presetsScript :: [Preset] -> String
presetsScript presets = unlines $
  [ generatedMarker ++ " from scenes/ (the preset scenes). Do not edit."
  , "globalThis.Manifold = globalThis.Manifold || { spaces: {} };"
  , "globalThis.Manifold.presets = ["
  ] ++
  [ "  " ++ BLC.unpack (A.encode (A.object [ K.fromString "name" A..= presetName p, K.fromString "space" A..= presetSpace p
                                          , K.fromString "title" A..= presetTitle p, K.fromString "scene" A..= withCamera p ])) ++ ","
  | p <- presets ] ++
  [ "];" ]
  where
    withCamera p = case presetScene p of
      A.Object o -> A.Object (KM.insert (K.fromString "camera") (cameraJSON (presetCamera p)) o)
      other -> other
    cameraJSON c = A.object [ K.fromString "eye" A..= xyz (cameraEye c), K.fromString "target" A..= xyz (cameraTarget c)
                            , K.fromString "up" A..= xyz (cameraUp c), K.fromString "fov" A..= cameraFov c ]
    xyz (V3 x y z) = [x, y, z]
