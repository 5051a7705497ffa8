// io/frame_surface.cpp — see frame_surface.h. The only file of the transfer stage's input that
// includes OpenVDB (compile time; toolchain.md).
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

struct FrameLevelSet::Grid {
  openvdb::FloatGrid::Ptr grid;
  double background = 0.0;  ///< |φ| outside the band [m]
  double voxel = 0.0;       ///< [m]
};

FrameLevelSet::FrameLevelSet(const std::filesystem::path& path) : grid_(std::make_unique<Grid>()) {
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

FrameLevelSet::~FrameLevelSet() = default;
FrameLevelSet::FrameLevelSet(FrameLevelSet&&) noexcept = default;
FrameLevelSet& FrameLevelSet::operator=(FrameLevelSet&&) noexcept = default;

double FrameLevelSet::phi(const Vec3& x) const {
  const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sample(
      *grid_->grid);
  return double(sample.wsSample(openvdb::Vec3d(x[0], x[1], x[2])));
}

double FrameLevelSet::bandHalfWidth() const { return grid_->background; }

double FrameLevelSet::voxelSize() const { return grid_->voxel; }

std::unique_ptr<const acoustics::LevelSetSampler> FrameFolderLevelSets::open(int frame) const {
  return std::make_unique<FrameLevelSet>(outdir_ / "frames" / frameFileName(frame, "vdb"));
}

}  // namespace fluidsound::io
