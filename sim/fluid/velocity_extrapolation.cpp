// sim/fluid/velocity_extrapolation.cpp — see velocity_extrapolation.h.
#include "sim/fluid/velocity_extrapolation.h"

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
          // Row pointers and steps to the six neighbours (those inside the grid), summed in the
          // order −x, +x, −y, +y, −z, +z.
          const std::size_t at = ok.offset(0, j, k);
          const std::ptrdiff_t sj = n[0], sk = static_cast<std::ptrdiff_t>(n[0]) * n[1];
          const float* const uRow = &u.values()[at];
          const std::uint8_t* const okRow = &ok.values()[at];
          const std::ptrdiff_t rowStep[4] = {-sj, sj, -sk, sk};
          const bool rowInside[4] = {j > 0, j + 1 < n[1], k > 0, k + 1 < n[2]};
          for (int i = 0; i < n[0]; ++i) {
            if (okRow[i]) continue;
            double sum = 0.0;
            int count = 0;
            if (i > 0 && okRow[i - 1]) sum += uRow[i - 1], ++count;
            if (i + 1 < n[0] && okRow[i + 1]) sum += uRow[i + 1], ++count;
            for (int r = 0; r < 4; ++r)
              if (rowInside[r] && okRow[i + rowStep[r]]) sum += uRow[i + rowStep[r]], ++count;
            if (count > 0) {
              u.values()[at + i] = static_cast<float>(sum / count);
              made[k].push_back(at + i);
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
