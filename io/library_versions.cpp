// io/library_versions.cpp — see library_versions.h.
#include "io/library_versions.h"

#include <cairo.h>
#include <embree3/rtcore_config.h>
#include <oneapi/tbb/version.h>
#include <openvdb/version.h>
#include <sndfile.h>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "io/loudness.h"

namespace fluidsound::io {
namespace {

/// "1.2.0" from libsndfile's "libsndfile-1.2.0".
std::string sndfileVersion() {
  const std::string text = sf_version_string();
  const auto dash = text.rfind('-');
  return dash == std::string::npos ? text : text.substr(dash + 1);
}

std::string dotted(int major, int minor, int patch) {
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

}  // namespace

std::vector<std::pair<std::string, std::string>> libraryVersions() {
  return {
      {"openvdb", openvdb::getLibraryVersionString()},
      {"embree", RTC_VERSION_STRING},
      {"tbb", TBB_runtime_version()},
      {"eigen", dotted(EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
      {"libsndfile", sndfileVersion()},
      {"libebur128", io::loudnessLibraryVersion()},
      {"cairo", cairo_version_string()},
      {"nlohmann_json", dotted(NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR,
                               NLOHMANN_JSON_VERSION_PATCH)},
      // No version macro in its header: the version of its CMake package (io/CMakeLists.txt).
      {"tinyobjloader", FLUIDSOUND_TINYOBJLOADER_VERSION},
  };
}

}  // namespace fluidsound::io
