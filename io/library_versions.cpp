// io/library_versions.cpp — see library_versions.h.
#include "io/library_versions.h"

#include <cairo.h>
#include <sndfile.h>

#include <nlohmann/json.hpp>

namespace fluidsound::io {

std::string libraryVersions() {
  return std::string("  ") + sf_version_string() + "\n" + "  cairo " + cairo_version_string() + "\n" +
         "  nlohmann-json " + std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
         std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." + std::to_string(NLOHMANN_JSON_VERSION_PATCH) +
         "\n";
}

}  // namespace fluidsound::io
