{-# LANGUAGE OverloadedStrings #-}
-- | Scenes: the JSON that @manifold sim@ and the page share — a space, the
-- engine's parameters and the bodies. Parsing names the JSON path of the
-- first problem it finds; unknown keys are problems too, so that a typo is
-- not silently ignored.
module Manifold.Scene
  ( Scene (..)
  , BodySpec (..)
  , parseScene
  , sceneJSON
  , loadScene
  , bodyInit
  , sceneOfWorld
  , P
  ) where

import Control.Monad (foldM, forM, unless, when)
import qualified Data.Aeson as A
import Data.Aeson.Internal (IResult (ISuccess), formatError)
import qualified Data.Aeson.Key as K
import qualified Data.Aeson.KeyMap as KM
import qualified Data.Aeson.Parser as AP
import qualified Data.Attoparsec.ByteString.Char8 as AC
import qualified Data.ByteString.Lazy as BL
import Data.List (intercalate)
import Data.Maybe (isJust)
import Data.Scientific (toRealFloat)
import qualified Data.Text as T
import qualified Data.Vector as V
import Linear.V3 (V3 (..))

import Manifold.Body
import Manifold.Engine
import Manifold.Params
import Manifold.Space
import Manifold.Spaces
import Manifold.World (contactsPerBody, layout)

-- | A body as a scene file gives it (its keys, in order: @shape@, @size@,
-- @density@, @static@, @p@, @v@, @angle@, @omega@, @axis@, @normal@,
-- @impulses@). A body with @axis@ and @normal@ (what a saved scene holds)
-- is restored exactly as it was saved; one without is placed: projected
-- onto the surface, its axis the reference axis there.
data BodySpec = BodySpec
  { bsShape :: ShapeKind
  , bsSize :: Double -- ^ circumradius, above 0
  , bsDensity :: Double -- ^ above 0 (default 1)
  , bsStatic :: Bool -- ^ a fixed body (default false)
  , bsP :: V3 Double -- ^ its centre, projected onto the surface on load
  , bsV :: V3 Double -- ^ velocity (default 0), projected onto the tangent plane
  , bsAngle0 :: Double -- ^ from the axis a body placed at 'bsP' starts with, or from the saved axis (default 0)
  , bsOmega0 :: Double -- ^ angular velocity (default 0)
  , bsFrame :: Maybe (V3 Double, V3 Double) -- ^ the saved axis and normal, both or neither
  , bsImpulses :: [Impulse] -- ^ what the body remembers of the last step's contacts it owns (warm starting)
  } deriving (Show, Eq)

-- | What a scene file holds.
data Scene = Scene
  { sceneSpace :: Space -- ^ a catalogue space, by name
  , sceneParams :: Params -- ^ what the scene's keys ('sceneKeys') set, the rest defaults
  , sceneBodies :: [BodySpec]
  }

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
  A.String s -> problem path ("unknown shape " ++ show (T.unpack s) ++ "; the shapes are \"circle\", \"square\" and {\"polygon\": N}")
  v@(A.Object _) -> do
    o <- object path ["polygon"] v
    n <- required path o "polygon" number
    when (n /= fromIntegral (round n :: Int) || n < 3 || n > 64) $
      problem (path ++ ".polygon") "must be a whole number of sides from 3 to 64"
    pure (PolygonShape (round n))
  _ -> problem path "must be \"circle\", \"square\" or {\"polygon\": N}"

body :: Path -> A.Value -> P BodySpec
body path v = do
  o <- object path ["shape", "size", "density", "static", "p", "v", "angle", "omega", "axis", "normal", "impulses"] v
  axis <- optional path o "axis" Nothing (\at x -> Just <$> vec3 at x)
  normal <- optional path o "normal" Nothing (\at x -> Just <$> vec3 at x)
  frame <- case (axis, normal) of
    (Just a, Just n) -> pure (Just (a, n))
    (Nothing, Nothing) -> pure Nothing
    (Just _, Nothing) -> problem (path ++ ".normal") "must be given with axis (a saved body's frame)"
    (Nothing, Just _) -> problem (path ++ ".axis") "must be given with normal (a saved body's frame)"
  BodySpec
    <$> required path o "shape" shape
    <*> required path o "size" positive
    <*> optional path o "density" 1 positive
    <*> optional path o "static" False boolean
    <*> required path o "p" vec3
    <*> optional path o "v" (V3 0 0 0) vec3
    <*> optional path o "angle" 0 number
    <*> optional path o "omega" 0 number
    <*> pure frame
    <*> optional path o "impulses" [] impulses

-- | A body's remembered contact impulses: @[[key, normal, friction], …]@.
impulses :: Path -> A.Value -> P [Impulse]
impulses path = \case
  A.Array a -> forM (zip [0 :: Int ..] (V.toList a)) $ \(k, x) -> do
    let at = path ++ "[" ++ show k ++ "]"
    case x of
      A.Array r | V.length r == 3 -> do
        key <- number (at ++ "[0]") (r V.! 0)
        when (key /= fromIntegral (round key :: Integer) || key < 0 || key >= 2 ^ (53 :: Int)) $
          problem (at ++ "[0]") "must be a contact key, a whole number from 0 to 2^53"
        Impulse key <$> nonNegative (at ++ "[1]") (r V.! 1) <*> number (at ++ "[2]") (r V.! 2)
      _ -> problem at "must be an array of three numbers [key, normal, friction]"
  _ -> problem path "must be an array of [key, normal, friction] impulses"

-- | A scene from its JSON text. Of an object's keys given twice, the last
-- counts, as in the page's @JSON.parse@ (aeson's own decoder keeps the
-- first), so that a scene file reads alike in both.
parseScene :: BL.ByteString -> P Scene
parseScene text = do
  v <- either (\(path, e) -> Left ("not JSON: " ++ formatError path e)) pure
         (AP.eitherDecodeWith (AP.jsonLast <* AC.skipSpace <* AC.endOfInput) ISuccess text)
  o <- object "$" (["space"] ++ map keyName sceneKeys ++ ["bodies"]) v
  sp <- required "$" o "space" $ \path -> \case
    A.String s -> maybe (problem path ("unknown space " ++ show (T.unpack s) ++ "; the spaces are " ++ intercalate ", " spaceNames))
                        pure (lookupSpace (T.unpack s))
    _ -> problem path "must be a space name"
  params <- foldM (sceneKey o) defaultParams sceneKeys
  bodies <- optional "$" o "bodies" [] $ \path -> \case
    A.Array a -> forM (zip [0 :: Int ..] (V.toList a)) $ \(k, b) -> body (path ++ "[" ++ show k ++ "]") b
    _ -> problem path "must be an array of bodies"
  let remembered = sum (map (length . bsImpulses) bodies)
      room = contactsPerBody * length bodies
  when (remembered > room) $
    problem "$.bodies" (show remembered ++ " remembered contact impulses, more than " ++ show (length bodies)
                         ++ " bodies remember (" ++ show contactsPerBody ++ " a body)")
  pure (Scene sp params bodies)

