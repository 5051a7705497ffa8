// tests/support/special_files.h — device nodes, FIFOs and sockets made inside a test's temporary
// folder (never the system's /dev): a node with the major/minor numbers of /dev/null (1, 3) or
// /dev/full (1, 7) behaves as they do, wherever it is.
#pragma once

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include "support/file_bytes.h"

namespace fluidsound::test {

/// Linux's memory devices (Documentation/admin-guide/devices.txt): 1,3 null; 1,7 full.
inline constexpr unsigned kMemoryMajor = 1, kNullMinor = 3, kFullMinor = 7;

/// @return true if a character device (major, minor) was made at `path` (needs CAP_MKNOD)
inline bool makeCharacterDevice(const std::filesystem::path& path, unsigned major, unsigned minor) {
  return ::mknod(path.c_str(), S_IFCHR | 0666, makedev(major, minor)) == 0;
}

/// @return true if a block device node was made (7,0: the first loop device); it is never opened
inline bool makeBlockDevice(const std::filesystem::path& path) {
  return ::mknod(path.c_str(), S_IFBLK | 0600, makedev(7, 0)) == 0;
}

inline bool makeFifo(const std::filesystem::path& path) { return ::mkfifo(path.c_str(), 0600) == 0; }

/// A bound Unix socket at `path`, closed again (the socket file stays).
inline bool makeSocketFile(const std::filesystem::path& path) {
  const int descriptor = ::socket(AF_UNIX, SOCK_STREAM, 0);
  if (descriptor < 0) return false;
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  const std::string text = path.string();
  if (text.size() >= sizeof address.sun_path) return ::close(descriptor), false;
  std::memcpy(address.sun_path, text.c_str(), text.size() + 1);
  const bool bound = ::bind(descriptor, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  ::close(descriptor);
  return bound;
}

/// Reads a FIFO to its end on a thread (a writer's open blocks until a reader is there).
class FifoReader {
 public:
  explicit FifoReader(std::filesystem::path fifo)
      : thread_([this, fifo] {
          std::ifstream in(fifo, std::ios::binary);
          bytes_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        }) {}
  ~FifoReader() {
    if (thread_.joinable()) thread_.join();
  }
  FifoReader(const FifoReader&) = delete;
  FifoReader& operator=(const FifoReader&) = delete;

  /// Waits for the writer to close the FIFO, then returns what was read.
  const std::string& bytes() {
    if (thread_.joinable()) thread_.join();
    return bytes_;
  }

 private:
  std::string bytes_;
  std::thread thread_;
};

}  // namespace fluidsound::test
