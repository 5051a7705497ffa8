// io/frame_points.cpp — see frame_points.h. Its own file: OpenVDB's point conversion templates are
// slow to compile.
#include "io/frame_points.h"

#include <openvdb/points/PointAttribute.h>
#include <openvdb/points/PointConversion.h>
#include <openvdb/tools/PointIndexGrid.h>

#include <vector>

namespace fluidsound::io {

openvdb::points::PointDataGrid::Ptr particlePointGrid(const sim::Particles& particles,
                                                      const openvdb::math::Transform::Ptr& transform) {
  using namespace openvdb::points;
  std::vector<openvdb::Vec3R> positions(particles.size());
  std::vector<openvdb::Vec3f> velocities(particles.size());
  std::vector<openvdb::Int64> ids(particles.size());
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const sim::Vec3f& x = particles.position[p];
    const sim::Vec3f& v = particles.velocity[p];
    positions[p] = openvdb::Vec3R(x[0], x[1], x[2]);
    velocities[p] = openvdb::Vec3f(v[0], v[1], v[2]);
    ids[p] = static_cast<openvdb::Int64>(p < particles.id.size() ? particles.id[p] : p);
  }
  const PointAttributeVector<openvdb::Vec3R> positionList(positions);
  const auto index = openvdb::tools::createPointIndexGrid<openvdb::tools::PointIndexGrid>(positionList, *transform);
  // NullCodec: positions as exact floats (voxel-relative), so a reader gets our particles back.
  PointDataGrid::Ptr points = createPointDataGrid<NullCodec, PointDataGrid>(*index, positionList, *transform);
  appendAttribute<openvdb::Vec3f>(points->tree(), "v");
  populateAttribute(points->tree(), index->tree(), "v", PointAttributeVector<openvdb::Vec3f>(velocities));
  appendAttribute<openvdb::Int64>(points->tree(), "id");
  populateAttribute(points->tree(), index->tree(), "id", PointAttributeVector<openvdb::Int64>(ids));
  points->setName(kParticlePointsName);
  return points;
}

}  // namespace fluidsound::io
