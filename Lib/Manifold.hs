-- | Rigid-body physics on curved surfaces: the library's front door. It
-- holds the scalar class, automatic differentiation, what a space is, the
-- catalogue of spaces, the geometry of a surface and bodies' shapes;
-- "Manifold.Engine" runs a world natively, "Manifold.Scene" reads and
-- writes scenes.
--
-- The unit sphere has Gaussian curvature 1 everywhere, and its field
-- grows by 1 a unit away from it:
--
-- >>> import Linear.V3 (V3 (..))
-- >>> gaussianCurvature (spaceField sphere) (V3 0 0 1 :: V3 Double)
-- 1.0
-- >>> evalField sphere (V3 0 2 0)
-- 1.0
module Manifold
  ( module Manifold.Field
  , module Manifold.AD
  , module Manifold.Metric
  , module Manifold.Space
  , module Manifold.Spaces
  , module Manifold.Surface
  , module Manifold.Body
  ) where

import Manifold.AD
import Manifold.Body
import Manifold.Field
import Manifold.Metric
import Manifold.Space
import Manifold.Spaces
import Manifold.Surface
