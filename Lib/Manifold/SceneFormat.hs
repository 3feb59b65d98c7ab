{-# LANGUAGE OverloadedStrings, LambdaCase, TupleSections #-}
-- | The scene file's format as data: every key of a scene, a body, a joint
-- and a camera, what its value must be, what it is when left out, the words
-- of every way it can be wrong and the order in which they are found.
-- 'check' reads a JSON value against it here ("Manifold.Scene" builds the
-- scene from what it gives); the page gets the same description
-- ('formatJSON', in the generated index) and reads scenes with the one small
-- interpreter of it in web/js/world.js, so that @manifold sim@ and the page
-- refuse the same scene in the same words and read the others alike.
--
-- A check gives the value completed: every key left out that has a
-- default given its default (a sleeping body its island), so that what
-- reads it needs no defaults of its own.
module Manifold.SceneFormat
  ( -- * The description
    Format (..)
  , Entry (..)
  , Presence (..)
  , Rule (..)
  , Choice (..)
  , Bounds (..)
  , Bound (..)
  , rangeBounds
  , boundsProblem
    -- * The scene's
  , sceneFormat
  , bodyFormat
  , jointFormat
    -- * Reading
  , Context (..)
  , Path
  , check
    -- * For the page
  , formatJSON
  ) where

import Control.Monad (foldM, forM, unless, when)
import qualified Data.Aeson as A
import qualified Data.Aeson.Key as K
import qualified Data.Aeson.KeyMap as KM
import Data.Char (isDigit)
import Data.List (intercalate)
import Data.Maybe (fromMaybe, isJust)
import Data.Scientific (toRealFloat)
import qualified Data.Text as T
import qualified Data.Vector as V

import Manifold.ContactManifold (maxHullCorners)
import Manifold.Hull (convexRound)
import Manifold.Params
import Manifold.World (contactsPerBody, keptFields)

-- | A JSON path: @$.bodies[2].size@.
type Path = String

-- | One end of a number's range: the limit, whether the limit itself is
-- out, and what a number past it is told.
data Bound = Bound Double Bool String deriving (Show, Eq)

-- | What a number must be besides finite: above its lower end, below its
-- upper one, whole (each with its message), checked in that order.
data Bounds = Bounds
  { lowest :: Maybe Bound
  , highest :: Maybe Bound
  , wholeOr :: Maybe String -- ^ a whole number, or this message
  } deriving (Show, Eq)

-- | What a JSON value must be.
data Format
  = Number Bounds -- ^ a finite number within the bounds
  | Flag -- ^ @true@ or @false@
  | Row [Format] Format [Int] String -- ^ an array of one of these lengths, item k of the k-th format (beyond them, the last format); else the message
  | List Format Int (Maybe Int) String -- ^ an array of so many values of the format (at least, at most); else the message
  | Record [String] [Entry] -- ^ an object of these keys (in the order an unknown key's message lists them), read entry by entry
  | OneOf Choice -- ^ one of some names, or an object of one of some keys
  | Tagged String [(String, Format)] String String -- ^ an object whose key names its kind, each kind's format; messages: not a name, an unknown kind ({0})
  | Name String String String -- ^ one of the context's names of this kind ('ctxNames'); messages: not a string, an unknown name ({0} the name, {1} the names)
  | Index String String (Maybe String) -- ^ an index into the list of this field's ('ctxCounts'), or the one string given; message ({0} the largest index)
  | Convex Format String -- ^ corners of the format that go round a convex polygon ("Manifold.Hull"'s 'convexRound'); else the message
  deriving (Show, Eq)

-- | A value that is one of some names (@"circle"@) or an object of one of
-- some keys (@{"box": [hx, hy]}@), with keys that may come with one of them
-- (@radius@ with @vertices@).
data Choice = Choice
  { choiceNames :: [String]
  , choiceKeyed :: [(String, Format)]
  , choiceCompanions :: [(String, String, Format)] -- ^ a key, the key it comes with, its format
  , choiceNotOne :: String -- ^ neither a name nor an object
  , choiceUnknown :: String -- ^ an unknown name ({0})
  , choiceOneKey :: String -- ^ an object of none or more than one of the keys
  , choiceCompanion :: String -- ^ a companion without its key ({0}: that key)
  } deriving (Show, Eq)

-- | How a record's key may be left out.
data Presence
  = Required -- ^ it may not
  | Optional -- ^ it may, and is then left out
  | Default A.Value -- ^ it may, and then has this value
  | PerStep Double String -- ^ it may, and then has so much a unit of the number this key of the record holds (the contact stiffness: 0.6 a step)
  deriving (Show, Eq)

-- | A step of reading a record.
data Entry
  = Field String Presence Format -- ^ a key and its value
  | Rule Rule -- ^ what the keys read so far must satisfy together
  | When String [String] [Entry] [Entry] -- ^ where the key's value is an object with one of these keys, these entries, else those
  deriving (Show, Eq)

-- | What keys must satisfy together.
data Rule
  = Together String String String -- ^ both or neither given: else the missing one "must be given with" the other, then the note
  | Ordered String String Bool -- ^ the first's number not above the second's: else the second (True) or the first (False) is told so
  | Differ String String String -- ^ not the same number: else the second is told the message ({0} the number)
  | NotGiven String String -- ^ left out: else the message
  | Islands String String String -- ^ a list of bodies: an @island@ names a sleeping body, only a sleeping body has one, a static body does not sleep (the messages); a sleeping body's island is its own unless given
  | Remembered String -- ^ a list of bodies remembers at most 'contactsPerBody' impulses a body ({0} how many, {1} the bodies, {2} a body's)
  | RefusedBy String String -- ^ the list of this key is empty where the context refuses it for the name this key holds ('ctxRefusal')
  | AtMostTwice String String String -- ^ the first key's list is at most twice as long as the second's (at least 1); message ({0}, {1} the lengths)
  | View String String String String String -- ^ eye, target, up: the target not the eye, up (the context's for the space, 'ctxUp', if left out) not along the view; the messages
  deriving (Show, Eq)

-- | What a check needs to know besides the value.
data Context = Context
  { ctxNames :: String -> [String] -- ^ the names a 'Name' of this kind takes
  , ctxCounts :: [(String, Int)] -- ^ the lengths of the lists read so far, by key
  , ctxFacts :: [(String, String)] -- ^ the names read so far, by key
  , ctxRefusal :: String -> Maybe String -- ^ why a space refuses a kind of thing (joints), if it does
  , ctxUp :: String -> Maybe [Double] -- ^ a space's camera's up
  }

-- The scene's --------------------------------------------------------------

-- | A scene key's values as bounds.
rangeBounds :: Range -> Bounds
rangeBounds = \case
  Switch -> noBounds
  Positive -> noBounds {lowest = Just positiveEnd}
  NonNegative -> noBounds {lowest = Just nonNegativeEnd}
  Fraction -> noBounds {lowest = Just nonNegativeEnd, highest = Just (Bound 1 False "must be between 0 and 1")}
  Count n -> let m = "must be a whole number from 1 to " ++ show n
             in Bounds (Just positiveEnd) (Just (Bound (fromIntegral n) False m)) (Just m)

-- | A number with no bounds but finiteness.
noBounds :: Bounds
noBounds = Bounds Nothing Nothing Nothing

-- | Above 0; 0 or above.
positiveEnd, nonNegativeEnd :: Bound
positiveEnd = Bound 0 True "must be positive"
nonNegativeEnd = Bound 0 False "must not be negative"

-- | Why a finite number is out of bounds, or 'Nothing'.
--
-- >>> boundsProblem (rangeBounds (Count 1000)) 2.5
-- Just "must be a whole number from 1 to 1000"
-- >>> boundsProblem (rangeBounds Fraction) 0.3
-- Nothing
boundsProblem :: Bounds -> Double -> Maybe String
boundsProblem b x = case (lowest b, highest b, wholeOr b) of
  (Just (Bound l strict m), _, _) | x < l || (strict && x == l) -> Just m
  (_, Just (Bound h strict m), _) | x > h || (strict && x == h) -> Just m
  (_, _, Just m) | x /= fromIntegral (round x :: Integer) -> Just m
  _ -> Nothing

-- | Any finite number; one above 0; one of 0 or above.
anyNumber, positive, nonNegative :: Format
anyNumber = Number noBounds
positive = Number noBounds {lowest = Just positiveEnd}
nonNegative = Number noBounds {lowest = Just nonNegativeEnd}

-- | A point or vector: three numbers.
vec3 :: Format
vec3 = Row [] anyNumber [3] "must be an array of three numbers [x, y, z]"

-- | So many numbers, what they are said in the message.
numbers :: Int -> String -> Format
numbers k what = Row [] anyNumber [k] ("must be an array of " ++ show k ++ " numbers, " ++ what)

-- | A scene: its space, the parameter keys ('sceneKeys'), its bodies,
-- joints and camera.
sceneFormat :: Format
sceneFormat = Record (["space"] ++ map keyName sceneKeys ++ ["bodies", "joints", "camera"]) $
  [Field "space" Required (Name "space" "must be a space name" "unknown space {0}; the spaces are {1}")]
  -- the parameters first (the step first: a left-out stiffness follows it), then the bodies
  ++ [Field (keyName k) (presence k) (keyFormat k) | k <- sceneKeys]
  ++ [ Field "bodies" (Default (A.Array mempty)) (List bodyFormat 0 Nothing "must be an array of bodies")
     , Rule (Islands "must be the index of a sleeping body (one with \"awake\": false)"
                     "is for a sleeping body (\"awake\": false)" "a static body does not sleep")
     , Rule (Remembered "{0} remembered contact impulses, more than {1} bodies remember ({2} a body)")
     , Field "joints" (Default (A.Array mempty)) (List jointFormat 0 Nothing "must be an array of joints")
     , Rule (RefusedBy "joints" "space")
     , Rule (AtMostTwice "joints" "bodies" "{0} joints, more than a world of {1} bodies holds (two a body)")
     , Field "camera" Optional cameraFormat ]
  where
    presence k = case perStepDefault (keyParam k) of
      Just c -> PerStep c "dt"
      Nothing -> Default (keyValueJSON k (paramValue defaultParams (keyParam k)))

-- | A scene key's value as a scene holds it.
keyValueJSON :: SceneKey -> Double -> A.Value
keyValueJSON k x = case keyRange k of
  Switch -> A.Bool (x > 0)
  Count _ -> A.toJSON (round x :: Int)
  _ -> A.toJSON x

-- | What a scene key takes.
keyFormat :: SceneKey -> Format
keyFormat k = case keyRange k of
  Switch -> Flag
  r -> Number (rangeBounds r)

-- | A scene's body (docs/scenes.md): its shape and size, its material,
-- where it is and how it moves, what it remembers.
bodyFormat :: Format
bodyFormat = Record bodyKeys $
  [ Field "axis" Optional vec3
  , Field "normal" Optional vec3
  , Rule (Together "axis" "normal" " (a saved body's frame)")
  , Field "shape" Required shapeFormat
  , When "shape" ["box", "capsule", "vertices"]
      [Rule (NotGiven "size" "is not given with a box, a capsule or vertices (its numbers are its size)")]
      [Field "size" Required positive]
  , Field "density" (Default (A.Number 1)) positive
  , Field "static" (Default (A.Bool False)) Flag
  , Field "p" Required vec3
  , Field "v" (Default (A.toJSON [0, 0, 0 :: Int])) vec3
  , Field "angle" (Default (A.Number 0)) anyNumber
  , Field "omega" (Default (A.Number 0)) anyNumber
  , Field "impulses" (Default (A.Array mempty)) impulsesFormat
  , Field "sleepTime" (Default (A.Number 0)) nonNegative ]
  -- its own friction and restitution: the scene keys' values
  ++ [Field (keyName k) Optional (keyFormat k) | k <- materialKeys]

-- | A body's shape.
shapeFormat :: Format
shapeFormat = OneOf Choice
  { choiceNames = ["circle", "square"]
  , choiceKeyed =
      [ ("polygon", Number (let m = "must be a whole number of sides from 3 to 64"
                            in Bounds (Just (Bound 3 False m)) (Just (Bound 64 False m)) (Just m)))
      , ("box", Row [] positive [2] "must be two half-extents [hx, hy]")
      , ("capsule", Row [] positive [2] "must be [halfLength, radius]")
      , ("vertices", Convex (List (Row [] anyNumber [2] "must be two numbers [a, b]") 3 (Just maxHullCorners)
                               ("must be an array of 3 to " ++ show maxHullCorners ++ " corners [a, b]"))
                            "must go round a convex polygon in order (each edge's line with every other corner strictly on one side, the same side for every edge)") ]
  , choiceCompanions = [("radius", "vertices", nonNegative)]
  , choiceNotOne = "must be one of " ++ shapeList
  , choiceUnknown = "unknown shape {0}; the shapes are " ++ shapeList
  , choiceOneKey = "must have one key: polygon, box, capsule or vertices"
  , choiceCompanion = "is given with {0} only" }
  where
    shapeList = "\"circle\", \"square\", {\"polygon\": N}, {\"box\": [hx, hy]}, {\"capsule\": [halfLength, radius]} and {\"vertices\": [[a, b], ...]}"

-- | A body's remembered contact impulses: @[[key, normal, friction], …]@,
-- a row to be kept followed by its kept numbers ('keptFields').
impulsesFormat :: Format
impulsesFormat = List row 0 Nothing "must be an array of [key, normal, friction] impulses"
  where
    kept = 3 + length keptFields
    key = let m = "must be a contact key, a whole number from 0 to 2^53"
          in Number (Bounds (Just (Bound 0 False m)) (Just (Bound (2 ^ (53 :: Int)) True m)) (Just m))
    row = Row [key, nonNegative, anyNumber] anyNumber [3, kept]
      ("must be an array of three numbers [key, normal, friction], or of " ++ show kept ++ " for a contact kept")

-- | A scene's joint, by its type (docs/scenes.md#joints).
jointFormat :: Format
jointFormat = Tagged "type" [(t, Record (common ++ own) (entries t)) | (t, own) <- kinds]
  ("must be one of " ++ types) ("unknown joint type {0}; the types are " ++ types)
  where
    types = "\"revolute\", \"distance\" and \"weld\""
    common = ["type", "a", "b", "collide", "local", "impulses"]
    kinds =
      [ ("revolute", ["anchor", "referenceAngle", "lowerAngle", "upperAngle", "motorSpeed", "maxMotorTorque"])
      , ("distance", ["anchorA", "anchorB", "length", "minLength", "maxLength", "hertz", "dampingRatio"])
      , ("weld", ["anchor", "referenceAngle", "hertz", "dampingRatio"]) ]
    index = "must be a body's index, from 0 to {0}"
    entries t =
      [ Field "a" Required (Index "bodies" index Nothing)
      , Field "b" Required (Index "bodies" (index ++ ", or \"world\"") (Just "world"))
      , Rule (Differ "a" "b" "joins body {0} to itself") ]
      ++ (if t == "distance" then [Field "anchorA" Required vec3, Field "anchorB" Required vec3] else [Field "anchor" Required vec3])
      ++ (if t == "distance"
            then [ Field "length" Optional nonNegative, Field "minLength" Optional nonNegative, Field "maxLength" Optional nonNegative
                 , Rule (Ordered "minLength" "length" False), Rule (Ordered "length" "maxLength" True)
                 , Rule (Ordered "minLength" "maxLength" True) ]
            else [])
      ++ (if t /= "revolute" then [Field "hertz" (Default (A.Number 0)) nonNegative, Field "dampingRatio" (Default (A.Number 0)) nonNegative] else [])
      ++ [Field "referenceAngle" Optional anyNumber | t /= "distance"]
      ++ (if t == "revolute"
            then [ Field "lowerAngle" Optional anyNumber, Field "upperAngle" Optional anyNumber
                 , Rule (Ordered "lowerAngle" "upperAngle" True), Rule (Together "lowerAngle" "upperAngle" "")
                 , Field "motorSpeed" Optional anyNumber, Field "maxMotorTorque" Optional nonNegative
                 , Rule (Together "motorSpeed" "maxMotorTorque" "") ]
            else [])
      ++ [ Field "local" Optional (numbers 7 "[rA, thetaA, rB, thetaB, worldX, worldY, worldZ]")
         , Field "impulses" (Default (A.Array mempty)) (numbers 7 "the joint's seven impulses")
         , Field "collide" (Default (A.Bool False)) Flag ]

-- | The view a scene opens with: eye and target, up and fov (degrees) the
-- space's camera's unless given.
cameraFormat :: Format
cameraFormat = Record ["eye", "target", "up", "fov"]
  [ Field "eye" Required vec3
  , Field "target" Required vec3
  , Field "up" Optional vec3
  , Field "fov" Optional (let m = "must be degrees between 0 and 180" in Number (Bounds (Just (Bound 0 True m)) (Just (Bound 180 True m)) Nothing))
  , Rule (View "eye" "target" "up" "must differ from the eye" "must not be along the view (from the eye to the target)") ]

-- Reading -------------------------------------------------------------------

-- | A value, or what is wrong with it: the JSON path of the first problem
-- and what is wrong there.
type P a = Either String a

-- | The problem at a path.
problem :: Path -> String -> P a
problem path msg = Left (path ++ ": " ++ msg)

-- | A message with its holes @{0}@, @{1}@, … filled.
--
-- >>> fill "{0} joints, more than {1}" ["3", "1"]
-- "3 joints, more than 1"
fill :: String -> [String] -> String
fill ('{' : d : '}' : rest) args | isDigit d, let k = fromEnum d - fromEnum '0', k < length args = args !! k ++ fill rest args
fill (c : rest) args = c : fill rest args
fill [] _ = []

-- | A JSON string as a message quotes it.
quoted :: T.Text -> String
quoted = show . T.unpack

-- | The value read against the format: completed, or the first problem.
check :: Context -> Format -> Path -> A.Value -> P A.Value
check ctx format path v = case format of
  Number b -> case v of
    A.Number s -> let x = toRealFloat s :: Double in
      if isNaN x || isInfinite x then problem path "must be a finite number"
      else maybe (pure v) (problem path) (boundsProblem b x)
    _ -> problem path "must be a number"
  Flag -> case v of
    A.Bool _ -> pure v
    _ -> problem path "must be true or false"
  Row items rest lengths msg -> case v of
    A.Array a | V.length a `elem` lengths ->
      A.Array . V.fromList <$> sequence
        [ check ctx (if k < length items then items !! k else rest) (at k) x | (k, x) <- zip [0 ..] (V.toList a) ]
    _ -> problem path msg
  List item least most msg -> case v of
    A.Array a | V.length a >= least, maybe True (V.length a <=) most ->
      A.Array . V.fromList <$> sequence [ check ctx item (at k) x | (k, x) <- zip [0 ..] (V.toList a) ]
    _ -> problem path msg
  Convex corners msg -> do
    cs <- check ctx corners path v
    let pairs = [ (n x, n y) | A.Array c <- arrayItems cs, [x, y] <- [V.toList c] ]
        n = \case A.Number s -> toRealFloat s; _ -> 0 / 0 :: Double
    unless (convexRound (fromIntegral (length pairs)) pairs > 0.5) $ problem path msg
    pure cs
  Record keys entries -> A.Object . fst <$> record ctx keys entries path v
  OneOf c -> case v of
    A.String s | T.unpack s `elem` choiceNames c -> pure v
               | otherwise -> problem path (fill (choiceUnknown c) [quoted s])
    A.Object o -> do
      _ <- known path (map fst (choiceKeyed c) ++ [k | (k, _, _) <- choiceCompanions c]) o
      let given = [ k | (k, _) <- choiceKeyed c, isJust (member o k) ]
      sequence_ [ when (isJust (member o k) && given /= [with]) (problem (path ++ "." ++ k) (fill (choiceCompanion c) [with]))
                | (k, with, _) <- choiceCompanions c ]
      case given of
        [k] | Just f <- lookup k (choiceKeyed c) -> do
          x <- check ctx f (path ++ "." ++ k) (fromMaybe A.Null (member o k))
          extra <- sequence [ (,) k' <$> check ctx f' (path ++ "." ++ k') y
                            | (k', with, f') <- choiceCompanions c, with == k, Just y <- [member o k'] ]
          pure (A.Object (KM.fromList [ (K.fromString n, y) | (n, y) <- (k, x) : extra ]))
        _ -> problem path (choiceOneKey c)
    _ -> problem path (choiceNotOne c)
  Tagged key kinds notOne unknown -> case v of
    A.Object o -> case member o key of
      Nothing -> problem (path ++ "." ++ key) "is missing"
      Just (A.String t) -> case lookup (T.unpack t) kinds of
        Just f -> check ctx f path v >>= \case
          A.Object out -> pure (A.Object (KM.insert (K.fromString key) (A.String t) out))
          out -> pure out
        Nothing -> problem (path ++ "." ++ key) (fill unknown [quoted t])
      Just _ -> problem (path ++ "." ++ key) notOne
    _ -> problem path "must be an object"
  Name kind notString unknown -> case v of
    A.String s | T.unpack s `elem` ctxNames ctx kind -> pure v
               | otherwise -> problem path (fill unknown [quoted s, intercalate ", " (ctxNames ctx kind)])
    _ -> problem path notString
  Index list msg alt -> case v of
    A.String s | Just (T.unpack s) == alt -> pure v
    A.Number s | let x = toRealFloat s :: Double, x == fromIntegral (round x :: Int)
               , let k = round x :: Int, k >= 0, k < count -> pure v
    _ -> problem path (fill msg [show (count - 1)])
    where count = fromMaybe 0 (lookup list (ctxCounts ctx))
  where
    at k = path ++ "[" ++ show (k :: Int) ++ "]"

-- | An array's items (none of anything else).
arrayItems :: A.Value -> [A.Value]
arrayItems = \case A.Array a -> V.toList a; _ -> []

-- | An object's value at a key.
member :: KM.KeyMap A.Value -> String -> Maybe A.Value
member o k = KM.lookup (K.fromString k) o

-- | An object whose keys are all known.
known :: Path -> [String] -> KM.KeyMap A.Value -> P (KM.KeyMap A.Value)
known path allowed o = do
  let unknown = [K.toString k | k <- KM.keys o, K.toString k `notElem` allowed]
  unless (null unknown) $
    problem (path ++ "." ++ head unknown) ("unknown key; the keys are " ++ intercalate ", " allowed)
  pure o

-- | A record read entry by entry: the completed object, and the context
-- with the lengths of its lists and its names.
record :: Context -> [String] -> [Entry] -> Path -> A.Value -> P (KM.KeyMap A.Value, Context)
record ctx0 keys entries path v = case v of
  A.Object o -> known path keys o >> foldM (entry o) (mempty, ctx0) entries
  _ -> problem path "must be an object"
  where
    entry o (out, ctx) = \case
      Field k presence f -> case member o k of
        Just x -> do
          y <- check ctx f (path ++ "." ++ k) x
          pure (KM.insert (K.fromString k) y out, learn ctx k f y)
        Nothing -> case presence of
          Required -> problem (path ++ "." ++ k) "is missing"
          Optional -> pure (out, ctx)
          Default d -> pure (KM.insert (K.fromString k) d out, learn ctx k f d)
          PerStep c unit -> pure (KM.insert (K.fromString k) (A.toJSON (c / numberAt out unit)) out, ctx)
      When k has yes no -> do
        let chosen = case member out k of
              Just (A.Object s) | any (isJust . member s) has -> yes
              _ -> no
        foldM (entry o) (out, ctx) chosen
      Rule r -> (, ctx) <$> rule ctx path o out r
    learn ctx k f y = case (f, y) of
      (List {}, A.Array a) -> ctx {ctxCounts = (k, V.length a) : ctxCounts ctx}
      (Name {}, A.String s) -> ctx {ctxFacts = (k, T.unpack s) : ctxFacts ctx}
      _ -> ctx

-- | The number at a key of a completed record (NaN if none).
numberAt :: KM.KeyMap A.Value -> String -> Double
numberAt o k = case member o k of
  Just (A.Number s) -> toRealFloat s
  _ -> 0 / 0

-- | A rule of a record whose entries so far gave @out@ (from the object @o@
-- as given): the record as the rule completes it, or its problem.
rule :: Context -> Path -> KM.KeyMap A.Value -> KM.KeyMap A.Value -> Rule -> P (KM.KeyMap A.Value)
rule ctx path o out = \case
  Together a b note -> do
    case (has a, has b) of
      (True, False) -> problem (path ++ "." ++ b) ("must be given with " ++ a ++ note)
      (False, True) -> problem (path ++ "." ++ a) ("must be given with " ++ b ++ note)
      _ -> pure out
  Ordered a b atSecond -> case (member out a, member out b) of
    (Just _, Just _) | numberAt out a > numberAt out b ->
      if atSecond then problem (path ++ "." ++ b) ("must not be less than " ++ a)
      else problem (path ++ "." ++ a) ("must not be more than " ++ b)
    _ -> pure out
  Differ a b msg -> case (member out a, member out b) of
    (Just (A.Number x), Just (A.Number y)) | x == y -> problem (path ++ "." ++ b) (fill msg [show (round (toRealFloat x :: Double) :: Int)])
    _ -> pure out
  NotGiven k msg -> if isJust (member o k) then problem (path ++ "." ++ k) msg else pure out
  Islands notIndex awakeIsland staticSleeps -> do
    let bodies = arrayItems (fromMaybe A.Null (member out "bodies"))
        given = arrayItems (fromMaybe A.Null (member o "bodies"))
        asleepAt i = i >= 0 && i < length given && case (given !! i, bodies !! i) of
          (A.Object g, A.Object b) -> member g "awake" == Just (A.Bool False) && member b "static" /= Just (A.Bool True)
          _ -> False
    done <- forM (zip3 [0 :: Int ..] given bodies) $ \(k, g, b) -> do
      let at = path ++ ".bodies[" ++ show k ++ "]"
          keysOf = \case A.Object x -> x; _ -> mempty
          gk = keysOf g
      awake <- maybe (pure True) (fmap (/= A.Bool False) . check ctx Flag (at ++ ".awake")) (member gk "awake")
      label <- case member gk "island" of
        Nothing -> pure Nothing
        Just x@(A.Number s) | let i = round (toRealFloat s :: Double) :: Int
                            , toRealFloat s == (fromIntegral i :: Double), asleepAt i -> pure (Just x)
        Just _ -> problem (at ++ ".island") notIndex
      let static = member (keysOf b) "static" == Just (A.Bool True)
      case (awake, label) of
        (True, Just _) -> problem (at ++ ".island") awakeIsland
        (False, _) | static -> problem (at ++ ".awake") staticSleeps
        (False, _) -> pure (A.Object (KM.insert "awake" (A.Bool False) (KM.insert "island" (fromMaybe (A.toJSON k) label) (keysOf b))))
        (True, Nothing) -> pure (A.Object (KM.delete "awake" (keysOf b)))
    pure (if null given then out else KM.insert "bodies" (A.toJSON done) out)
  Remembered msg -> do
    let bodies = arrayItems (fromMaybe A.Null (member out "bodies"))
        remembered = sum [ length (arrayItems (fromMaybe A.Null (member b "impulses"))) | A.Object b <- bodies ]
    when (remembered > contactsPerBody * length bodies) $
      problem (path ++ ".bodies") (fill msg [show remembered, show (length bodies), show contactsPerBody])
    pure out
  RefusedBy k by -> case (lookup by (ctxFacts ctx) >>= ctxRefusal ctx, arrayItems (fromMaybe A.Null (member out k))) of
    (Just why, _ : _) -> problem (path ++ "." ++ k) why
    _ -> pure out
  AtMostTwice a b msg -> do
    let n = length (arrayItems (fromMaybe A.Null (member out a)))
        m = length (arrayItems (fromMaybe A.Null (member out b)))
    when (n > 2 * max 1 m) $ problem (path ++ "." ++ a) (fill msg [show n, show m])
    pure out
  View eye target up same along -> do
    let vec k = [ toRealFloat s :: Double | A.Array a <- [fromMaybe A.Null (member out k)], A.Number s <- V.toList a ]
        f = zipWith (-) (vec target) (vec eye)
        u = case vec up of
          [] -> fromMaybe [] (lookup "space" (ctxFacts ctx) >>= ctxUp ctx)
          given -> given
    when (all (== 0) f) $ problem (path ++ "." ++ target) same
    case u of
      [ux, uy, uz] | [fx, fy, fz] <- f, uy * fz - uz * fy == 0, uz * fx - ux * fz == 0, ux * fy - uy * fx == 0 ->
        problem (path ++ "." ++ up) along
      _ -> pure out
  where
    has k = isJust (member out k)

-- For the page ---------------------------------------------------------------

-- | The format as JSON, for the page's interpreter (web/js/world.js): each
-- format an object of one key, its constructor's name.
formatJSON :: Format -> A.Value
formatJSON = \case
  Number b -> tag "number" (boundsJSON b)
  Flag -> tag "flag" A.Null
  Row items rest lengths msg -> tag "row" (A.object ["items" A..= map formatJSON items, "rest" A..= formatJSON rest, "lengths" A..= lengths, "message" A..= msg])
  List item least most msg -> tag "list" (A.object ["item" A..= formatJSON item, "least" A..= least, "most" A..= most, "message" A..= msg])
  Record keys entries -> tag "record" (A.object ["keys" A..= keys, "entries" A..= map entryJSON entries])
  OneOf c -> tag "oneOf" (A.object
    [ "names" A..= choiceNames c, "keyed" A..= [[A.toJSON k, formatJSON f] | (k, f) <- choiceKeyed c]
    , "companions" A..= [[A.toJSON k, A.toJSON w, formatJSON f] | (k, w, f) <- choiceCompanions c]
    , "notOne" A..= choiceNotOne c, "unknown" A..= choiceUnknown c, "oneKey" A..= choiceOneKey c, "companion" A..= choiceCompanion c ])
  Tagged key kinds notOne unknown -> tag "tagged" (A.object
    ["key" A..= key, "kinds" A..= A.object [K.fromString k A..= formatJSON f | (k, f) <- kinds], "notOne" A..= notOne, "unknown" A..= unknown])
  Name kind notString unknown -> tag "name" (A.object ["kind" A..= kind, "notString" A..= notString, "unknown" A..= unknown])
  Index list msg alt -> tag "index" (A.object ["list" A..= list, "message" A..= msg, "or" A..= alt])
  Convex corners msg -> tag "convex" (A.object ["corners" A..= formatJSON corners, "message" A..= msg])
  where
    tag :: String -> A.Value -> A.Value
    tag k x = A.object [K.fromString k A..= x]
    boundsJSON b = A.object
      [ "lowest" A..= fmap boundJSON (lowest b), "highest" A..= fmap boundJSON (highest b), "whole" A..= wholeOr b ]
    boundJSON (Bound x strict m) = A.object ["at" A..= x, "strict" A..= strict, "message" A..= m]
    entryJSON = \case
      Field k presence f -> A.object ["field" A..= k, "presence" A..= presenceJSON presence, "format" A..= formatJSON f]
      When k has yes no -> A.object ["when" A..= k, "has" A..= has, "then" A..= map entryJSON yes, "else" A..= map entryJSON no]
      Rule r -> A.object ["rule" A..= ruleJSON r]
    presenceJSON = \case
      Required -> A.object ["required" A..= True]
      Optional -> A.object ["optional" A..= True]
      Default d -> A.object ["default" A..= d]
      PerStep c unit -> A.object ["perStep" A..= c, "of" A..= unit]
    ruleJSON = \case
      Together a b note -> A.object ["together" A..= [a, b, note]]
      Ordered a b atSecond -> A.object ["ordered" A..= [a, b], "atSecond" A..= atSecond]
      Differ a b msg -> A.object ["differ" A..= [a, b, msg]]
      NotGiven k msg -> A.object ["notGiven" A..= [k, msg]]
      Islands a b c -> A.object ["islands" A..= [a, b, c]]
      Remembered msg -> A.object ["remembered" A..= msg, "perBody" A..= contactsPerBody]
      RefusedBy k by -> A.object ["refusedBy" A..= [k, by]]
      AtMostTwice a b msg -> A.object ["atMostTwice" A..= [a, b, msg]]
      View e t u same along -> A.object ["view" A..= [e, t, u, same, along]]
