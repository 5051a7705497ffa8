// io/library_versions.h — versions of the libraries fluidsound links, for `fluidsound --version`
// and the `versions` object of report.json.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace fluidsound::io {

/// @brief (name, version) of every library linked except CLI11 (tools/ adds it: only the
///        executable links it), in a fixed order: "openvdb", "embree", "tbb", "eigen",
///        "libsndfile", "libebur128", "cairo", "nlohmann_json", "tinyobjloader". Shared libraries
///        report the version that runs (their version functions: TBB, libsndfile, libebur128,
///        cairo), header-only and statically versioned ones the version built with (macros).
std::vector<std::pair<std::string, std::string>> libraryVersions();

}  // namespace fluidsound::io
