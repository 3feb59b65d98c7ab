-- | Every catalogue space's compiled step ("Manifold.Compile"): a module
-- each, so that they compile in parallel. A space added to the catalogue
-- gets a module like these (two imports and a splice), listed in
-- Manifold.cabal's exposed-modules and here; a test fails for a catalogue
-- space without one.
module Manifold.Compiled (compiledSteps) where

import Manifold.Compiled.Runtime (CompiledStep)
import qualified Manifold.Compiled.Bolza as Bolza
import qualified Manifold.Compiled.Cube as Cube
import qualified Manifold.Compiled.Disc as Disc
import qualified Manifold.Compiled.FlatKlein as FlatKlein
import qualified Manifold.Compiled.FlatTorus as FlatTorus
import qualified Manifold.Compiled.Funnel as Funnel
import qualified Manifold.Compiled.HyperbolicPlane as HyperbolicPlane
import qualified Manifold.Compiled.Hemisphere as Hemisphere
import qualified Manifold.Compiled.KleinBottle as KleinBottle
import qualified Manifold.Compiled.Moebius as Moebius
import qualified Manifold.Compiled.Plane as Plane
import qualified Manifold.Compiled.ProjectivePlane as ProjectivePlane
import qualified Manifold.Compiled.Rectangle as Rectangle
import qualified Manifold.Compiled.Sphere as Sphere
import qualified Manifold.Compiled.Torus as Torus
import qualified Manifold.Compiled.Trumpet as Trumpet

-- | The compiled steps, in catalogue order.
compiledSteps :: [CompiledStep]
compiledSteps =
  [ Plane.compiled, Sphere.compiled, Torus.compiled, Trumpet.compiled, Cube.compiled
  , Hemisphere.compiled, Disc.compiled, Rectangle.compiled, ProjectivePlane.compiled
  , KleinBottle.compiled, Moebius.compiled, Funnel.compiled, FlatTorus.compiled, FlatKlein.compiled
  , HyperbolicPlane.compiled, Bolza.compiled ]
