{-# LANGUAGE OverloadedStrings, LambdaCase #-}
-- | Scenes: the JSON that @manifold sim@ and the page share — a space, the
-- engine's parameters and the bodies. Parsing names the JSON path of the
-- first problem it finds; unknown keys are problems too, so that a typo is
-- not silently ignored.
module Manifold.Scene
  ( Scene (..)
  , BodySpec (..)
  , JointSpec (..)
  , parseScene
  , sceneJSON
  , loadScene
  , bodyInit
  , sceneOfWorld
  , P
  ) where

import Control.Monad (foldM, forM, forM_, unless, when, zipWithM, zipWithM_)
import qualified Data.Aeson as A
import Data.Aeson.Internal (IResult (ISuccess), formatError)
import qualified Data.Aeson.Key as K
import qualified Data.Aeson.KeyMap as KM
import qualified Data.Aeson.Parser as AP
import qualified Data.Attoparsec.ByteString.Char8 as AC
import qualified Data.ByteString.Lazy as BL
import Data.List (intercalate)
import Data.Maybe (fromMaybe, isJust)
import Data.Scientific (toRealFloat)
import qualified Data.Text as T
import qualified Data.Vector as V
import Linear.V3 (V3 (..), cross)

import Manifold.ContactManifold (maxHullCorners)
import Manifold.Hull (convexRound)
import Manifold.Body
import Manifold.Engine
import Manifold.Params
import Manifold.Space
import Manifold.Spaces
import Manifold.World (Param (..), contactsPerBody, keptFields, layout)

-- | A body as a scene file gives it (its keys, in order: @shape@, @size@,
-- @density@, @friction@, @restitution@, @static@, @p@, @v@, @angle@, @omega@, @axis@, @normal@,
-- @impulses@, @awake@, @island@, @sleepTime@). A body with @axis@ and
-- @normal@ (what a saved scene holds) is restored exactly as it was saved;
-- one without is placed: projected onto the surface, its axis the
-- reference axis there. A body with @"awake": false@ sleeps, in the island
-- named by the index of one of its bodies (@island@, default its own).
-- A body without @friction@ or @restitution@ takes the scene's.
data BodySpec = BodySpec
  { bsShape :: ShapeKind
  , bsSize :: Double -- ^ circumradius, above 0 (a box's or a capsule's from its numbers: 'shapeSize')
  , bsDensity :: Double -- ^ above 0 (default 1)
  , bsStatic :: Bool -- ^ a fixed body (default false)
  , bsP :: V3 Double -- ^ its centre, projected onto the surface on load
  , bsV :: V3 Double -- ^ velocity (default 0), projected onto the tangent plane
  , bsAngle0 :: Double -- ^ from the axis a body placed at 'bsP' starts with, or from the saved axis (default 0)
  , bsOmega0 :: Double -- ^ angular velocity (default 0)
  , bsFrame :: Maybe (V3 Double, V3 Double) -- ^ the saved axis and normal, both or neither
  , bsImpulses :: [Impulse] -- ^ what the body remembers of the last step's contacts it owns (warm starting)
  , bsSleeping :: Maybe Int -- ^ asleep, in the island named by this body's index (default: awake)
  , bsCalmFor :: Double -- ^ its sleep timer: how long it has been calm (s, default 0: "Manifold.Sleep")
  , bsMaterial :: Material -- ^ its own friction and restitution (default: the scene's)
  } deriving (Show, Eq)

-- | What a scene file holds.
data Scene = Scene
  { sceneSpace :: Space -- ^ a catalogue space, by name
  , sceneParams :: Params -- ^ what the scene's keys ('sceneKeys') set, the rest defaults
  , sceneBodies :: [BodySpec]
  , sceneJoints :: [JointSpec] -- ^ joints between the scene's bodies (by index) or a body and the world
  , sceneCamera :: Maybe Camera -- ^ the view the page opens the scene with (@"camera"@: eye, target, and up and fov as the space's camera's unless given); the engine does not read it
  }

-- | A joint as a scene file gives it (@"joints": [{"type": "revolute",
-- "a": 0, "b": 1, "anchor": [x, y, z]}, …]@; docs/scenes.md#joints). A
-- saved joint ('sceneOfWorld') carries its anchors in its bodies' own
-- coordinates and its impulses, so that it is restored exactly.
data JointSpec = JointSpec
  { jsKind :: JointKind
  , jsA :: Int -- ^ a body's index
  , jsB :: Maybe Int -- ^ a body's index, or the world
  , jsAnchorA :: V3 Double -- ^ on body a (a pin's one anchor)
  , jsAnchorB :: V3 Double -- ^ on body b or of the world (a pin's: the same point)
  , jsLength :: Maybe Double -- ^ a distance joint's length (default: the anchors' distance)
  , jsMinLength :: Maybe Double -- ^ a distance joint's shortest (default: its length)
  , jsMaxLength :: Maybe Double -- ^ and longest
  , jsHertz :: Double -- ^ a distance joint's spring, or a weld's angular spring (0: rigid)
  , jsDampingRatio :: Double -- ^ that spring's damping ratio
  , jsReference :: Maybe Double -- ^ the relative angle held (default: the bodies' as the joint is made)
  , jsLimit :: Maybe (Double, Double) -- ^ a revolute joint's lower and upper angle, from the reference
  , jsMotor :: Maybe (Double, Double) -- ^ a revolute joint's motor: speed (rad/s) and most torque
  , jsLocal :: Maybe [Double] -- ^ a saved joint's anchors: body a's (r, θ), body b's (r, θ), the world point
  , jsImpulses :: [Double] -- ^ a saved joint's impulses (7)
  , jsCollide :: Bool -- ^ whether the joined bodies collide (default false)
  } deriving (Show, Eq)

type Path = String

-- | A value, or what is wrong with the scene: the JSON path of the first
-- problem (@$.bodies[2].size@) and what is wrong there.
type P a = Either String a

problem :: Path -> String -> P a
problem path msg = Left (path ++ ": " ++ msg)

object :: Path -> [String] -> A.Value -> P (KM.KeyMap A.Value)
object path allowed v = case v of
  A.Object o -> do
    let unknown = [K.toString k | k <- KM.keys o, K.toString k `notElem` allowed]
    unless (null unknown) $
      problem (path ++ "." ++ head unknown) ("unknown key; the keys are " ++ intercalate ", " allowed)
    pure o
  _ -> problem path "must be an object"

member :: KM.KeyMap A.Value -> String -> Maybe A.Value
member o k = KM.lookup (K.fromString k) o

required :: Path -> KM.KeyMap A.Value -> String -> (Path -> A.Value -> P a) -> P a
required path o k parse = maybe (problem (path ++ "." ++ k) "is missing") (parse (path ++ "." ++ k)) (member o k)

optional :: Path -> KM.KeyMap A.Value -> String -> a -> (Path -> A.Value -> P a) -> P a
optional path o k def parse = maybe (pure def) (parse (path ++ "." ++ k)) (member o k)

number :: Path -> A.Value -> P Double
number path = \case
  A.Number s -> let x = toRealFloat s in
    if isNaN x || isInfinite x then problem path "must be a finite number" else pure x
  _ -> problem path "must be a number"

nonNegative, positive :: Path -> A.Value -> P Double
nonNegative path v = number path v >>= \x -> if x < 0 then problem path "must not be negative" else pure x
positive path v = number path v >>= \x -> if x <= 0 then problem path "must be positive" else pure x

boolean :: Path -> A.Value -> P Bool
boolean _ (A.Bool b) = pure b
boolean path _ = problem path "must be true or false"

vec3 :: Path -> A.Value -> P (V3 Double)
vec3 path = \case
  A.Array a | V.length a == 3 -> do
    let component k = number (path ++ "[" ++ show k ++ "]") (a V.! k)
    V3 <$> component 0 <*> component 1 <*> component 2
  _ -> problem path "must be an array of three numbers [x, y, z]"

shape :: Path -> A.Value -> P ShapeKind
shape path = \case
  A.String "circle" -> pure CircleShape
  A.String "square" -> pure SquareShape
  A.String s -> problem path ("unknown shape " ++ show (T.unpack s) ++ "; the shapes are " ++ shapeList)
  v@(A.Object _) -> do
    o <- object path ["polygon", "box", "capsule", "vertices", "radius"] v
    let kinds = [k | k <- ["polygon", "box", "capsule", "vertices"], isJust (member o k)]
    when (isJust (member o "radius") && kinds /= ["vertices"]) $
      problem (path ++ ".radius") "is given with vertices only"
    case kinds of
      ["polygon"] -> do
        n <- required path o "polygon" number
        when (n /= fromIntegral (round n :: Int) || n < 3 || n > 64) $
          problem (path ++ ".polygon") "must be a whole number of sides from 3 to 64"
        pure (PolygonShape (round n))
      ["box"] -> uncurry BoxShape <$> required path o "box" (pair "two half-extents [hx, hy]")
      ["capsule"] -> uncurry CapsuleShape <$> required path o "capsule" (pair "[halfLength, radius]")
      ["vertices"] -> VerticesShape <$> required path o "vertices" corners <*> optional path o "radius" 0 nonNegative
      _ -> problem path "must have one key: polygon, box, capsule or vertices"
  _ -> problem path ("must be one of " ++ shapeList)
  where
    shapeList = "\"circle\", \"square\", {\"polygon\": N}, {\"box\": [hx, hy]}, {\"capsule\": [halfLength, radius]} and {\"vertices\": [[a, b], ...]}"
    corners at = \case
      A.Array a | V.length a >= 3 && V.length a <= maxHullCorners -> do
        cs <- sequence [ corner (at ++ "[" ++ show k ++ "]") c | (k, c) <- zip [0 :: Int ..] (V.toList a) ]
        unless (convexRound (fromIntegral (length cs)) cs > 0.5) $
          problem at "must go round a convex polygon in order (each edge's line with every other corner strictly on one side, the same side for every edge)"
        pure cs
      _ -> problem at ("must be an array of 3 to " ++ show maxHullCorners ++ " corners [a, b]")
    corner at = \case
      A.Array a | V.length a == 2 -> (,) <$> number (at ++ "[0]") (a V.! 0) <*> number (at ++ "[1]") (a V.! 1)
      _ -> problem at "must be two numbers [a, b]"
    pair what at = \case
      A.Array a | V.length a == 2 -> (,) <$> positive (at ++ "[0]") (a V.! 0) <*> positive (at ++ "[1]") (a V.! 1)
      _ -> problem at ("must be " ++ what)

-- | A body's size: given, or, for a box or a capsule, its numbers' (given
-- too, it is a problem).
bodySize :: Path -> KM.KeyMap A.Value -> ShapeKind -> P Double
bodySize path o k = case shapeSize k of
  Nothing -> required path o "size" positive
  Just s
    | isJust (member o "size") -> problem (path ++ ".size") "is not given with a box, a capsule or vertices (its numbers are its size)"
    | otherwise -> pure s

body :: Path -> A.Value -> P BodySpec
body path v = do
  o <- object path bodyKeys v
  axis <- optional path o "axis" Nothing (\at x -> Just <$> vec3 at x)
  normal <- optional path o "normal" Nothing (\at x -> Just <$> vec3 at x)
  frame <- case (axis, normal) of
    (Just a, Just n) -> pure (Just (a, n))
    (Nothing, Nothing) -> pure Nothing
    (Just _, Nothing) -> problem (path ++ ".normal") "must be given with axis (a saved body's frame)"
    (Nothing, Just _) -> problem (path ++ ".axis") "must be given with normal (a saved body's frame)"
  kind <- required path o "shape" shape
  BodySpec kind
    <$> bodySize path o kind
    <*> optional path o "density" 1 positive
    <*> optional path o "static" False boolean
    <*> required path o "p" vec3
    <*> optional path o "v" (V3 0 0 0) vec3
    <*> optional path o "angle" 0 number
    <*> optional path o "omega" 0 number
    <*> pure frame
    <*> optional path o "impulses" [] impulses
    <*> pure Nothing
    <*> optional path o "sleepTime" 0 nonNegative
    <*> (Material <$> materialKey o Friction <*> materialKey o Restitution)
  where
    -- a body's friction or restitution: the scene key's values
    materialKey o param = case [k | k <- materialKeys, keyParam k == param] of
      k : _ -> optional path o (keyName k) Nothing $ \at x ->
        number at x >>= \y -> maybe (pure (Just y)) (problem at) (outOfRange (keyRange k) y)
      [] -> error "materialKey: no scene key sets this parameter"

-- | The bodies' @awake@ and @island@ keys: a sleeping body's island is
-- named by the index of a sleeping body (its own by default); a static
-- body does not sleep.
sleeping :: [A.Value] -> [BodySpec] -> P [BodySpec]
sleeping values specs = forM (zip3 [0 :: Int ..] values specs) $ \(k, v, spec) -> do
  let path = "$.bodies[" ++ show k ++ "]"
      keys = case v of A.Object o -> o; _ -> mempty
  awake <- optional path keys "awake" True boolean
  let asleepAt i = i >= 0 && i < length values && case values !! i of
        A.Object o -> member o "awake" == Just (A.Bool False) && not (bsStatic (specs !! i))
        _ -> False
  label <- optional path keys "island" Nothing $ \at x -> case x of
    A.Number n | toRealFloat n == (fromIntegral (round (toRealFloat n :: Double) :: Int) :: Double)
               , asleepAt (round (toRealFloat n :: Double)) -> pure (Just (round (toRealFloat n :: Double)))
    _ -> problem at "must be the index of a sleeping body (one with \"awake\": false)"
  case (awake, label) of
    (True, Just _) -> problem (path ++ ".island") "is for a sleeping body (\"awake\": false)"
    (False, _) | bsStatic spec -> problem (path ++ ".awake") "a static body does not sleep"
    (False, _) -> pure spec { bsSleeping = Just (fromMaybe k label) }
    (True, Nothing) -> pure spec

-- | A body's remembered contact impulses: @[[key, normal, friction], …]@,
-- a row to be kept followed by its kept numbers ('keptFields').
impulses :: Path -> A.Value -> P [Impulse]
impulses path = \case
  A.Array a -> forM (zip [0 :: Int ..] (V.toList a)) $ \(k, x) -> do
    let at = path ++ "[" ++ show k ++ "]"
    case x of
      A.Array r | V.length r `elem` [3, 3 + length keptFields] -> do
        key <- number (at ++ "[0]") (r V.! 0)
        when (key /= fromIntegral (round key :: Integer) || key < 0 || key >= 2 ^ (53 :: Int)) $
          problem (at ++ "[0]") "must be a contact key, a whole number from 0 to 2^53"
        Impulse key <$> nonNegative (at ++ "[1]") (r V.! 1) <*> number (at ++ "[2]") (r V.! 2)
          <*> mapM (\m -> number (at ++ "[" ++ show m ++ "]") (r V.! m)) [3 .. V.length r - 1]
      _ -> problem at ("must be an array of three numbers [key, normal, friction], or of "
                       ++ show (3 + length keptFields) ++ " for a contact kept")
  _ -> problem path "must be an array of [key, normal, friction] impulses"

-- | A scene from its JSON text. Of an object's keys given twice, the last
-- counts, as in the page's @JSON.parse@ (aeson's own decoder keeps the
-- first), so that a scene file reads alike in both.
parseScene :: BL.ByteString -> P Scene
parseScene text = do
  v <- either (\(path, e) -> Left ("not JSON: " ++ formatError path e)) pure
         (AP.eitherDecodeWith (AP.jsonLast <* AC.skipSpace <* AC.endOfInput) ISuccess text)
  o <- object "$" (["space"] ++ map keyName sceneKeys ++ ["bodies", "joints", "camera"]) v
  sp <- required "$" o "space" $ \path -> \case
    A.String s -> maybe (problem path ("unknown space " ++ show (T.unpack s) ++ "; the spaces are " ++ intercalate ", " spaceNames))
                        pure (lookupSpace (T.unpack s))
    _ -> problem path "must be a space name"
  params <- foldM (sceneKey o) defaultParams sceneKeys
  bodies <- optional "$" o "bodies" [] $ \path -> \case
    A.Array a -> do
      specs <- forM (zip [0 :: Int ..] (V.toList a)) $ \(k, b) -> body (path ++ "[" ++ show k ++ "]") b
      sleeping (V.toList a) specs
    _ -> problem path "must be an array of bodies"
  let remembered = sum (map (length . bsImpulses) bodies)
      room = contactsPerBody * length bodies
  when (remembered > room) $
    problem "$.bodies" (show remembered ++ " remembered contact impulses, more than " ++ show (length bodies)
                         ++ " bodies remember (" ++ show contactsPerBody ++ " a body)")
  joints <- optional "$" o "joints" [] $ \path -> \case
    A.Array a -> forM (zip [0 :: Int ..] (V.toList a)) $ \(k, j) -> joint (length bodies) (path ++ "[" ++ show k ++ "]") j
    _ -> problem path "must be an array of joints"
  forM_ (jointsRefused sp) $ \why -> unless (null joints) (problem "$.joints" why)
  when (length joints > 2 * max 1 (length bodies)) $
    problem "$.joints" (show (length joints) ++ " joints, more than a world of " ++ show (length bodies) ++ " bodies holds (two a body)")
  camera <- optional "$" o "camera" Nothing (\path c -> Just <$> sceneCameraOf sp path c)
  pure (Scene sp params bodies joints camera)

-- | A scene's camera: eye and target (which must differ), up and fov (in
-- degrees, between 0 and 180) the space's camera's unless given, up not
-- along the view.
sceneCameraOf :: Space -> Path -> A.Value -> P Camera
sceneCameraOf sp path v = do
  o <- object path ["eye", "target", "up", "fov"] v
  let own = spaceCamera sp
  eye <- required path o "eye" vec3
  target <- required path o "target" vec3
  up <- optional path o "up" (cameraUp own) vec3
  fov <- optional path o "fov" (cameraFov own) $ \at x -> number at x >>= \d ->
    if d > 0 && d < 180 then pure d else problem at "must be degrees between 0 and 180"
  when (target == eye) $ problem (path ++ ".target") "must differ from the eye"
  when (cross up (target - eye) == V3 0 0 0) $
    problem (path ++ ".up") "must not be along the view (from the eye to the target)"
  pure (Camera eye target up fov)

-- | A scene's joint, for a scene of @n@ bodies.
joint :: Int -> Path -> A.Value -> P JointSpec
joint n path v = do
  kind <- case v of
    A.Object o0 -> case member o0 "type" of
      Just (A.String "revolute") -> pure Revolute
      Just (A.String "distance") -> pure Distance
      Just (A.String "weld") -> pure Weld
      Just (A.String t) -> problem (path ++ ".type") ("unknown joint type " ++ show (T.unpack t) ++ "; the types are " ++ jointTypes)
      Just _ -> problem (path ++ ".type") ("must be one of " ++ jointTypes)
      Nothing -> problem (path ++ ".type") "is missing"
    _ -> problem path "must be an object"
  let common = ["type", "a", "b", "collide", "local", "impulses"]
      own = case kind of
        Revolute -> ["anchor", "referenceAngle", "lowerAngle", "upperAngle", "motorSpeed", "maxMotorTorque"]
        Distance -> ["anchorA", "anchorB", "length", "minLength", "maxLength", "hertz", "dampingRatio"]
        Weld -> ["anchor", "referenceAngle", "hertz", "dampingRatio"]
  o <- object path (common ++ own) v
  let index at = \case
        A.Number x | toRealFloat x == (fromIntegral (round (toRealFloat x :: Double) :: Int) :: Double)
                   , let k = round (toRealFloat x :: Double), k >= 0, k < n -> pure k
        _ -> problem at ("must be a body's index, from 0 to " ++ show (n - 1))
  a <- required path o "a" index
  b <- required path o "b" $ \at -> \case
    A.String "world" -> pure Nothing
    x -> either (const (problem at ("must be a body's index, from 0 to " ++ show (n - 1) ++ ", or \"world\""))) (pure . Just) (index at x)
  when (b == Just a) $ problem (path ++ ".b") ("joins body " ++ show a ++ " to itself")
  (anchorA, anchorB) <- case kind of
    Distance -> (,) <$> required path o "anchorA" vec3 <*> required path o "anchorB" vec3
    _ -> (\p -> (p, p)) <$> required path o "anchor" vec3
  len <- optional path o "length" Nothing (\at x -> Just <$> nonNegative at x)
  lo <- optional path o "minLength" Nothing (\at x -> Just <$> nonNegative at x)
  hi <- optional path o "maxLength" Nothing (\at x -> Just <$> nonNegative at x)
  case (lo, len, hi) of
    (Just l, Just m, _) | l > m -> problem (path ++ ".minLength") "must not be more than length"
    (_, Just m, Just h) | m > h -> problem (path ++ ".maxLength") "must not be less than length"
    (Just l, _, Just h) | l > h -> problem (path ++ ".maxLength") "must not be less than minLength"
    _ -> pure ()
  hz <- optional path o "hertz" 0 nonNegative
  zeta <- optional path o "dampingRatio" 0 nonNegative
  ref <- optional path o "referenceAngle" Nothing (\at x -> Just <$> number at x)
  lower <- optional path o "lowerAngle" Nothing (\at x -> Just <$> number at x)
  upper <- optional path o "upperAngle" Nothing (\at x -> Just <$> number at x)
  limit <- case (lower, upper) of
    (Just l, Just u) | l > u -> problem (path ++ ".upperAngle") "must not be less than lowerAngle"
                     | otherwise -> pure (Just (l, u))
    (Nothing, Nothing) -> pure Nothing
    (Just _, Nothing) -> problem (path ++ ".upperAngle") "must be given with lowerAngle"
    (Nothing, Just _) -> problem (path ++ ".lowerAngle") "must be given with upperAngle"
  speed <- optional path o "motorSpeed" Nothing (\at x -> Just <$> number at x)
  torque <- optional path o "maxMotorTorque" Nothing (\at x -> Just <$> nonNegative at x)
  motor <- case (speed, torque) of
    (Just s', Just t) -> pure (Just (s', t))
    (Nothing, Nothing) -> pure Nothing
    (Just _, Nothing) -> problem (path ++ ".maxMotorTorque") "must be given with motorSpeed"
    (Nothing, Just _) -> problem (path ++ ".motorSpeed") "must be given with maxMotorTorque"
  local <- optional path o "local" Nothing (\at x -> Just <$> numbers 7 "[rA, thetaA, rB, thetaB, worldX, worldY, worldZ]" at x)
  imps <- optional path o "impulses" [] (numbers 7 "the joint's seven impulses")
  collide <- optional path o "collide" False boolean
  pure (JointSpec kind a b anchorA anchorB len lo hi hz zeta ref limit motor local imps collide)
  where
    jointTypes = "\"revolute\", \"distance\" and \"weld\""
    numbers k what at = \case
      A.Array xs | V.length xs == k -> forM (zip [0 :: Int ..] (V.toList xs)) $ \(i, x) -> number (at ++ "[" ++ show i ++ "]") x
      _ -> problem at ("must be an array of " ++ show k ++ " numbers, " ++ what)

-- | A scene key's value set in the parameters: the scene's, or its
-- 'keyDefault' (the keys are read in order, the step first).
sceneKey :: KM.KeyMap A.Value -> Params -> SceneKey -> P Params
sceneKey o p k = optional "$" o (keyName k) (setParam (keyParam k) (keyDefault p k) p) $ \path v -> do
  x <- case keyRange k of
    Switch -> (\b -> if b then 1 else 0) <$> boolean path v
    r -> number path v >>= \x -> maybe (pure x) (problem path) (outOfRange r x)
  pure (setParam (keyParam k) x p)

-- | A scene as the JSON 'parseScene' reads (numbers are printed so that
-- they read back exactly).
sceneJSON :: Scene -> A.Value
sceneJSON s = A.object
  ( ["space" A..= spaceName (sceneSpace s)]
    ++ [ K.fromString (keyName k) A..= keyJSON k | k <- sceneKeys ]
    ++ ["bodies" A..= map bodyJSON (sceneBodies s)]
    ++ [ "joints" A..= map jointJSON (sceneJoints s) | not (null (sceneJoints s)) ]
    ++ [ "camera" A..= A.object [ "eye" A..= v3 (cameraEye c), "target" A..= v3 (cameraTarget c)
                                , "up" A..= v3 (cameraUp c), "fov" A..= cameraFov c ]
       | Just c <- [sceneCamera s] ] )
  where
    jointJSON j = A.object $
      [ "type" A..= (case jsKind j of Revolute -> "revolute"; Distance -> "distance"; Weld -> "weld" :: String)
      , "a" A..= jsA j, "b" A..= maybe (A.String "world") A.toJSON (jsB j) ]
      ++ (case jsKind j of
            Distance -> [ "anchorA" A..= v3 (jsAnchorA j), "anchorB" A..= v3 (jsAnchorB j) ]
                        ++ concat [ [K.fromString key A..= x] | (key, Just x) <- [("length", jsLength j), ("minLength", jsMinLength j), ("maxLength", jsMaxLength j)] ]
            _ -> ("anchor" A..= v3 (jsAnchorA j)) : [ "referenceAngle" A..= r | Just r <- [jsReference j] ])
      ++ [ "hertz" A..= jsHertz j | jsKind j /= Revolute, jsHertz j /= 0 ]
      ++ [ "dampingRatio" A..= jsDampingRatio j | jsKind j /= Revolute, jsDampingRatio j /= 0 ]
      ++ concat [ ["lowerAngle" A..= l, "upperAngle" A..= u] | Just (l, u) <- [jsLimit j] ]
      ++ concat [ ["motorSpeed" A..= sp', "maxMotorTorque" A..= t] | Just (sp', t) <- [jsMotor j] ]
      ++ [ "collide" A..= True | jsCollide j ]
      ++ [ "local" A..= l | Just l <- [jsLocal j] ]
      ++ [ "impulses" A..= jsImpulses j | not (null (jsImpulses j)) ]
    bodyJSON b = A.object $
      [ "shape" A..= shapeJSON (bsShape b) ]
      ++ [ "size" A..= bsSize b | Nothing <- [shapeSize (bsShape b)] ]
      ++ [ "density" A..= bsDensity b ]
      ++ [ "friction" A..= x | Just x <- [matFriction (bsMaterial b)] ]
      ++ [ "restitution" A..= x | Just x <- [matRestitution (bsMaterial b)] ]
      ++ [ "static" A..= bsStatic b, "p" A..= v3 (bsP b), "v" A..= v3 (bsV b)
      , "angle" A..= bsAngle0 b, "omega" A..= bsOmega0 b ]
      ++ concat [ ["axis" A..= v3 a, "normal" A..= v3 n] | Just (a, n) <- [bsFrame b] ]
      ++ [ "impulses" A..= [[impulseKey r, impulseNormal r, impulseFriction r] ++ impulseKept r | r <- bsImpulses b] | not (null (bsImpulses b)) ]
      ++ concat [ ["awake" A..= False, "island" A..= label] | Just label <- [bsSleeping b] ]
      ++ [ "sleepTime" A..= bsCalmFor b | bsCalmFor b /= 0 ]
    shapeJSON = \case
      CircleShape -> A.String "circle"
      SquareShape -> A.String "square"
      PolygonShape n -> A.object ["polygon" A..= n]
      BoxShape p q -> A.object ["box" A..= [p, q]]
      CapsuleShape p q -> A.object ["capsule" A..= [p, q]]
      VerticesShape cs r -> A.object (("vertices" A..= [[a, b] | (a, b) <- cs]) : ["radius" A..= r | r /= 0])
    v3 (V3 x y z) = [x, y, z]
    keyJSON k = let x = paramValue (sceneParams s) (keyParam k) in case keyRange k of
      Switch -> A.Bool (x > 0)
      Count _ -> A.toJSON (round x :: Int)
      _ -> A.toJSON x

-- | The body a scene's body spec adds to a world (its remembered impulses
-- are given to the world apart: 'restoreImpulses').
bodyInit :: BodySpec -> BodyInit
bodyInit b = BodyInit (shapeFromKind (bsShape b)) (bsSize b) (bsDensity b) (bsStatic b) (bsP b) (bsV b) (bsAngle0 b) (bsOmega0 b) (bsMaterial b)

-- | A world holding the scene (with room for @extra@ more bodies), its
-- bodies remembering the contact impulses the scene gives them, so that a
-- saved pile goes on as it went instead of sagging for the steps warm
-- starting would take to find its impulses again.
loadScene :: Int -> Scene -> IO (P NativeWorld)
loadScene extra s = do
  w <- newWorld (sceneSpace s) (layout (length (sceneBodies s) + extra))
  setParams w (sceneParams s)
  added <- forM (zip [0 :: Int ..] (sceneBodies s)) $ \(k, b) ->
    let field = if isJust (bsFrame b) then ".axis: " else ".p: "
    in either (Left . (("$.bodies[" ++ show k ++ "]" ++ field) ++)) Right
         <$> maybe (addBody w (bodyInit b)) (restoreBody w (bodyInit b)) (bsFrame b)
  case sequence added of
    Left e -> pure (Left e)
    Right _ -> do
      restored <- either (Left . ("$.bodies: " ++)) Right <$> restoreImpulses w (map bsImpulses (sceneBodies s))
      joined <- zipWithM (loadJoint w) [0 ..] (sceneJoints s)
      -- asleep after the joints are made: a joint made wakes its bodies
      forM_ (zip [0 ..] (sceneBodies s)) $ \(k, b) -> setSleepingAt w k (bsSleeping b) (bsCalmFor b)
      pure (restored >> sequence_ joined >> pure w)

-- | Add a scene's joint @k@ to the world.
loadJoint :: NativeWorld -> Int -> JointSpec -> IO (P ())
loadJoint w k j = do
  let path = "$.joints[" ++ show k ++ "]"
      anchorKey = if jsKind j == Distance then ".anchorA" else ".anchor"
  added <- addJointAt w (jsKind j) (jsA j) (fromMaybe (-1) (jsB j)) (jsAnchorA j) (jsAnchorB j)
  case added of
    Left e -> pure (Left (path ++ anchorKey ++ ": " ++ e))
    Right i -> do
      let set = setJointField w i
      forM_ (jsLocal j) $ \l -> zipWithM_ set [JRadiusA, JThetaA, JRadiusB, JThetaB, JWorldX, JWorldY, JWorldZ] l
      chord <- jointField w i JLength
      let len = fromMaybe chord (jsLength j)
          lo = fromMaybe len (jsMinLength j)
          hi = fromMaybe len (jsMaxLength j)
          tooShort = lo > len
          tooLong = len > hi
      if jsKind j == Distance && (tooShort || tooLong)
        then pure (problem (path ++ (if tooShort then ".minLength" else ".maxLength"))
                     (if tooShort then "must not be more than the length (the anchors' distance)" else "must not be less than the length (the anchors' distance)"))
        else do
          when (jsKind j == Distance) $ zipWithM_ set [JLength, JMinLength, JMaxLength] [len, lo, hi]
          set JHertz (jsHertz j)
          set JCollide (if jsCollide j then 1 else 0)
          set JDamping (jsDampingRatio j)
          forM_ (jsReference j) (set JReference)
          forM_ (jsLimit j) $ \(l, u) -> zipWithM_ set [JLimitOn, JLower, JUpper] [1, l, u]
          forM_ (jsMotor j) $ \(sp', t) -> zipWithM_ set [JMotorOn, JMotorSpeed, JMaxTorque] [1, sp', t]
          zipWithM_ set jointImpulses (jsImpulses j)
          pure (Right ())

-- | A joint's impulses, in the order a saved joint lists them.
jointImpulses :: [JointField]
jointImpulses = [JImpulse1, JImpulse2, JImpulseAxial, JImpulseLower, JImpulseUpper, JImpulseMotor, JImpulseAngle]

-- | Joint @i@ of the world as a scene holds it, with its anchors in its
-- bodies' coordinates and its impulses (restored exactly by 'loadScene').
jointOfWorld :: NativeWorld -> Int -> IO JointSpec
jointOfWorld w i = do
  let get = jointField w i
      v3At k = V3 <$> get k <*> get (succ k) <*> get (succ (succ k))
  kind <- toEnum . round <$> get JKind
  a <- round <$> get JA
  b <- get JB
  anchorA <- v3At JAnchorAX
  anchorB <- if b < 0 then v3At JWorldX else v3At JAnchorBX
  [len, lo, hi, hz, zeta, ref, limitOn, lower, upper, motorOn, speed, torque] <-
    mapM get [JLength, JMinLength, JMaxLength, JHertz, JDamping, JReference, JLimitOn, JLower, JUpper, JMotorOn, JMotorSpeed, JMaxTorque]
  local <- mapM get [JRadiusA, JThetaA, JRadiusB, JThetaB, JWorldX, JWorldY, JWorldZ]
  imps <- mapM get jointImpulses
  collide <- get JCollide
  let distance = kind == Distance
  pure JointSpec
    { jsKind = kind, jsA = a, jsB = if b < 0 then Nothing else Just (round b)
    , jsAnchorA = anchorA, jsAnchorB = if kind == Distance then anchorB else anchorA
    , jsLength = if distance then Just len else Nothing
    , jsMinLength = if distance then Just lo else Nothing
    , jsMaxLength = if distance then Just hi else Nothing
    , jsHertz = hz, jsDampingRatio = zeta
    , jsReference = if distance then Nothing else Just ref
    , jsLimit = if limitOn > 0 then Just (lower, upper) else Nothing
    , jsMotor = if motorOn > 0 then Just (speed, torque) else Nothing
    , jsLocal = Just local, jsImpulses = imps, jsCollide = collide > 0 }

-- | The scene as the world now has it: the scene's bodies (which the world
-- must hold in the scene's order: as 'loadScene' made it, none added or
-- removed since) where they are now, moving as they now move, each with
-- the axis it has carried along and its normal (its angle measured from
-- that axis), so that loading the scene restores every body bit for bit
-- and the run goes on as it would have. Each body keeps what it remembers
-- of the last step's contacts; the joints are the world's now, each with
-- its anchors in its bodies' coordinates and its impulses.
sceneOfWorld :: Scene -> NativeWorld -> IO (P Scene)
sceneOfWorld s w = do
  n <- bodyCount w
  let specs = sceneBodies s
  if n /= length specs
    then pure (Left ("the world holds " ++ show n ++ " bodies, the scene " ++ show (length specs)))
    else do
      bodies <- forM (zip [0 ..] specs) $ \(i, spec) -> do
        st <- readBody w i
        remembered <- rememberedImpulses w i
        pure spec { bsP = bsPos st, bsV = bsVel st, bsAngle0 = bsAngle st, bsOmega0 = bsOmega st
                  , bsFrame = Just (bsAxis st, bsNormal st), bsImpulses = remembered
                  , bsSleeping = bsAsleep st, bsCalmFor = bsSleepTimer st }
      nj <- jointCount w
      joints <- mapM (jointOfWorld w) [0 .. nj - 1]
      pure (Right s { sceneBodies = bodies, sceneJoints = joints })
