{-# LANGUAGE FlexibleContexts #-}
-- | The engine as a staged program: the step's phases and the page's
-- procedures (adding, removing, picking and grabbing bodies, adding and
-- removing joints and drawing them, the measures
-- the page plots) over the world's arrays, and the geodesic the page's tool draws, as
-- "Manifold.Stage.Imp" stages them. The page's script
-- ("Manifold.Stage.EngineScript") and the compiled native step
-- ("Manifold.Compile") are both made from these lists.
module Manifold.Program
  ( stagedArrays
  , worldParams
  , stepProcedures
  , pageProcedures
  , stagedPhases
  , phaseFunction
  ) where

import Data.Char (toUpper)
import Data.Foldable (toList)
import Linear.V3 (V3 (..))

import Manifold.Body
import Manifold.GeodesicPath (walkGeodesic)
import Manifold.Grab
import Manifold.Joint (addJoint, jointAnchors, jointPaths, removeJoint)
import Manifold.Measures (measureBody, measureWorld)
import Manifold.Population
import Manifold.Sleep (countIslands, setSleeping)
import Manifold.Space
import Manifold.Stage.Expr (E)
import Manifold.Stage.Imp
import Manifold.Step (stepPhases)
import Manifold.World

-- | The world's arrays as a staged program names them.
stagedArrays :: WorldArrays StagedArray
stagedArrays = fmap StagedArray arrayNames

-- | The names of the world's arrays, in order: every procedure's array
-- parameters.
worldParams :: [String]
worldParams = toList arrayNames

-- | The step's phases as procedures, one for each phase.
stepProcedures :: Space -> Layout -> [(Procedure, [StagedArray] -> [E] -> Staged ())]
stepProcedures sp l = [ (Procedure (phaseFunction name) worldParams [], \_ _ -> phase sp l stagedArrays) | (name, phase) <- stagedPhases ]

-- | The procedures the page calls: the phases, then the rest.
pageProcedures :: Space -> Layout -> [(Procedure, [StagedArray] -> [E] -> Staged ())]
pageProcedures sp l = stepProcedures sp l ++
  [ (Procedure "polygonise" worldParams [], \_ _ -> polygoniseEvery sp l stagedArrays)
  , (Procedure "addBody" (worldParams ++ ["corners"])
      ["shape", "shapeP", "shapeQ", "size", "density", "isStatic", "px", "py", "pz", "vx", "vy", "vz", "angle", "omega", "restore", "ax", "ay", "az", "nx", "ny", "nz"
      , "friction", "restitution"],
      \arrays [code, p, q, size, density, static, px, py, pz, vx, vy, vz, angle, omega, restore, ax, ay, az, nx, ny, nz, mu, e] ->
         addBodyWith sp l stagedArrays (last arrays) codeOutline
           (BodyArgs size density static (V3 px py pz) (V3 vx vy vz) angle omega restore (V3 ax ay az) (V3 nx ny nz) mu e
              code p q))
  , (Procedure "removeBody" worldParams ["index"],
      \_ [i] -> removeBody sp l stagedArrays (toIndex i))
  , (Procedure "pickBody" worldParams ["qx", "qy", "qz"],
      \_ [x, y, z] -> pickBody sp l stagedArrays (V3 x y z))
  , (Procedure "grab" worldParams ["index", "sign", "qx", "qy", "qz", "frequency", "damping", "maxForce"],
      \_ [i, sgn, x, y, z, hz, zeta, fmax] -> grab sp stagedArrays (toIndex i) sgn (V3 x y z) hz zeta fmax)
  , (Procedure "drag" worldParams ["qx", "qy", "qz"],
      \_ [x, y, z] -> dragTo stagedArrays (V3 x y z))
  , (Procedure "release" worldParams [], \_ _ -> release stagedArrays)
  , (Procedure "addJoint" worldParams ["kind", "a", "b", "ax", "ay", "az", "bx", "by", "bz"],
      \_ [kind, a, b, ax, ay, az, bx, by, bz] -> addJoint sp stagedArrays kind a b (V3 ax ay az) (V3 bx by bz))
  , (Procedure "removeJoint" worldParams ["index"],
      \_ [j] -> removeJoint stagedArrays (toIndex j))
  , (Procedure "countIslands" worldParams [], \_ _ -> countIslands stagedArrays)
  , (Procedure "setSleeping" worldParams ["index", "island", "timer"],
      \_ [i, label, timer] -> setSleeping stagedArrays (toIndex i) label timer)
  , (Procedure "jointAnchors" (worldParams ++ ["out"]) [],
      \arrays _ -> jointAnchors sp stagedArrays (last arrays))
  , (Procedure "jointPaths" (worldParams ++ ["out"]) [],
      \arrays _ -> jointPaths sp stagedArrays (last arrays))
  , (Procedure "measure" (worldParams ++ ["out"]) [],
      \arrays _ -> measureWorld sp stagedArrays (last arrays))
  , (Procedure "measureBody" (worldParams ++ ["out"]) ["index"],
      \arrays [i] -> measureBody sp stagedArrays (last arrays) (toIndex i))
  , (Procedure "geodesic" ["path"] ["px", "py", "pz", "dx", "dy", "dz", "length", "steps"],
      \[path] [px, py, pz, dx, dy, dz, len, steps] ->
         walkGeodesic sp path (V3 px py pz) (V3 dx dy dz) len (toIndex steps))
  ]

-- | The step's phases, staged.
stagedPhases :: [(String, Space -> Layout -> WorldArrays StagedArray -> Staged ())]
stagedPhases = stepPhases

-- | The function of one phase of the step. The step is staged as one
-- function per phase (and the phases' large parts as subroutines, see
-- 'subroutine') because V8 does not optimise a function whose bytecode is
-- larger than 60 KB, and the whole step is larger: unoptimised, it ran 17
-- times slower (torus, 655 bodies, bench/node.mjs).
phaseFunction :: String -> String
phaseFunction (c : cs) = "step" ++ toUpper c : cs
phaseFunction [] = "step"
