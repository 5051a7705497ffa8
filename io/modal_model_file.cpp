// io/modal_model_file.cpp — see modal_model_file.h.
#include "io/modal_model_file.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>
#include <type_traits>
#include <vector>

#include "io/atomic_file.h"
#include "io/file_digest.h"
#include "io/input_error.h"

namespace fluidsound::io {
namespace {

constexpr std::string_view kMagic = "fluidsound.modes/1\n";

class Writer {
 public:
  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void put(const Eigen::Vector3d& v) {
    for (int a = 0; a < 3; ++a) put(v[a]);
  }
  template <typename T>
  void putVector(const std::vector<T>& values) {
    put<std::uint64_t>(values.size());
    for (const T& v : values) put(v);
  }
  std::string bytes;
};

class Reader {
 public:
  explicit Reader(std::string_view bytes) : rest_(bytes) {}
  template <typename T>
  bool get(T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (rest_.size() < sizeof(T)) return false;
    std::memcpy(&value, rest_.data(), sizeof(T));
    rest_.remove_prefix(sizeof(T));
    return true;
  }
  bool get(Eigen::Vector3d& v) { return get(v[0]) && get(v[1]) && get(v[2]); }
  template <typename T>
  bool getVector(std::vector<T>& values) {
    std::uint64_t count = 0;
    if (!get(count) || count > rest_.size() / std::min<std::size_t>(sizeof(T), 8)) return false;
    values.resize(count);
    for (T& v : values)
      if (!get(v)) return false;
    return true;
  }
  bool atEnd() const { return rest_.empty(); }
  bool skip(std::string_view expected) {
    if (rest_.substr(0, expected.size()) != expected) return false;
    rest_.remove_prefix(expected.size());
    return true;
  }

 private:
  std::string_view rest_;
};

}  // namespace

std::uint64_t modalCacheKey(const std::filesystem::path& mesh, std::string_view settings) {
  const std::optional<FileDigest> digest = digestOfFile(mesh);
  if (!digest) throw InputError(mesh.string(), "", "a readable mesh file", "a file that cannot be read");
  return fnv1a64(kMagic, fnv1a64(settings, digest->fnv1a));
}

std::uint64_t modalCacheKey(std::string_view settings) { return fnv1a64(kMagic, fnv1a64(settings)); }

std::filesystem::path modalCacheFile(const std::filesystem::path& folder, std::uint64_t key) {
  return folder / (hexDigits(key) + ".modes");
}

std::string encodeModalModel(const acoustics::ModalModel& model, std::uint64_t key) {
  Writer w;
  w.bytes.append(kMagic);
  w.put(key);
  w.putVector(model.frequency);
  w.putVector(model.decayRate);
  w.putVector(model.dampedFrequency);
  w.putVector(model.surfaceNodes);
  w.putVector(model.surfacePositions);
  w.putVector(model.surfaceFaces);
  w.put(model.voxelSize);
  w.put<std::int64_t>(model.surfaceShapes.rows());
  w.put<std::int64_t>(model.surfaceShapes.cols());
  w.bytes.append(reinterpret_cast<const char*>(model.surfaceShapes.data()),
                 sizeof(float) * static_cast<std::size_t>(model.surfaceShapes.size()));
  w.put(model.dofCount);
  w.put(model.rigidModesDropped);
  w.putVector(model.rigidFrequencies);
  w.put(model.operations);
  return std::move(w.bytes);
}

std::optional<acoustics::ModalModel> decodeModalModel(std::string_view bytes, std::uint64_t key) {
  Reader r(bytes);
  acoustics::ModalModel m;
  std::uint64_t stored = 0;
  std::int64_t rows = 0, cols = 0;
  if (!r.skip(kMagic) || !r.get(stored) || stored != key || !r.getVector(m.frequency) || !r.getVector(m.decayRate) ||
      !r.getVector(m.dampedFrequency) || !r.getVector(m.surfaceNodes) || !r.getVector(m.surfacePositions) ||
      !r.getVector(m.surfaceFaces) || !r.get(m.voxelSize) || !r.get(rows) || !r.get(cols))
    return std::nullopt;
  const std::size_t modes = m.frequency.size();
  if (m.decayRate.size() != modes || m.dampedFrequency.size() != modes || m.surfacePositions.size() != m.surfaceNodes.size() ||
      rows != 3 * static_cast<std::int64_t>(m.surfaceNodes.size()) || cols != static_cast<std::int64_t>(modes))
    return std::nullopt;
  m.surfaceShapes.resize(rows, cols);
  for (Eigen::Index i = 0; i < m.surfaceShapes.size(); ++i)
    if (!r.get(m.surfaceShapes.data()[i])) return std::nullopt;
  if (!r.get(m.dofCount) || !r.get(m.rigidModesDropped) || !r.getVector(m.rigidFrequencies) || !r.get(m.operations) ||
      !r.atEnd())
    return std::nullopt;
  for (const acoustics::SurfaceFace& face : m.surfaceFaces)
    for (int node : face.nodes)
      if (node < 0 || static_cast<std::size_t>(node) >= m.surfaceNodes.size()) return std::nullopt;
  return m;
}

std::optional<acoustics::ModalModel> readCachedModes(const std::filesystem::path& folder, std::uint64_t key) {
  const std::filesystem::path file = modalCacheFile(folder, key);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in && !in.eof()) return std::nullopt;
  return decodeModalModel(bytes.str(), key);
}

std::optional<std::string> writeCachedModes(const std::filesystem::path& folder, std::uint64_t key,
                                            const acoustics::ModalModel& model) {
  const std::filesystem::path file = modalCacheFile(folder, key);
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) return folder.string() + ": cannot be made (" + ec.message() + ")";
  const auto status = std::filesystem::symlink_status(file, ec);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    return file.string() + " is not a regular file: left alone";
  try {
    AtomicFile out(file);
    {
      std::ofstream bytes(out.temporaryPath(), std::ios::binary);
      const std::string encoded = encodeModalModel(model, key);
      bytes.write(encoded.data(), static_cast<std::streamsize>(encoded.size()));
      if (!bytes.flush()) return file.string() + ": cannot be written";
    }
    out.commit();
  } catch (const OutputError& e) {
    return std::string(e.what());
  }
  return std::nullopt;
}

}  // namespace fluidsound::io
