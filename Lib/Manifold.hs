-- | Rigid-body physics on curved surfaces: the library's front door.
module Manifold
  ( module Manifold.Field
  , module Manifold.AD
  , module Manifold.Space
  , module Manifold.Spaces
  , module Manifold.Surface
  , module Manifold.Body
  ) where

import Manifold.AD
import Manifold.Body
import Manifold.Field
import Manifold.Space
import Manifold.Spaces
import Manifold.Surface
