// tests/support/file_bytes.h — a file's whole content as bytes (empty if it cannot be read), for
// tests that compare outputs byte for byte or parse them.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace fluidsound::test {

inline std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace fluidsound::test
