-- | The documentation's worked example of adding a space (docs/spaces.md,
-- "Adding a space"); the lines between the markers stand there as they are
-- here ("ReadmeExampleSpec").
module Bowl (bowl) where

import Linear.V3 (V3 (..))

import Manifold

-- README: from here
bowl :: Space
bowl = (space "bowl" "the paraboloid y = x² + z², up to y = 1" (scalarFn bowlField))
  { spaceBoundary = Just (scalarFn (\(V3 _ y _) -> 1 - y))
  , spaceGravity  = uniformGravity (V3 0 (-4) 0)
  , spaceScene    = [Placement (V3 0.3 0.1 0) SquareShape 0.15 False]
  }
  where
    -- a field, not a distance: the engine only needs f/|∇f| near the surface
    bowlField (V3 x y z) = (x * x + z * z - y) / sqrt (1 + 4 * (x * x + z * z))
-- README: to here
