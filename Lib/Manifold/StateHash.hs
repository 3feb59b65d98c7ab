{-# LANGUAGE RankNTypes #-}
-- | A run's fingerprint: the 64-bit FNV-1a hash of the world's state, which
-- the native engine ('Manifold.Engine.stateHash', @manifold sim --hash@)
-- and the page's (@window.manifold.hash()@) compute over the same numbers,
-- so that two runs that differ in one bit of one body give other hashes.
--
-- The state hashed is, in this order: every body's position, velocity,
-- carried axis, normal and scalars (angle, angular velocity, masses, size,
-- …; see 'Manifold.World.Slot'), then every contact row of the last step
-- (its bodies, key, rows, depth and impulses; see
-- 'Manifold.World.ContactField'). Each number goes in as the eight bytes
-- of its IEEE 754 bit pattern, least significant first, and −0 as 0: the
-- staged code folds @0·x@ to 0 where the native step may compute −0, and
-- the two compare equal and change no later number but by a division by
-- that zero, which the engine does not do.
module Manifold.StateHash
  ( HashedPart (..)
  , hashedParts
  , fnv1a64
  , showHash
  ) where

import Data.Bits (shiftR, xor, (.&.))
import Data.List (foldl')
import Data.Word (Word64)
import GHC.Float (castDoubleToWord64)
import Numeric (showHex)

import Manifold.World

-- | One array of the state: its rows (as many as the counter says: bodies
-- or contacts) of @stride@ numbers each, from the array's start.
data HashedPart = HashedPart
  { hashedArray :: forall a. WorldArrays a -> a
  , hashedRows :: Meta -- ^ 'BodyCount' or 'ContactCount'
  , hashedStride :: Int
  }

-- | The arrays hashed, in order.
hashedParts :: [HashedPart]
hashedParts =
  [ HashedPart wPos BodyCount 3
  , HashedPart wVel BodyCount 3
  , HashedPart wAxis BodyCount 3
  , HashedPart wNormal BodyCount 3
  , HashedPart wScalars BodyCount scalarSlots
  , HashedPart wContacts ContactCount contactStride
  , HashedPart wJoints JointCount jointStride
  ]

-- | FNV-1a, 64 bits, over the bytes of the numbers' bit patterns (least
-- significant byte first; −0 as 0).
--
-- >>> fnv1a64 [-0] == fnv1a64 [0]
-- True
--
-- >>> showHash (fnv1a64 [])
-- "cbf29ce484222325"
-- >>> showHash (fnv1a64 [1])
-- "aab1693229ba1db8"
fnv1a64 :: [Double] -> Word64
fnv1a64 = foldl' number offsetBasis
  where
    offsetBasis = 0xcbf29ce484222325
    prime = 0x100000001b3
    number h x = let w = castDoubleToWord64 (if x == 0 then 0 else x)
                 in foldl' (\acc k -> (acc `xor` ((w `shiftR` (8 * k)) .&. 0xff)) * prime) h [0 .. 7]

-- | A hash as the 16 hexadecimal digits both engines print.
showHash :: Word64 -> String
showHash h = let s = showHex h "" in replicate (16 - length s) '0' ++ s
