// Tests of io/memory_text.h: the sizes the memory errors print.
#include "io/memory_text.h"

#include <gtest/gtest.h>

namespace fluidsound::io {
namespace {

// Claim: bytes are printed in GiB (2^30 B) to one decimal, rounded to nearest. Reference: the
// sizes of the render and grid errors (docs/cli.md): 4.8e9 samples × 8 B = 35.8 GiB, 1024³ cells
// × 250 B = 250.0 GiB; 2^30 B exactly 1.0 GiB; 0.04 GiB rounds to 0.0, 0.06 up to 0.1.
TEST(MemoryText, GibibytesToOneDecimal) {
  EXPECT_EQ(gibibytes(4.8e9 * 8.0), "35.8 GiB");
  EXPECT_EQ(gibibytes(1024.0 * 1024.0 * 1024.0 * 250.0), "250.0 GiB");
  EXPECT_EQ(gibibytes(1024.0 * 1024.0 * 1024.0), "1.0 GiB");
  EXPECT_EQ(gibibytes(0.04 * 1024.0 * 1024.0 * 1024.0), "0.0 GiB");
  EXPECT_EQ(gibibytes(0.06 * 1024.0 * 1024.0 * 1024.0), "0.1 GiB");
  EXPECT_EQ(gibibytes(0.0), "0.0 GiB");
}

}  // namespace
}  // namespace fluidsound::io
