// io/library_versions.h — versions of the file-format libraries io/ was built with, for
// `fluidsound --version` and report.json.
#pragma once

#include <string>

namespace fluidsound::io {

/// One line per library ("  libsndfile 1.2.0"), each ending in a newline.
std::string libraryVersions();

}  // namespace fluidsound::io
