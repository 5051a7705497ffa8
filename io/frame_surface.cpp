// io/frame_surface.cpp — see frame_surface.h. The only file of the transfer stage that includes
// OpenVDB (compile time; toolchain.md).
#include "io/frame_surface.h"

#include <cmath>
#include <new>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>

#include "io/frame_folder.h"
#include "io/input_error.h"
#include "io/vdb_file_check.h"

namespace fluidsound::io {

struct FrameSurface::Grid {
  openvdb::FloatGrid::Ptr grid;
  double background = 0.0;  ///< |φ| outside the band [m]
  double voxel = 0.0;       ///< [m]
};

FrameSurface::FrameSurface(const std::filesystem::path& path) : grid_(std::make_unique<Grid>()) {
  openvdb::initialize();
  if (!std::filesystem::is_regular_file(path))
    throw InputError(path.string(), "", "a frame file written by fluidsound simulate", "no such file");
  requireIntactVdbFile(path);  // OpenVDB trusts the lengths in the file (vdb_file_check.h)
  try {
    openvdb::io::File file(path.string());
    file.open(/*delayLoad=*/false);  // read in full now, in the order requireIntactVdbFile checked
    openvdb::GridBase::Ptr base = file.hasGrid("surface") ? file.readGrid("surface") : nullptr;
    file.close();
    grid_->grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
  } catch (const openvdb::Exception& e) {
    throw InputError(path.string(), "", "an OpenVDB file", std::string("an unreadable file (") + e.what() + ")");
  } catch (const std::exception& e) {  // a damaged tree: a length read as a huge allocation, a short read
    throw InputError(path.string(), "", "an intact OpenVDB file", std::string("a damaged file (") + e.what() + ")");
  }
  if (!grid_->grid) throw InputError(path.string(), "surface", "a FloatGrid named surface", "none");
  grid_->background = std::abs(grid_->grid->background());
  grid_->voxel = grid_->grid->voxelSize()[0];
}

FrameSurface::~FrameSurface() = default;
FrameSurface::FrameSurface(FrameSurface&&) noexcept = default;
FrameSurface& FrameSurface::operator=(FrameSurface&&) noexcept = default;

acoustics::LocalSurface FrameSurface::surfaceAbove(const Vec3& centre, double depth,
                                                   const Vec3& up) const {
  const acoustics::LocalSurface flat{{centre[0] + depth * up[0], centre[1] + depth * up[1], centre[2] + depth * up[2]},
                                     up, depth};
  openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sample(*grid_->grid);
  const auto phi = [&](const Vec3& x) { return double(sample.wsSample(openvdb::Vec3d(x[0], x[1], x[2]))); };
  const Vec3& p = flat.point;
  const double value = phi(p);
  if (std::abs(value) >= 0.99 * grid_->background) return flat;  // beyond the band
  Vec3 gradient{};
  double norm2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    Vec3 plus = p, minus = p;
    plus[a] += grid_->voxel, minus[a] -= grid_->voxel;
    gradient[a] = (phi(plus) - phi(minus)) / (2.0 * grid_->voxel);
    norm2 += gradient[a] * gradient[a];
  }
  if (norm2 < 0.25) return flat;
  const double norm = std::sqrt(norm2);
  acoustics::LocalSurface s;
  double h = 0.0;
  for (int a = 0; a < 3; ++a) {
    s.normal[a] = gradient[a] / norm;
    s.point[a] = p[a] - value * s.normal[a];
  }
  for (int a = 0; a < 3; ++a) h += (s.point[a] - centre[a]) * s.normal[a];
  if (!(h > 0.0)) return flat;
  s.depth = h;
  // The plane through the surface point; the bubble sits h below it along the normal.
  for (int a = 0; a < 3; ++a) s.point[a] = centre[a] + h * s.normal[a];
  return s;
}

std::unique_ptr<acoustics::FrameSurface> FrameFolderSurfaces::open(int frame) const {
  return std::make_unique<FrameSurface>(outdir_ / "frames" / frameFileName(frame, "vdb"));
}

}  // namespace fluidsound::io
