#include <gtest/gtest.h>
TEST(Placeholder, WrittenByHelper) { GTEST_SKIP(); }
