// io/memory_text.h — a size in memory as the errors about memory print it (the render and the
// solver's grid refused before they are allocated: tools/render_memory.h, tools/solver_memory.h).
#pragma once

#include <string>

namespace fluidsound::io {

/// @brief `bytes` in gibibytes (2^30 B) to one decimal, e.g. `35.8 GiB`, `250.0 GiB`.
std::string gibibytes(double bytes);

}  // namespace fluidsound::io
