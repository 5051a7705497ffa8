// io/frame_ply.cpp — frames/NNNN.ply (see frame_files.h).
#include <bit>
#include <cstring>
#include <sstream>
#include <string>

#include "io/frame_files.h"
#include "io/output_file.h"

namespace fluidsound::io {

void writeParticlesPly(const std::filesystem::path& path, const sim::Particles& particles) {
  static_assert(std::endian::native == std::endian::little, "PLY is written as the host's little-endian floats");
  std::ostringstream file;
  {
    file << "ply\nformat binary_little_endian 1.0\ncomment fluidsound particles, SI units\n"
         << "element vertex " << particles.size() << "\n"
         << "property float x\nproperty float y\nproperty float z\n"
         << "property float vx\nproperty float vy\nproperty float vz\nend_header\n";
    std::string block;
    block.resize(particles.size() * 6 * sizeof(float));
    char* at = block.data();
    for (std::size_t p = 0; p < particles.size(); ++p) {
      std::memcpy(at, particles.position[p].data(), 3 * sizeof(float));
      std::memcpy(at + 3 * sizeof(float), particles.velocity[p].data(), 3 * sizeof(float));
      at += 6 * sizeof(float);
    }
    file.write(block.data(), static_cast<std::streamsize>(block.size()));
  }
  writeOutputFile(path, file.str());  // the output rule (output_file.h)
}

}  // namespace fluidsound::io
