// io/cache_frame_reader.cpp — see cache_frame_reader.h.
#include "io/cache_frame_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/points/PointDataGrid.h>
#include <openvdb/tools/Interpolation.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "io/input_error.h"
#include "io/point_grid_particles.h"

namespace fluidsound::io {

Vec3 fromCacheAxes(const Vec3& v, UpAxis up) { return up == UpAxis::Y ? v : Vec3{v[0], v[2], -v[1]}; }

Vec3 toCacheAxes(const Vec3& v, UpAxis up) { return up == UpAxis::Y ? v : Vec3{v[0], -v[2], v[1]}; }

namespace {

/// Where x [m, y up] lies in `field`'s index space, the cache's axes and units being `up` and
/// `scale` metres per unit.
openvdb::Vec3d indexOf(const openvdb::GridBase& field, const Vec3& x, double scale, UpAxis up) {
  const Vec3 c = toCacheAxes(x, up);
  return field.worldToIndex(openvdb::Vec3d(c[0] / scale, c[1] / scale, c[2] / scale));
}

/// The world box [m, y up] of index box `box` of `transform`, in the cache's units `scale`.
std::array<Vec3, 2> worldBounds(const openvdb::CoordBBox& box, const openvdb::math::Transform& transform,
                                double scale, UpAxis up) {
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec3 hi{-lo[0], -lo[1], -lo[2]};
  for (int corner = 0; corner < 8; ++corner) {
    const openvdb::Coord ijk((corner & 1 ? box.max() : box.min()).x(), (corner & 2 ? box.max() : box.min()).y(),
                             (corner & 4 ? box.max() : box.min()).z());
    const openvdb::Vec3d w = transform.indexToWorld(ijk);
    const Vec3 p = fromCacheAxes({scale * w[0], scale * w[1], scale * w[2]}, up);
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  }
  return {lo, hi};
}

/// Calls sample(i, j, k, worldPoint) for every (i, j, k) < size, k-slabs in parallel.
template <class Sample>
void forEachPoint(const sim::Index3& size, const sim::GridGeometry& grid, const Vec3& offsetCells, Sample sample) {
  tbb::parallel_for(tbb::blocked_range<int>(0, size[2]), [&](const tbb::blocked_range<int>& r) {
    auto local = sample;  // one accessor per task
    for (int k = r.begin(); k < r.end(); ++k)
      for (int j = 0; j < size[1]; ++j)
        for (int i = 0; i < size[0]; ++i)
          local(i, j, k, grid.worldFromGrid({i + offsetCells[0], j + offsetCells[1], k + offsetCells[2]}));
  });
}

/// The index offset O with cell (i, j, k) of `grid` on voxel (i, j, k) + O of `field`, when the
/// frame's lattice is the grid's: y up, no rotation in the transform, the voxel the cell's edge
/// and cell centres on voxel centres (1e-4 voxels). Reads there are lookups, not interpolations:
/// the same values (a trilinear sample at a voxel centre is the voxel's value) at a fraction of the
/// cost. None otherwise.
std::optional<openvdb::Coord> alignedOffset(const openvdb::GridBase& field, const sim::GridGeometry& grid,
                                            double scale, UpAxis up) {
  const openvdb::math::MapBase::ConstPtr map = field.transform().baseMap();
  if (up != UpAxis::Y || !(map->isType<openvdb::math::UniformScaleTranslateMap>() ||
                           map->isType<openvdb::math::UniformScaleMap>()))
    return std::nullopt;
  if (std::abs(scale * field.voxelSize()[0] - grid.cellSize) > 1e-6 * grid.cellSize) return std::nullopt;
  const openvdb::Vec3d o = indexOf(field, grid.cellCentre(0, 0, 0), scale, up);
  openvdb::Coord offset;
  for (int a = 0; a < 3; ++a) {
    offset[a] = static_cast<int>(std::lround(o[a]));
    if (std::abs(o[a] - offset[a]) > 1e-4) return std::nullopt;
  }
  return offset;
}

}  // namespace

CacheFrameExtent cacheFrameExtent(const std::filesystem::path& path, const CacheGridNames& names,
                                  double metresPerUnit, UpAxis up) {
  const CacheFrameGrids found = checkCacheFrame(path, names);
  openvdb::io::File file(path.string());
  file.open(/*delayLoad=*/true);
  openvdb::GridBase::Ptr surface = file.readGridMetadata(found.surface);
  bool points = false;
  for (auto name = file.beginName(); name != file.endName() && !points; ++name)
    points = file.readGridMetadata(name.gridName())->isType<openvdb::points::PointDataGrid>();
  openvdb::CoordBBox box;
  const auto lo = surface->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MIN);
  const auto hi = surface->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MAX);
  if (lo && hi) {
    box = openvdb::CoordBBox(openvdb::Coord(lo->value()), openvdb::Coord(hi->value()));
  } else {
    surface = file.readGrid(found.surface);
    box = surface->evalActiveVoxelBoundingBox();
  }
  file.close();
  if (box.empty()) return {std::nullopt, metresPerUnit * found.voxelSize, points};
  return {worldBounds(box, surface->transform(), metresPerUnit, up), metresPerUnit * found.voxelSize, points};
}

