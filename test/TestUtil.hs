-- | Helpers shared by the specs: approximate comparison, random points on and
-- near the surface of every space of the catalogue, finite differences, and
-- locating the @manifold@ executable.
module TestUtil
  ( -- * Approximate comparison
    closeAbs
  , closeRel
  , relErr
  , vecDist
  , maxAbsV
  , matDist
    -- * Random vectors
  , genUnitV3
  , genV3In
  , genTangentUnit
    -- * Surface points
  , SurfaceSampler (..)
  , surfaceSampler
  , genSurfacePoint
  , genNearSurfacePoint
  , genTorusAngles
  , torusPoint
    -- * Finite differences
  , fdGrad
  , fdHessianOfGrad
  , fdStable
    -- * Misc
  , fieldFn
  , fieldAt
  , gradAt
  , firstPlacement
  , findManifoldExe
  , runBytes
  , showV3
    -- * Space scripts
  , scriptOf
  ) where

import Control.Concurrent (forkIO)
import Control.Concurrent.MVar (newEmptyMVar, putMVar, takeMVar)
import Control.Exception (SomeException, evaluate, try)
import qualified Data.ByteString as BS
import qualified Data.ByteString.Lazy as BL
import Data.Char (isSpace)
import Linear.Matrix (M33)
import Linear.Metric (dot, norm)
import Linear.V3 (V3 (..))
import Linear.Vector ((*^), (^+^), (^-^))
import System.Directory (doesFileExist, findExecutable)
import System.Environment (lookupEnv)
import System.IO (hClose, hSetBinaryMode)
import System.Process
import System.Exit (ExitCode (..))
import Test.QuickCheck
import Text.Printf (printf)

import Manifold
import Manifold.Compiled.Runtime (spaceFingerprint)
import Manifold.Stage.Kernels (spaceScript)
import Manifold.World (layout)

-- Approximate comparison ---------------------------------------------------

-- | @|a − b| ≤ tol@.
closeAbs :: Double -> Double -> Double -> Bool
closeAbs tol a b = abs (a - b) <= tol

-- | @|a − b| ≤ tol · max(|a|, |b|)@ (so 0 is only close to 0).
closeRel :: Double -> Double -> Double -> Bool
closeRel tol a b = abs (a - b) <= tol * max (abs a) (abs b)

-- | @|measured − expected| / |expected|@.
relErr :: Double -> Double -> Double
relErr expected measured = abs (measured - expected) / abs expected

vecDist :: V3 Double -> V3 Double -> Double
vecDist a b = norm (a ^-^ b)

maxAbsV :: V3 Double -> Double
maxAbsV = maximum . fmap abs

-- | Largest absolute entry difference of two 3×3 matrices.
matDist :: M33 Double -> M33 Double -> Double
matDist a b = maximum (fmap maxAbsV (a ^-^ b))

showV3 :: V3 Double -> String
showV3 (V3 x y z) = printf "(%.6g, %.6g, %.6g)" x y z

-- Random vectors -------------------------------------------------------------

-- | A uniformly distributed unit vector (Marsaglia).
genUnitV3 :: Gen (V3 Double)
genUnitV3 = do
  z <- choose (-1, 1)
  t <- choose (0, 2 * pi)
  let r = sqrt (max 0 (1 - z * z))
  pure (V3 (r * cos t) (r * sin t) z)

-- | A point of the cube @[-a, a]³@.
genV3In :: Double -> Gen (V3 Double)
genV3In a = V3 <$> choose (-a, a) <*> choose (-a, a) <*> choose (-a, a)

-- | A unit tangent vector at a point with unit normal @n@.
genTangentUnit :: V3 Double -> Gen (V3 Double)
genTangentUnit n =
  (genUnitV3 >>= \u -> let w = u ^-^ (u `dot` n) *^ n
                           l = norm w
                       in pure (if l > 0.1 then Just ((1 / l) *^ w) else Nothing))
    `suchThatMap` id

-- Surface points ---------------------------------------------------------------

-- | How points on a space's surface are drawn, and the (explicit) domain.
data SurfaceSampler = SurfaceSampler
  { samplerDomain :: String -- ^ human-readable domain of the samples
  , samplerGen :: Gen (V3 Double) -- ^ points exactly (analytically) on f = 0
  }

