// io/cache_frame_reader.cpp — see cache_frame_reader.h.
#include "io/cache_frame_reader.h"

#include <algorithm>
#include <limits>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>

#include "io/input_error.h"

namespace fluidsound::io {

Vec3 fromCacheAxes(const Vec3& v, UpAxis up) { return up == UpAxis::Y ? v : Vec3{v[0], v[2], -v[1]}; }

Vec3 toCacheAxes(const Vec3& v, UpAxis up) { return up == UpAxis::Y ? v : Vec3{v[0], -v[2], v[1]}; }

struct CacheFrameReader::Grids {
  openvdb::FloatGrid::Ptr surface;
  openvdb::Vec3SGrid::Ptr velocity;  // a double grid is read as floats
};

CacheFrameReader::CacheFrameReader(const std::filesystem::path& path, const CacheGridNames& names,
                                   double metresPerUnit, UpAxis up)
    : grids_(std::make_unique<Grids>()), scale_(metresPerUnit), up_(up) {
  const CacheFrameGrids found = checkCacheFrame(path, names);
  openvdb::io::File file(path.string());
  file.open(/*delayLoad=*/false);
  grids_->surface = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(found.surface));
  const openvdb::GridBase::Ptr velocity = file.readGrid(found.velocity);
  file.close();
  if (auto single = openvdb::gridPtrCast<openvdb::Vec3SGrid>(velocity)) {
    grids_->velocity = single;
  } else {  // checkCacheFrame allows Vec3 doubles: the same values as floats
    const auto twice = openvdb::gridPtrCast<openvdb::Vec3DGrid>(velocity);
    grids_->velocity = openvdb::Vec3SGrid::create(openvdb::Vec3s(twice->background()));
    grids_->velocity->setTransform(twice->transform().copy());
    auto out = grids_->velocity->getAccessor();
    for (auto it = twice->cbeginValueOn(); it; ++it) out.setValue(it.getCoord(), openvdb::Vec3s(*it));
  }
}

CacheFrameReader::~CacheFrameReader() = default;
CacheFrameReader::CacheFrameReader(CacheFrameReader&&) noexcept = default;
CacheFrameReader& CacheFrameReader::operator=(CacheFrameReader&&) noexcept = default;

double CacheFrameReader::phi(const Vec3& x) const {
  const Vec3 c = toCacheAxes(x, up_);
  const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sample(*grids_->surface);
  return scale_ * static_cast<double>(sample.wsSample(openvdb::Vec3d(c[0] / scale_, c[1] / scale_, c[2] / scale_)));
}

Vec3 CacheFrameReader::velocity(const Vec3& x) const {
  const Vec3 c = toCacheAxes(x, up_);
  const openvdb::tools::GridSampler<openvdb::Vec3SGrid, openvdb::tools::BoxSampler> sample(*grids_->velocity);
  const openvdb::Vec3s v = sample.wsSample(openvdb::Vec3d(c[0] / scale_, c[1] / scale_, c[2] / scale_));
  return fromCacheAxes({scale_ * v[0], scale_ * v[1], scale_ * v[2]}, up_);
}

double CacheFrameReader::voxelSize() const { return scale_ * grids_->surface->voxelSize()[0]; }

std::array<Vec3, 2> CacheFrameReader::bounds() const {
  const openvdb::CoordBBox box = grids_->surface->evalActiveVoxelBoundingBox();
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec3 hi{-lo[0], -lo[1], -lo[2]};
  for (int corner = 0; corner < 8; ++corner) {
    const openvdb::Coord ijk((corner & 1 ? box.max() : box.min()).x(), (corner & 2 ? box.max() : box.min()).y(),
                             (corner & 4 ? box.max() : box.min()).z());
    const openvdb::Vec3d w = grids_->surface->indexToWorld(ijk);
    const Vec3 p = fromCacheAxes({scale_ * w[0], scale_ * w[1], scale_ * w[2]}, up_);
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
  return {lo, hi};
}

}  // namespace fluidsound::io
