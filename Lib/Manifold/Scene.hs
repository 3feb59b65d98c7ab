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

import Control.Monad (forM, forM_, when, zipWithM, zipWithM_, (>=>))
import qualified Data.Aeson as A
import Data.Aeson.Internal (IResult (ISuccess), formatError)
import qualified Data.Aeson.Key as K
import qualified Data.Aeson.KeyMap as KM
import qualified Data.Aeson.Parser as AP
import qualified Data.Attoparsec.ByteString.Char8 as AC
import qualified Data.ByteString.Lazy as BL
import Data.Maybe (fromMaybe, isJust)
import Data.Scientific (toRealFloat)
import qualified Data.Text as T
import qualified Data.Vector as V
import Linear.V3 (V3 (..))

import Manifold.Body
import Manifold.Engine
import Manifold.Params
import Manifold.SceneFormat (Context (..), check, sceneFormat)
import Manifold.Space
import Manifold.Spaces
import Manifold.World (layout)

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

-- | A value, or what is wrong with the scene: the JSON path of the first
-- problem (@$.bodies[2].size@) and what is wrong there.
type P a = Either String a

-- | The problem at a JSON path.
problem :: String -> String -> P a
problem path msg = Left (path ++ ": " ++ msg)

-- | A scene from its JSON text: checked against "Manifold.SceneFormat"'s
-- description (the page reads it with the same), then read. Of an
-- object's keys given twice, the last counts, as in the page's
-- @JSON.parse@ (aeson's own decoder keeps the first), so that a scene file
-- reads alike in both.
parseScene :: BL.ByteString -> P Scene
parseScene text = do
  v <- either (\(path, e) -> Left ("not JSON: " ++ formatError path e)) pure
         (AP.eitherDecodeWith (AP.jsonLast <* AC.skipSpace <* AC.endOfInput) ISuccess text)
  checked <- check sceneContext sceneFormat "$" v
  let o = keys checked
  sp <- maybe (Left "$.space: unknown space") pure (lookupSpace (str (at o "space")))
  pure Scene
    { sceneSpace = sp
    , sceneParams = foldl (\p k -> setParam (keyParam k) (paramNumber (at o (keyName k))) p) defaultParams sceneKeys
    , sceneBodies = map bodySpec (items (at o "bodies"))
    , sceneJoints = map jointSpec (items (at o "joints"))
    , sceneCamera = cameraOf (spaceCamera sp) <$> given o "camera" }

-- | What a scene's check knows: the catalogue's spaces, which refuse
-- joints, and their cameras' up.
sceneContext :: Context
sceneContext = Context
  { ctxNames = const spaceNames
  , ctxCounts = []
  , ctxFacts = []
  , ctxRefusal = lookupSpace >=> jointsRefused
  , ctxUp = fmap ((\(V3 x y z) -> [x, y, z]) . cameraUp . spaceCamera) . lookupSpace }

-- Reading a checked value (its format has made sure of what it holds) ------

-- | An object's keys and values.
keys :: A.Value -> KM.KeyMap A.Value
keys = \case A.Object o -> o; _ -> mempty

-- | The value at a key, if the object has it.
given :: KM.KeyMap A.Value -> String -> Maybe A.Value
given o k = KM.lookup (K.fromString k) o

-- | The value at a key the format completes.
at :: KM.KeyMap A.Value -> String -> A.Value
at o k = fromMaybe A.Null (given o k)

-- | An array's items.
items :: A.Value -> [A.Value]
items = \case A.Array a -> V.toList a; _ -> []

-- | A number.
num :: A.Value -> Double
num = \case A.Number s -> toRealFloat s; _ -> 0 / 0

-- | A string.
str :: A.Value -> String
str = \case A.String t -> T.unpack t; _ -> ""

-- | A flag.
flag :: A.Value -> Bool
flag = (== A.Bool True)

-- | A scene key's value as its parameter holds it (a switch 1 or 0).
paramNumber :: A.Value -> Double
paramNumber = \case A.Bool b -> if b then 1 else 0; x -> num x

-- | Three numbers as a vector.
v3 :: A.Value -> V3 Double
v3 x = case map num (items x) of
  [a, b, c] -> V3 a b c
  _ -> V3 (0 / 0) (0 / 0) (0 / 0)

-- | A checked shape.
shapeOf :: A.Value -> ShapeKind
shapeOf = \case
  A.String "square" -> SquareShape
  A.String _ -> CircleShape
  x -> let o = keys x
           pair k = case map num (items (at o k)) of [p, q] -> (p, q); _ -> (0, 0)
       in case () of
            _ | Just n <- given o "polygon" -> PolygonShape (round (num n))
              | Just _ <- given o "box" -> uncurry BoxShape (pair "box")
              | Just _ <- given o "capsule" -> uncurry CapsuleShape (pair "capsule")
              | otherwise -> VerticesShape [ (a, b) | [a, b] <- map (map num . items) (items (at o "vertices")) ]
                                           (maybe 0 num (given o "radius"))

-- | A checked body (a box's, a capsule's or vertices' size from their numbers).
bodySpec :: A.Value -> BodySpec
bodySpec x = BodySpec
  { bsShape = kind
  , bsSize = fromMaybe (num (at o "size")) (shapeSize kind)
  , bsDensity = num (at o "density")
  , bsStatic = flag (at o "static")
  , bsP = v3 (at o "p")
  , bsV = v3 (at o "v")
  , bsAngle0 = num (at o "angle")
  , bsOmega0 = num (at o "omega")
  , bsFrame = (,) <$> (v3 <$> given o "axis") <*> (v3 <$> given o "normal")
  , bsImpulses = [ Impulse (num k) (num n) (num f) (map num kept) | k : n : f : kept <- map items (items (at o "impulses")) ]
  , bsSleeping = if given o "awake" == Just (A.Bool False) then Just (round (num (at o "island"))) else Nothing
  , bsCalmFor = num (at o "sleepTime")
  , bsMaterial = Material (num <$> given o "friction") (num <$> given o "restitution") }
  where
    o = keys x
    kind = shapeOf (at o "shape")

-- | A checked joint.
jointSpec :: A.Value -> JointSpec
jointSpec x = JointSpec
  { jsKind = kind
  , jsA = round (num (at o "a"))
  , jsB = case at o "b" of A.Number s -> Just (round (toRealFloat s :: Double)); _ -> Nothing
  , jsAnchorA = v3 (at o (if kind == Distance then "anchorA" else "anchor"))
  , jsAnchorB = v3 (at o (if kind == Distance then "anchorB" else "anchor"))
  , jsLength = number "length"
  , jsMinLength = number "minLength"
  , jsMaxLength = number "maxLength"
  , jsHertz = fromMaybe 0 (number "hertz")
  , jsDampingRatio = fromMaybe 0 (number "dampingRatio")
  , jsReference = number "referenceAngle"
  , jsLimit = (,) <$> number "lowerAngle" <*> number "upperAngle"
  , jsMotor = (,) <$> number "motorSpeed" <*> number "maxMotorTorque"
  , jsLocal = map num . items <$> given o "local"
  , jsImpulses = map num (items (at o "impulses"))
  , jsCollide = flag (at o "collide") }
  where
    o = keys x
    number k = num <$> given o k
    kind = case str (at o "type") of
      "distance" -> Distance
      "weld" -> Weld
      _ -> Revolute

-- | A checked camera, up and fov the space's camera's where left out.
cameraOf :: Camera -> A.Value -> Camera
cameraOf own x = Camera (v3 (at o "eye")) (v3 (at o "target")) (maybe (cameraUp own) v3 (given o "up")) (maybe (cameraFov own) num (given o "fov"))
  where o = keys x

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