-- | Torus angles: φ around the tube, ψ around the y axis.
genTorusAngles :: Gen (Double, Double)
genTorusAngles = (,) <$> choose (0, 2 * pi) <*> choose (0, 2 * pi)

-- | The torus point @((R + r cos φ) cos ψ, r sin φ, (R + r cos φ) sin ψ)@.
torusPoint :: Double -> Double -> V3 Double
torusPoint phi psi =
  let bigR = torusMajor
      r = torusMinor
      rho = bigR + r * cos phi
  in V3 (rho * cos psi) (r * sin phi) (rho * sin psi)

-- | A sampler of surface points for each space of the catalogue, by name. The
-- domains avoid the places where the gradient of the field vanishes or the
-- field is not smooth: the trumpet's axis (its far narrow end) and the
-- centre of the inner box of the rounded cube.
surfaceSampler :: Space -> SurfaceSampler
surfaceSampler s = case spaceName s of
  n | n `elem` ["plane", "disc", "rectangle", "funnel", "flat-torus", "flat-klein"] ->
        SurfaceSampler "y = 0, |x| <= 1.5, |z| <= 1.5"
          ((\x z -> V3 x 0 z) <$> choose (-1.5, 1.5) <*> choose (-1.5, 1.5))
  n | n `elem` ["sphere", "hemisphere", "projective-plane"] ->
        SurfaceSampler "the whole unit sphere" genUnitV3
  n | n `elem` ["torus", "klein-bottle"] ->
        SurfaceSampler "the whole torus R = 0.8, r = 0.5" (uncurry torusPoint <$> genTorusAngles)
  "trumpet" ->
        SurfaceSampler "sqrt(x²+z²) = exp y with -1 <= y <= 1 (radius >= 0.37, away from the axis)"
          ((\y t -> let r = exp y in V3 (r * cos t) y (r * sin t))
             <$> choose (-1, 1) <*> choose (0, 2 * pi))
  "moebius" ->
        SurfaceSampler "x²+z² = 1, |y| <= 0.6"
          ((\y t -> V3 (cos t) y (sin t)) <$> choose (-0.6, 0.6) <*> choose (0, 2 * pi))
  "cube" ->
        -- The field is the exact distance to the box of half-size 0.6, minus
        -- 0.3: the surface point nearest a point x outside the box is its
        -- nearest box point c pushed out by 0.3 along x − c.
        SurfaceSampler "the whole rounded cube (box half-size 0.6 + 0.3)"
          ((genV3In 1.5 >>= \x ->
              let c = fmap (max (-0.6) . min 0.6) x
                  d = x ^-^ c
                  l = norm d
              in pure (if l > 1e-3 then Just (c ^+^ (0.3 / l) *^ d) else Nothing))
             `suchThatMap` id)
  "hyperbolic-plane" ->
        SurfaceSampler "the hyperboloid y = cosh r, (x, z) = sinh r (cos t, sin t), r <= 2.5"
          ((\r t -> V3 (sinh r * cos t) (cosh r) (sinh r * sin t)) <$> choose (0, 2.5) <*> choose (0, 2 * pi))
  "bolza" ->
        SurfaceSampler "the hyperboloid y = cosh r, (x, z) = sinh r (cos t, sin t), r <= 2.5 (the octagon's inradius is 1.53, its circumradius 2.45)"
          ((\r t -> V3 (sinh r * cos t) (cosh r) (sinh r * sin t)) <$> choose (0, 2.5) <*> choose (0, 2 * pi))
  other -> error ("TestUtil.surfaceSampler: no sampler for space " ++ show other)

genSurfacePoint :: Space -> Gen (V3 Double)
genSurfacePoint = samplerGen . surfaceSampler

-- | A surface point moved by up to @d@ in a random direction.
genNearSurfacePoint :: Double -> Space -> Gen (V3 Double)
genNearSurfacePoint d s = do
  p <- genSurfacePoint s
  u <- genUnitV3
  t <- choose (0, d)
  pure (p ^+^ t *^ u)

-- Finite differences ------------------------------------------------------------

-- | Central finite-difference gradient with step @h@.
fdGrad :: Double -> (V3 Double -> Double) -> V3 Double -> V3 Double
fdGrad h f p = fmap (\e -> (f (p ^+^ h *^ e) - f (p ^-^ h *^ e)) / (2 * h)) basis

