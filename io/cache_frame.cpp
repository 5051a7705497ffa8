// io/cache_frame.cpp — see cache_frame.h.
#include "io/cache_frame.h"

#include <cmath>
#include <sstream>

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include "io/input_error.h"
#include "io/vdb_file_check.h"

namespace fluidsound::io {
namespace {

std::string joined(const std::vector<std::string>& names, const std::string& separator) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) out += (i ? separator : "") + names[i];
  return out;
}

std::string coordText(const openvdb::Coord& c) {
  return "[" + std::to_string(c.x()) + ", " + std::to_string(c.y()) + ", " + std::to_string(c.z()) + "]";
}

std::string voxelText(const openvdb::Vec3d& v) {
  std::ostringstream out;
  out << "[" << v[0] << ", " << v[1] << ", " << v[2] << "]";
  return out.str();
}

/// The first of `wanted` among the file's grids, else an error listing what the file holds.
std::string findGrid(const std::vector<std::string>& present, const std::vector<std::string>& wanted,
                     const std::string& file, const std::string& role) {
  for (const std::string& name : wanted)
    for (const std::string& p : present)
      if (p == name) return name;
  throw InputError(file, wanted.front(), "a " + role + " grid named " + joined(wanted, " or "),
                   present.empty() ? "no grids" : "grids " + joined(present, ", "));
}

/// Uniform voxels on a linear transform, else an error.
void requireUniform(const openvdb::GridBase& grid, const std::string& file) {
  if (!grid.transform().isLinear() || !grid.hasUniformVoxels())
    throw InputError(file, grid.getName(), "uniform voxels on a linear transform",
                     "voxel size " + voxelText(grid.voxelSize()));
}

/// Every value (voxels and tiles, active or not) finite, else an error naming the first voxel.
template <class GridType, class Finite>
void requireFinite(const GridType& grid, const std::string& file, Finite finite) {
  for (auto it = grid.cbeginValueAll(); it; ++it)
    if (!finite(*it))
      throw InputError(file, grid.getName(), "finite values",
                       "a NaN or infinite value at voxel " + coordText(it.getCoord()));
}

}  // namespace

CacheFrameGrids findCacheFrameGrids(const std::filesystem::path& path, const CacheGridNames& names) {
  openvdb::initialize();
  const std::string file = path.string();
  CacheFrameGrids found;
  try {
    openvdb::io::File vdb(file);
    vdb.open(/*delayLoad=*/true);
    std::vector<std::string> present;
    for (auto it = vdb.beginName(); it != vdb.endName(); ++it) present.push_back(it.gridName());
    vdb.close();
    found.surface = findGrid(present, names.surface, file, "level set");
    found.velocity = findGrid(present, names.velocity, file, "velocity");
  } catch (const openvdb::Exception& e) {
    throw InputError(file, "", "an OpenVDB file", std::string("an unreadable file (") + e.what() + ")");
  }
  return found;
}

CacheFrameGrids checkCacheFrame(const std::filesystem::path& path, const CacheGridNames& names) {
  openvdb::initialize();
  const std::string file = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(file, "", "an OpenVDB frame file", std::filesystem::exists(path, ec) ? "not a regular file" : "no such file");
  requireIntactVdbFile(path);  // OpenVDB trusts the lengths in the file (vdb_file_check.h)
  openvdb::GridBase::Ptr surfaceBase, velocityBase;
  CacheFrameGrids found = findCacheFrameGrids(path, names);
  try {
    openvdb::io::File vdb(file);
    vdb.open(/*delayLoad=*/false);
    surfaceBase = vdb.readGrid(found.surface);
    velocityBase = vdb.readGrid(found.velocity);
    vdb.close();
  } catch (const openvdb::Exception& e) {
    throw InputError(file, "", "an OpenVDB file", std::string("an unreadable file (") + e.what() + ")");
  }
  const auto surface = openvdb::gridPtrCast<openvdb::FloatGrid>(surfaceBase);
  if (!surface) throw InputError(file, found.surface, "a FloatGrid (a level set)", "a " + surfaceBase->valueType() + " grid");
  requireUniform(*surface, file);
  requireFinite(*surface, file, [](float v) { return std::isfinite(v); });
  const auto finite3 = [](const auto& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); };
  if (const auto v = openvdb::gridPtrCast<openvdb::Vec3SGrid>(velocityBase)) {
    requireFinite(*v, file, finite3);
  } else if (const auto d = openvdb::gridPtrCast<openvdb::Vec3DGrid>(velocityBase)) {
    requireFinite(*d, file, finite3);
  } else {
    throw InputError(file, found.velocity, "a Vec3 float or double grid (a velocity)", "a " + velocityBase->valueType() + " grid");
  }
  requireUniform(*velocityBase, file);
  if (velocityBase->transform() != surface->transform())
    throw InputError(file, found.velocity, "the transform of " + found.surface + " (voxel " + voxelText(surface->voxelSize()) + ")",
                     "voxel " + voxelText(velocityBase->voxelSize()) + " at another placement");
  found.voxelSize = surface->voxelSize()[0];
  return found;
}

}  // namespace fluidsound::io
