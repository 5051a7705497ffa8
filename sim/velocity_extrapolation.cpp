// sim/velocity_extrapolation.cpp — see velocity_extrapolation.h.
#include "sim/velocity_extrapolation.h"

#include <vector>

#include <tbb/parallel_for.h>

namespace fluidsound::sim {

void extrapolateVelocity(MacVelocity& velocity, FaceMask valid, int layers) {
  for (int a = 0; a < 3; ++a) {
    Array3f& u = velocity[a];
    Array3<std::uint8_t>& ok = valid[a];
    const Index3 n = u.size();
    // Valid faces per row (j, k) of faces: only rows with invalid faces next to a row holding
    // valid ones can change, so a layer visits the band around the liquid, not the whole grid.
    std::vector<int> rowValid(static_cast<std::size_t>(n[1]) * n[2], 0);
    tbb::parallel_for(0, n[2], [&](int k) {
      for (int j = 0; j < n[1]; ++j) {
        int count = 0;
        for (int i = 0; i < n[0]; ++i) count += ok(i, j, k) != 0;
        rowValid[static_cast<std::size_t>(k) * n[1] + j] = count;
      }
    });
    const auto row = [&](int j, int k) { return rowValid[static_cast<std::size_t>(k) * n[1] + j]; };
    // Faces made valid by a layer, per plane k; marked only after the layer, so that the layer
    // reads the previous round's mask, and the faces it reads (valid before it) never change.
    std::vector<std::vector<std::size_t>> made(n[2]);
    for (int layer = 0; layer < layers; ++layer) {
      tbb::parallel_for(0, n[2], [&](int k) {
        made[k].clear();
        for (int j = 0; j < n[1]; ++j) {
          const int here = row(j, k);
          if (here == n[0]) continue;  // all valid
          const bool near = here > 0 || (j > 0 && row(j - 1, k) > 0) || (j + 1 < n[1] && row(j + 1, k) > 0) ||
                            (k > 0 && row(j, k - 1) > 0) || (k + 1 < n[2] && row(j, k + 1) > 0);
          if (!near) continue;
          for (int i = 0; i < n[0]; ++i) {
            if (ok(i, j, k)) continue;
            double sum = 0.0;
            int count = 0;
            const int offsets[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
            for (const auto& o : offsets) {
              const int x = i + o[0], y = j + o[1], z = k + o[2];
              if (ok.contains(x, y, z) && ok(x, y, z)) {
                sum += u(x, y, z);
                ++count;
              }
            }
            if (count > 0) {
              u(i, j, k) = static_cast<float>(sum / count);
              made[k].push_back(ok.offset(i, j, k));
            }
          }
        }
      });
      tbb::parallel_for(0, n[2], [&](int k) {
        for (const std::size_t f : made[k]) {
          ok.values()[f] = 1;
          ++rowValid[f / n[0]];
        }
      });
    }
  }
}

}  // namespace fluidsound::sim