-- | A scene key's value, if the scene gives it, set in the parameters.
sceneKey :: KM.KeyMap A.Value -> Params -> SceneKey -> P Params
sceneKey o p k = optional "$" o (keyName k) p $ \path v -> do
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
    ++ ["bodies" A..= map bodyJSON (sceneBodies s)] )
  where
    bodyJSON b = A.object $
      [ "shape" A..= shapeJSON (bsShape b), "size" A..= bsSize b, "density" A..= bsDensity b
      , "static" A..= bsStatic b, "p" A..= v3 (bsP b), "v" A..= v3 (bsV b)
      , "angle" A..= bsAngle0 b, "omega" A..= bsOmega0 b ]
      ++ concat [ ["axis" A..= v3 a, "normal" A..= v3 n] | Just (a, n) <- [bsFrame b] ]
      ++ [ "impulses" A..= [[impulseKey r, impulseNormal r, impulseFriction r] | r <- bsImpulses b] | not (null (bsImpulses b)) ]
    shapeJSON = \case
      CircleShape -> A.String "circle"
      SquareShape -> A.String "square"
      PolygonShape n -> A.object ["polygon" A..= n]
    v3 (V3 x y z) = [x, y, z]
    keyJSON k = let x = paramValue (sceneParams s) (keyParam k) in case keyRange k of
      Switch -> A.Bool (x > 0)
      Count _ -> A.toJSON (round x :: Int)
      _ -> A.toJSON x

-- | The body a scene's body spec adds to a world (its remembered impulses
-- are given to the world apart: 'restoreImpulses').
bodyInit :: BodySpec -> BodyInit
bodyInit b = BodyInit (shapeFromKind (bsShape b)) (bsSize b) (bsDensity b) (bsStatic b) (bsP b) (bsV b) (bsAngle0 b) (bsOmega0 b)

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
    Right _ -> fmap (const w) . either (Left . ("$.bodies: " ++)) Right
                 <$> restoreImpulses w (map bsImpulses (sceneBodies s))

-- | The scene as the world now has it: the scene's bodies (which the world
-- must hold in the scene's order: as 'loadScene' made it, none added or
-- removed since) where they are now, moving as they now move, each with
-- the axis it has carried along and its normal (its angle measured from
-- that axis), so that loading the scene restores every body bit for bit
-- and the run goes on as it would have. Each body keeps what it remembers
-- of the last step's contacts.
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
                  , bsFrame = Just (bsAxis st, bsNormal st), bsImpulses = remembered }
      pure (Right s { sceneBodies = bodies })
