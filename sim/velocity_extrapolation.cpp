// sim/velocity_extrapolation.cpp — see velocity_extrapolation.h.
#include "sim/velocity_extrapolation.h"

#include <tbb/parallel_for.h>

namespace fluidsound::sim {

void extrapolateVelocity(MacVelocity& velocity, FaceMask valid, int layers) {
  for (int a = 0; a < 3; ++a) {
    Array3f& u = velocity[a];
    Array3<std::uint8_t>& ok = valid[a];
    const Index3 n = u.size();
    for (int layer = 0; layer < layers; ++layer) {
      const Array3f previous = u;
      const Array3<std::uint8_t> was = ok;
      tbb::parallel_for(0, n[2], [&](int k) {
        for (int j = 0; j < n[1]; ++j)
          for (int i = 0; i < n[0]; ++i) {
            if (was(i, j, k)) continue;
            double sum = 0.0;
            int count = 0;
            const int offsets[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
            for (const auto& o : offsets) {
              const int x = i + o[0], y = j + o[1], z = k + o[2];
              if (was.contains(x, y, z) && was(x, y, z)) {
                sum += previous(x, y, z);
                ++count;
              }
            }
            if (count > 0) {
              u(i, j, k) = static_cast<float>(sum / count);
              ok(i, j, k) = 1;
            }
          }
      });
    }
  }
}

}  // namespace fluidsound::sim
