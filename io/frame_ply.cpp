// io/frame_ply.cpp — frames/NNNN.ply (see frame_files.h).
#include <bit>
#include <cstdint>
#include <limits>
#include <cstring>
#include <sstream>
#include <string>

#include "io/frame_files.h"
#include "io/input_error.h"
#include "io/output_file.h"

namespace fluidsound::io {

void writeParticlesPly(const std::filesystem::path& path, const sim::Particles& particles) {
  static_assert(std::endian::native == std::endian::little, "PLY is written as the host's little-endian floats");
  std::ostringstream file;
  {
    file << "ply\nformat binary_little_endian 1.0\ncomment fluidsound particles, SI units\n"
         << "element vertex " << particles.size() << "\n"
         << "property float x\nproperty float y\nproperty float z\n"
         << "property float vx\nproperty float vy\nproperty float vz\nproperty uint id\nend_header\n";
    constexpr std::size_t kVertexBytes = 6 * sizeof(float) + sizeof(std::uint32_t);
    std::string block;
    block.resize(particles.size() * kVertexBytes);
    char* at = block.data();
    for (std::size_t p = 0; p < particles.size(); ++p) {
      std::memcpy(at, particles.position[p].data(), 3 * sizeof(float));
      std::memcpy(at + 3 * sizeof(float), particles.velocity[p].data(), 3 * sizeof(float));
      // PLY has no 64-bit integer: ids are numbered from 0 in creation order, far below 2³².
      const std::uint64_t id = p < particles.id.size() ? particles.id[p] : sim::kUnassignedParticleId;
      if (id > std::numeric_limits<std::uint32_t>::max())
        throw OutputError(path.string() + ": particle " + std::to_string(p) + " has no id a PLY uint holds (" +
                          std::to_string(id) + ")");
      const auto id32 = static_cast<std::uint32_t>(id);
      std::memcpy(at + 6 * sizeof(float), &id32, sizeof id32);
      at += kVertexBytes;
    }
    file.write(block.data(), static_cast<std::streamsize>(block.size()));
  }
  writeOutputFile(path, file.str());  // the output rule (output_file.h)
}

}  // namespace fluidsound::io