struct CacheFrameReader::Grids {
  openvdb::FloatGrid::Ptr surface;
  openvdb::Vec3SGrid::Ptr velocity;  // a double grid is read as floats
  openvdb::points::PointDataGrid::Ptr points;  // with withPoints, if the file has one
};

CacheFrameReader::CacheFrameReader(const std::filesystem::path& path, const CacheGridNames& names,
                                   double metresPerUnit, UpAxis up)
    : CacheFrameReader(path, checkCacheFrame(path, names), metresPerUnit, up, false) {}

CacheFrameReader::CacheFrameReader(const std::filesystem::path& path, const CacheFrameGrids& checked,
                                   double metresPerUnit, UpAxis up, bool withPoints)
    : grids_(std::make_unique<Grids>()), path_(path), scale_(metresPerUnit), up_(up) {
  openvdb::initialize();
  openvdb::GridBase::Ptr velocity;
  try {
    openvdb::io::File file(path.string());
    file.open(/*delayLoad=*/false);
    grids_->surface = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(checked.surface));
    velocity = file.readGrid(checked.velocity);
    for (auto name = file.beginName(); withPoints && name != file.endName() && !grids_->points; ++name)
      if (file.readGridMetadata(name.gridName())->isType<openvdb::points::PointDataGrid>())
        grids_->points = openvdb::gridPtrCast<openvdb::points::PointDataGrid>(file.readGrid(name.gridName()));
    file.close();
  } catch (const openvdb::Exception& e) {
    throw InputError(path.string(), "", "an OpenVDB file", std::string("an unreadable file (") + e.what() + ")");
  }
  if (!grids_->surface) throw InputError(path.string(), checked.surface, "a FloatGrid (a level set)", "another type");
  if (auto single = openvdb::gridPtrCast<openvdb::Vec3SGrid>(velocity)) {
    grids_->velocity = single;
  } else if (const auto twice = openvdb::gridPtrCast<openvdb::Vec3DGrid>(velocity)) {
    // Vec3 doubles (checkCacheFrame allows them): the same values as floats
    grids_->velocity = openvdb::Vec3SGrid::create(openvdb::Vec3s(twice->background()));
    grids_->velocity->setTransform(twice->transform().copy());
    grids_->velocity->setGridClass(twice->getGridClass());
    auto out = grids_->velocity->getAccessor();
    for (auto it = twice->cbeginValueOn(); it; ++it) out.setValue(it.getCoord(), openvdb::Vec3s(*it));
  } else {
    throw InputError(path.string(), checked.velocity, "a Vec3 grid of floats or doubles", "another type");
  }
}

std::optional<sim::FrameParticles> CacheFrameReader::particles() const {
  if (!grids_->points) return std::nullopt;
  return pointGridParticles(*grids_->points, scale_, up_, path_.string());
}

CacheFrameReader::~CacheFrameReader() = default;
CacheFrameReader::CacheFrameReader(CacheFrameReader&&) noexcept = default;
CacheFrameReader& CacheFrameReader::operator=(CacheFrameReader&&) noexcept = default;

double CacheFrameReader::phi(const Vec3& x) const {
  float value = 0.0f;
  openvdb::tools::BoxSampler::sample(grids_->surface->getConstAccessor(), indexOf(*grids_->surface, x, scale_, up_),
                                     value);
  return scale_ * static_cast<double>(value);
}

Vec3 CacheFrameReader::velocity(const Vec3& x) const {
  const openvdb::Vec3SGrid& field = *grids_->velocity;
  const openvdb::Vec3d index = indexOf(field, x, scale_, up_);
  openvdb::Vec3s v(0.0f);
  // A staggered grid (Houdini's FLIP `vel`, fluidsound's `velocity`) holds each component on the
  // voxel's low face.
  if (field.getGridClass() == openvdb::GRID_STAGGERED)
    openvdb::tools::StaggeredBoxSampler::sample(field.getConstAccessor(), index, v);
  else
    openvdb::tools::BoxSampler::sample(field.getConstAccessor(), index, v);
  return fromCacheAxes({scale_ * v[0], scale_ * v[1], scale_ * v[2]}, up_);
}

double CacheFrameReader::voxelSize() const { return scale_ * grids_->surface->voxelSize()[0]; }

std::array<Vec3, 2> CacheFrameReader::bounds() const {
  return worldBounds(grids_->surface->evalActiveVoxelBoundingBox(), grids_->surface->transform(), scale_, up_);
}

