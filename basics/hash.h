// Content hashes: FNV-1a (64 bit) of bytes, chained through its seed, and its hex text. What makes
// a study's run, or a .geo meshed before, the same as the one asked for.
#pragma once

#include <cstdint>
#include <string>

namespace pumpd
{
  /// FNV-1a's offset basis: the seed of a hash that starts a chain.
  constexpr std::uint64_t fnv1a_offset = 14695981039346656037ull;

  /// FNV-1a over 8-byte words (the tail byte by byte), continuing from `seed`: a change of any
  /// byte changes the hash but for chance collisions, at a word per multiplication (fast on
  /// files of tens of MB).
  std::uint64_t fnv1a(const std::string &bytes, std::uint64_t seed = fnv1a_offset);

  /// `h` as 16 hex digits.
  std::string hex(std::uint64_t h);
} // namespace pumpd
