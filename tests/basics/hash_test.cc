// fnv1a (basics/hash.h): FNV-1a's published 64-bit test vectors for inputs shorter than a word
// (hashed byte by byte), every byte of a longer input changing the hash, a chain through the
// seed, and hex's zero padding.
#include <gtest/gtest.h>

#include <string>

#include "hash.h"

TEST(Fnv1a, PublishedVectors)
{
  EXPECT_EQ(pumpd::hex(pumpd::fnv1a("")), "cbf29ce484222325");
  EXPECT_EQ(pumpd::hex(pumpd::fnv1a("a")), "af63dc4c8601ec8c");
  EXPECT_EQ(pumpd::hex(pumpd::fnv1a("foobar")), "85944171f73967e8");
}

TEST(Fnv1a, EveryByteOfALongInputCounts)
{
  const std::string text = "Lipton's softening potential, horizon 4 mm";
  const auto        h    = pumpd::fnv1a(text);
  for (std::size_t i = 0; i < text.size(); ++i)
    {
      std::string changed = text;
      changed[i] ^= 1;
      EXPECT_NE(pumpd::fnv1a(changed), h) << "byte " << i;
    }
  EXPECT_EQ(pumpd::fnv1a(text), h);
}

TEST(Fnv1a, ChainsThroughItsSeed)
{
  EXPECT_NE(pumpd::fnv1a("b", pumpd::fnv1a("a")), pumpd::fnv1a("a", pumpd::fnv1a("b")));
  EXPECT_EQ(pumpd::fnv1a("b", pumpd::fnv1a("a")), pumpd::fnv1a("ab"));
}

TEST(Hex, SixteenDigits)
{
  EXPECT_EQ(pumpd::hex(1), "0000000000000001");
  EXPECT_EQ(pumpd::hex(0xfedcba9876543210ull), "fedcba9876543210");
}
