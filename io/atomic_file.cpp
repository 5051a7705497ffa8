// io/atomic_file.cpp — temporary file beside the target, renamed onto it on commit().
#include "io/atomic_file.h"

#include <unistd.h>  // getpid

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <system_error>
#include <utility>

#include "io/input_error.h"
#include "io/output_file.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

/// Attempts at a fresh temporary name before giving up; a collision of two 64-bit random suffixes
/// is already astronomically unlikely, so more than one retry means something else is wrong.
constexpr int kMaxNameAttempts = 8;

/// `TARGET: cannot write: REASON`, the one-line form of every OutputError of this file.
OutputError cannotWrite(const fs::path& target, const std::string& reason) {
  return OutputError(target.string() + ": cannot write: " + reason);
}

/// A 64-bit suffix that differs between objects, calls and processes without any global state:
/// std::random_device when it works, mixed with the object's address and the clock.
std::uint64_t uniqueSuffix(const void* owner) {
  std::uint64_t bits = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(owner));
  bits ^= static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  try {
    std::random_device entropy;
    bits ^= (static_cast<std::uint64_t>(entropy()) << 32) ^ static_cast<std::uint64_t>(entropy());
  } catch (const std::exception&) {
    // No entropy source: address and clock still separate this object from any other.
  }
  // splitmix64 finaliser: spreads the bits, so similar inputs give unrelated names.
  bits ^= bits >> 30;
  bits *= 0xbf58476d1ce4e5b9ULL;
  bits ^= bits >> 27;
  bits *= 0x94d049bb133111ebULL;
  bits ^= bits >> 31;
  return bits;
}

std::string hex(std::uint64_t value) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string text(16, '0');
  for (int i = 15; i >= 0; --i, value >>= 4)
    text[static_cast<std::size_t>(i)] = kDigits[value & 0xf];
  return text;
}

}  // namespace

AtomicFile::AtomicFile(fs::path target) : shown_(std::move(target)) {
  // The output rule (output_file.h): only a regular file or a new name is replaced; a symlink's
  // regular target is replaced in its own folder and the link stays.
  const OutputTarget resolved = resolveOutput(shown_);
  if (resolved.kind != OutputKind::Replace)
    throw cannotWrite(shown_,
                      "a device, a FIFO or standard output is written through, not replaced");
  target_ = resolved.file;
  const fs::path folder = target_.parent_path();
  const fs::path shownFolder = folder.empty() ? fs::path(".") : folder;

  // Creating the temporary file now (exclusively, "x") is the real test that the folder is
  // writable, and reserves the name. fopen gives the usual permissions (0666 minus umask).
  // Built by append: g++ 12 warns falsely (-Wrestrict, GCC bug 105329) on "literal" + string&&.
  std::string prefix(1, '.');
  prefix.append(target_.filename().string()).append(".tmp-").append(std::to_string(::getpid())).append("-");
  for (int attempt = 0; attempt < kMaxNameAttempts; ++attempt) {
    const fs::path candidate = folder / (prefix + hex(uniqueSuffix(this)));
    if (std::FILE* file = std::fopen(candidate.c_str(), "wx")) {
      std::fclose(file);
      temporary_ = candidate;
      registration_ = std::make_unique<TemporaryRegistration>(temporary_);
      return;
    }
    const int error = errno;
    if (error != EEXIST) {
      throw cannotWrite(shown_, "cannot create a file in folder '" + shownFolder.string() +
                                    "': " + std::generic_category().message(error));
    }
  }
  throw cannotWrite(shown_, "no unused temporary name in folder '" + shownFolder.string() + "'");
}

AtomicFile::~AtomicFile() {
  if (!committed_ && !temporary_.empty()) {
    std::error_code ignored;  // a destructor never throws; a leftover temporary is hidden (".")
    fs::remove(temporary_, ignored);
  }
  // registration_ ends after the removal, so a second signal in between still removes it.
}

void AtomicFile::commit() {
  if (committed_) return;
  std::error_code ec;
  fs::rename(temporary_, target_, ec);
  if (ec) throw cannotWrite(shown_, "renaming the temporary file failed: " + ec.message());
  committed_ = true;
}

}  // namespace fluidsound::io