sim::Array3f CacheFrameReader::cellCentrePhi(const sim::GridGeometry& grid) const {
  sim::Array3f phi(grid.cells);
  const openvdb::FloatGrid& surface = *grids_->surface;
  if (const auto offset = alignedOffset(surface, grid, scale_, up_)) {
    const auto scale = static_cast<float>(scale_);
    tbb::parallel_for(tbb::blocked_range<int>(0, grid.cells[2]), [&](const tbb::blocked_range<int>& r) {
      const auto read = surface.getConstAccessor();
      for (int k = r.begin(); k < r.end(); ++k)
        for (int j = 0; j < grid.cells[1]; ++j)
          for (int i = 0; i < grid.cells[0]; ++i) phi(i, j, k) = scale * read.getValue(openvdb::Coord(i, j, k) + *offset);
    });
    return phi;
  }
  struct Sampler {
    openvdb::FloatGrid::ConstAccessor accessor;
    const openvdb::FloatGrid* grid;
    sim::Array3f* out;
    double scale;
    UpAxis up;
    void operator()(int i, int j, int k, const Vec3& x) {
      const openvdb::Vec3d index = indexOf(*grid, x, scale, up);
      float value = 0.0f;
      openvdb::tools::BoxSampler::sample(accessor, index, value);
      (*out)(i, j, k) = static_cast<float>(scale * value);
    }
  };
  forEachPoint(grid.cells, grid, {0.5, 0.5, 0.5}, Sampler{surface.getConstAccessor(), &surface, &phi, scale_, up_});
  return phi;
}

sim::MacVelocity CacheFrameReader::faceVelocity(const sim::GridGeometry& grid,
                                                std::array<sim::Array3<std::uint8_t>, 3>* known) const {
  sim::MacVelocity velocity(grid);
  const openvdb::Vec3SGrid& field = *grids_->velocity;
  if (const auto offset = alignedOffset(field, grid, scale_, up_)) {
    // Face (i, j, k) of `axis` is the low face of cell (i, j, k): a staggered grid holds it in that
    // cell's voxel; a cell-centred one gives the mean of the voxels on its two sides.
    const bool staggered = field.getGridClass() == openvdb::GRID_STAGGERED;
    const auto scale = static_cast<float>(scale_);
    for (int axis = 0; axis < 3; ++axis) {
      if (known) (*known)[axis] = sim::Array3<std::uint8_t>(grid.faceCount(axis), 0);
      const sim::Index3 n = grid.faceCount(axis);
      openvdb::Coord step(0, 0, 0);
      step[axis] = -1;
      tbb::parallel_for(tbb::blocked_range<int>(0, n[2]), [&](const tbb::blocked_range<int>& r) {
        const auto read = field.getConstAccessor();
        for (int k = r.begin(); k < r.end(); ++k)
          for (int j = 0; j < n[1]; ++j)
            for (int i = 0; i < n[0]; ++i) {
              const openvdb::Coord at = openvdb::Coord(i, j, k) + *offset;
              openvdb::Vec3s value;
              bool on = read.probeValue(at, value);
              float u = value[axis];
              if (!staggered) {
                openvdb::Vec3s below;
                on = read.probeValue(at + step, below) && on;
                u = 0.5f * (u + below[axis]);
              }
              velocity[axis](i, j, k) = scale * u;
              if (known) (*known)[axis](i, j, k) = on ? 1 : 0;
            }
      });
    }
    return velocity;
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (known) (*known)[axis] = sim::Array3<std::uint8_t>(grid.faceCount(axis), 0);
    struct Sampler {
      openvdb::Vec3SGrid::ConstAccessor accessor;
      const openvdb::Vec3SGrid* grid;
      sim::Array3f* out;
      sim::Array3<std::uint8_t>* known;
      int axis;
      bool staggered;
      double scale;
      UpAxis up;
      void operator()(int i, int j, int k, const Vec3& x) {
        const openvdb::Vec3d index = indexOf(*grid, x, scale, up);
        openvdb::Vec3s value(0.0f);
        if (staggered) openvdb::tools::StaggeredBoxSampler::sample(accessor, index, value);
        else openvdb::tools::BoxSampler::sample(accessor, index, value);
        const Vec3 v = fromCacheAxes({scale * value[0], scale * value[1], scale * value[2]}, up);
        (*out)(i, j, k) = static_cast<float>(v[axis]);
        if (known) {  // every voxel of the interpolation's stencil holds a value of the cache's
          const openvdb::Coord base(static_cast<int>(std::floor(index[0])), static_cast<int>(std::floor(index[1])),
                                    static_cast<int>(std::floor(index[2])));
          bool on = true;
          for (int corner = 0; corner < 8 && on; ++corner)
            on = accessor.isValueOn(base.offsetBy(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1));
          (*known)(i, j, k) = on ? 1 : 0;
        }
      }
    };
    Vec3 offset{0.5, 0.5, 0.5};
    offset[axis] = 0.0;
    forEachPoint(grid.faceCount(axis), grid, offset,
                 Sampler{field.getConstAccessor(), &field, &velocity[axis], known ? &(*known)[axis] : nullptr, axis,
                         field.getGridClass() == openvdb::GRID_STAGGERED, scale_, up_});
  }
  return velocity;
}


}  // namespace fluidsound::io
