// io/file_kind.cpp — see file_kind.h.
#include "io/file_kind.h"

namespace fluidsound::io {

std::string fileKindName(std::filesystem::file_type type) {
  using std::filesystem::file_type;
  switch (type) {
    case file_type::regular:
      return "a regular file";
    case file_type::directory:
      return "a folder";
    case file_type::fifo:
      return "a FIFO";
    case file_type::character:
      return "a character device";
    case file_type::block:
      return "a block device";
    case file_type::socket:
      return "a socket";
    case file_type::symlink:
      return "a symbolic link";
    case file_type::not_found:
      return "no such file";
    default:
      return "not a regular file";
  }
}

}  // namespace fluidsound::io
