// io/text_file.cpp — text output by the output rule (see text_file.h).
#include "io/text_file.h"

#include "io/output_file.h"

namespace fluidsound::io {

void writeTextFile(const std::filesystem::path& path, std::string_view text) {
  writeOutputFile(path, text);
}

void requireWritableFolder(const std::filesystem::path& path) { resolveOutput(path); }

}  // namespace fluidsound::io
