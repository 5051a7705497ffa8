// io/cache_particles.cpp — see cache_particles.h.
#include "io/cache_particles.h"

#include "io/point_grid_particles.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/points/PointDataGrid.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "io/cache_frame_reader.h"
#include "io/input_error.h"
#include "io/vdb_file_check.h"

namespace fluidsound::io {
namespace {

using openvdb::points::AttributeHandle;
using openvdb::points::PointDataGrid;

bool finite(const openvdb::Vec3d& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

/// The index of attribute `name` in the grid's leaves and its value type, or none.
std::optional<std::pair<std::size_t, std::string>> attribute(const PointDataGrid& grid, const std::string& name) {
  const auto leaf = grid.constTree().cbeginLeaf();
  if (!leaf) return std::nullopt;
  const auto& descriptor = leaf->attributeSet().descriptor();
  const std::size_t index = descriptor.find(name);
  if (index == openvdb::points::AttributeSet::INVALID_POS) return std::nullopt;
  return std::make_pair(index, descriptor.valueType(index));
}

template <class T>
void readVectors(const openvdb::points::AttributeArray& array, std::vector<openvdb::Vec3d>& out) {
  const AttributeHandle<openvdb::math::Vec3<T>> handle(array);
  for (openvdb::Index i = 0; i < handle.size(); ++i) out.push_back(openvdb::Vec3d(handle.get(i)));
}

template <class T>
void readIds(const openvdb::points::AttributeArray& array, std::vector<std::uint64_t>& out) {
  const AttributeHandle<T> handle(array);
  for (openvdb::Index i = 0; i < handle.size(); ++i) out.push_back(static_cast<std::uint64_t>(handle.get(i)));
}

}  // namespace

std::optional<sim::FrameParticles> readPointParticles(const std::filesystem::path& path, double metresPerUnit,
                                                      UpAxis up) {
  requireIntactVdbFile(path);
  openvdb::initialize();
  openvdb::io::File file(path.string());
  file.open(/*delayLoad=*/false);
  PointDataGrid::Ptr grid;
  for (auto name = file.beginName(); name != file.endName() && !grid; ++name) {
    const openvdb::GridBase::Ptr header = file.readGridMetadata(name.gridName());
    if (header->isType<PointDataGrid>()) grid = openvdb::gridPtrCast<PointDataGrid>(file.readGrid(name.gridName()));
  }
  file.close();
  if (!grid) return std::nullopt;
  return pointGridParticles(*grid, metresPerUnit, up, path.string());
}

sim::FrameParticles pointGridParticles(const PointDataGrid& grid, double metresPerUnit, UpAxis up,
                                       const std::string& file) {
  const std::string& file_ = file;
  const std::string gridName = grid.getName();
  const auto v = attribute(grid, "v");
  const auto id = attribute(grid, "id");
  if (v && v->second != "vec3s" && v->second != "vec3d")
    throw InputError(file_, gridName + ".v", "a point velocity of 3 floats or doubles", "a " + v->second + " attribute");
  if (id && id->second != "int32" && id->second != "int64")
    throw InputError(file_, gridName + ".id", "a point id of int32 or int64", "a " + id->second + " attribute");

  std::vector<openvdb::Vec3d> positions, velocities;
  std::vector<std::uint64_t> ids;
  for (auto leaf = grid.constTree().cbeginLeaf(); leaf; ++leaf) {
    const AttributeHandle<openvdb::Vec3f> offset(leaf->constAttributeArray("P"));
    for (auto index = leaf->beginIndexOn(); index; ++index) {
      const openvdb::Vec3d voxel = index.getCoord().asVec3d() + openvdb::Vec3d(offset.get(*index));
      positions.push_back(grid.transform().indexToWorld(voxel));
    }
    // Attribute arrays are per leaf, in the same order as the points the index walk visits when
    // every point is active (the grids caches hold); read them whole.
    if (v) {
      if (v->second == "vec3s") readVectors<float>(leaf->constAttributeArray(v->first), velocities);
      else readVectors<double>(leaf->constAttributeArray(v->first), velocities);
    }
    if (id) {
      if (id->second == "int32") readIds<openvdb::Int32>(leaf->constAttributeArray(id->first), ids);
      else readIds<openvdb::Int64>(leaf->constAttributeArray(id->first), ids);
    }
  }
  sim::FrameParticles particles;
  particles.position.reserve(positions.size());
  for (std::size_t p = 0; p < positions.size(); ++p) {
    if (!finite(positions[p]) || (v && !finite(velocities[p])))
      throw InputError(file_, gridName, "finite point positions and velocities", "a NaN or infinite value at point " + std::to_string(p));
    const Vec3 x = fromCacheAxes({metresPerUnit * positions[p][0], metresPerUnit * positions[p][1], metresPerUnit * positions[p][2]}, up);
    particles.position.push_back({static_cast<float>(x[0]), static_cast<float>(x[1]), static_cast<float>(x[2])});
    if (v) {
      const Vec3 u = fromCacheAxes({metresPerUnit * velocities[p][0], metresPerUnit * velocities[p][1], metresPerUnit * velocities[p][2]}, up);
      particles.velocity.push_back({static_cast<float>(u[0]), static_cast<float>(u[1]), static_cast<float>(u[2])});
    }
  }
  if (id) {
    std::vector<std::uint64_t> sorted = ids;
    std::sort(sorted.begin(), sorted.end());
    const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    if (twice != sorted.end())
      throw InputError(file_, gridName + ".id", "a different id for every point", "id " + std::to_string(*twice) + " twice");
    particles.id = std::move(ids);
  }
  return particles;
}

}  // namespace fluidsound::io
