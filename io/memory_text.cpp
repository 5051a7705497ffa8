// io/memory_text.cpp — see memory_text.h.
#include "io/memory_text.h"

#include <cstdio>

namespace fluidsound::io {

std::string gibibytes(double bytes) {
  constexpr double kGibibyte = 1024.0 * 1024.0 * 1024.0;  // [B]
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", bytes / kGibibyte);
  return text;
}

}  // namespace fluidsound::io