basis :: V3 (V3 Double)
basis = V3 (V3 1 0 0) (V3 0 1 0) (V3 0 0 1)

-- | Central differences of a gradient: row i is ∂(∇f)/∂x_i (the Hessian is
-- symmetric, so rows and columns agree for a C² field).
fdHessianOfGrad :: Double -> (V3 Double -> V3 Double) -> V3 Double -> M33 Double
fdHessianOfGrad h g p = fmap (\e -> (1 / (2 * h)) *^ (g (p ^+^ h *^ e) ^-^ g (p ^-^ h *^ e))) basis

-- | Do two finite-difference estimates agree (so the function is smooth at
-- the scale of the steps)? Used to skip points next to a kink.
fdStable :: Double -> Double -> Double -> Bool
fdStable tol a b = abs (a - b) <= tol * max 1 (max (abs a) (abs b))

-- Misc -----------------------------------------------------------------------------

fieldFn :: Space -> (forall a. Field a => V3 a -> a)
fieldFn s = evalPoly (spaceField s)

fieldAt :: Space -> V3 Double -> Double
fieldAt = evalField

-- | The AD gradient of a space's field.
gradAt :: Space -> V3 Double -> V3 Double
gradAt s = fieldGradient (spaceField s)

-- | The first placement of a space's default scene.
firstPlacement :: Space -> V3 Double
firstPlacement s = case spaceScene s of
  (pl : _) -> placeAt pl
  [] -> error ("space " ++ spaceName s ++ " has an empty scene")

-- | The @manifold@ executable: @$MANIFOLD_EXE@ when set (an explicit
-- choice wins), else on PATH (cabal puts build-tool-depends there during
-- @cabal test@), else @cabal list-bin@.
findManifoldExe :: IO FilePath
findManifoldExe = do
  env <- lookupEnv "MANIFOLD_EXE"
  onPath <- findExecutable "manifold"
  case (env, onPath) of
    (Just p, _) -> pure p
    (Nothing, Just p) -> pure p
    (Nothing, Nothing) -> do
      r <- try (readProcessWithExitCode "cabal" ["list-bin", "-v0", "exe:manifold"] "")
             :: IO (Either SomeException (ExitCode, String, String))
      case r of
        Right (ExitSuccess, out, _) -> do
          let p = trim out
          ok <- doesFileExist p
          if ok then pure p else fail ("cabal list-bin gave " ++ show p ++ ", which does not exist")
        _ -> fail "cannot find the manifold executable: not on PATH, MANIFOLD_EXE unset, cabal list-bin failed"
  where trim = reverse . dropWhile isSpace . reverse . dropWhile isSpace

-- | Run a program with arguments and no input; its stdout as raw bytes (the
-- JSON is UTF-8 whatever the locale) and its stderr as raw bytes too.
runBytes :: FilePath -> [String] -> IO (ExitCode, BL.ByteString, BS.ByteString)
runBytes exe args = do
  (Just hin, Just hout, Just herr, ph) <-
    createProcess (proc exe args) { std_in = CreatePipe, std_out = CreatePipe, std_err = CreatePipe }
  hClose hin
  hSetBinaryMode hout True
  hSetBinaryMode herr True
  errVar <- newEmptyMVar
  _ <- forkIO (BS.hGetContents herr >>= evaluate >>= putMVar errVar)
  out <- BS.hGetContents hout
  err <- takeMVar errVar
  code <- waitForProcess ph
  pure (code, BL.fromStrict out, err)

-- | A space's script ('spaceScript'): for a space of the catalogue (the
-- same name and fingerprint), printed once for the whole suite. Staging a
-- space takes seconds, and many specs run the same catalogue space's
-- engine under node; a space of a test's own is printed afresh.
scriptOf :: Space -> String
scriptOf sp = case lookup (spaceName sp) catalogueScripts of
  Just (fingerprint, script) | fingerprint == spaceFingerprint sp (layout 0) -> script
  _ -> spaceScript sp

-- | Each catalogue space's fingerprint and script, printed when first asked.
catalogueScripts :: [(String, (String, String))]
catalogueScripts = [ (spaceName s, (spaceFingerprint s (layout 0), spaceScript s)) | s <- catalogue ]
{-# NOINLINE catalogueScripts #-}
