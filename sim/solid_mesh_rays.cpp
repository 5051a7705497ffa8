// sim/solid_mesh_rays.cpp — see solid_mesh_rays.h. Embree 3 API (Debian 12 has no Embree 4).
#include "sim/solid_mesh_rays.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include <embree3/rtcore.h>

#include "sim/solid_geometry.h"

namespace fluidsound::sim {
namespace {

struct DeviceRelease {
  void operator()(RTCDevice device) const { rtcReleaseDevice(device); }
};
struct SceneRelease {
  void operator()(RTCScene scene) const { rtcReleaseScene(scene); }
};
using DeviceHandle = std::unique_ptr<RTCDeviceTy, DeviceRelease>;
using SceneHandle = std::unique_ptr<RTCSceneTy, SceneRelease>;

/// One mesh solid: its triangles in its own frame (placed, path translation not applied).
struct MeshSolid {
  SceneHandle scene;
  std::vector<PathKey> path;
  Vec3 lower{}, upper{};  ///< bounding box of the triangles in the solid's frame [m]
};

Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// Whether the segment's bounding box, widened by `margin`, misses the solid's box.
bool missesBounds(const MeshSolid& solid, const Vec3& a, const Vec3& b, double margin) {
  for (int k = 0; k < 3; ++k)
    if (std::max(a[k], b[k]) + margin < solid.lower[k] || std::min(a[k], b[k]) - margin > solid.upper[k]) return true;
  return false;
}

RTCRayHit segmentRay(const Vec3& a, const Vec3& b) {
  RTCRayHit r;
  std::memset(&r, 0, sizeof r);
  r.ray.org_x = static_cast<float>(a[0]);
  r.ray.org_y = static_cast<float>(a[1]);
  r.ray.org_z = static_cast<float>(a[2]);
  r.ray.dir_x = static_cast<float>(b[0] - a[0]);
  r.ray.dir_y = static_cast<float>(b[1] - a[1]);
  r.ray.dir_z = static_cast<float>(b[2] - a[2]);
  r.ray.tnear = 0.0f;
  r.ray.tfar = 1.0f;  // the direction is the whole segment: t ∈ [0, 1]
  r.ray.mask = std::numeric_limits<unsigned>::max();
  r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  r.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return r;
}

}  // namespace

struct SolidMeshRays::Impl {
  DeviceHandle device;
  std::vector<MeshSolid> solids;

  /// Fraction t ∈ [0, 1] of the segment a → b (in the solid's frame) at its first surface
  /// crossing, with the geometric normal there; nothing when it misses.
  std::optional<std::pair<double, Vec3>> hit(const MeshSolid& solid, const Vec3& a, const Vec3& b) const {
    RTCRayHit r = segmentRay(a, b);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(solid.scene.get(), &context, &r);
    if (r.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    return std::pair<double, Vec3>{r.ray.tfar, Vec3{r.hit.Ng_x, r.hit.Ng_y, r.hit.Ng_z}};
  }
};

SolidMeshRays::SolidMeshRays() = default;
SolidMeshRays::~SolidMeshRays() = default;
SolidMeshRays::SolidMeshRays(SolidMeshRays&&) noexcept = default;
SolidMeshRays& SolidMeshRays::operator=(SolidMeshRays&&) noexcept = default;

SolidMeshRays::SolidMeshRays(std::span<const Solid> solids) {
  std::vector<const Solid*> meshSolids;
  for (const Solid& s : solids)
    if (const auto* mesh = std::get_if<MeshFile>(&s.shape); mesh != nullptr && mesh->surface) meshSolids.push_back(&s);
  if (meshSolids.empty()) return;
  impl_ = std::make_unique<Impl>();
  impl_->device.reset(rtcNewDevice(nullptr));
  if (!impl_->device)
    throw std::runtime_error("Embree: cannot create a device (error " + std::to_string(rtcGetDeviceError(nullptr)) + ")");
  for (const Solid* s : meshSolids) {
    const TriangleMesh& mesh = *std::get<MeshFile>(s->shape).surface;
    MeshSolid solid;
    solid.path = s->path;
    solid.scene.reset(rtcNewScene(impl_->device.get()));
    // Robust mode: watertight ray–triangle tests, so a ray through a shared edge or vertex of a
    // closed mesh always reports a hit (Embree's documentation of RTC_SCENE_FLAG_ROBUST).
    rtcSetSceneFlags(solid.scene.get(), RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(solid.scene.get(), RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geometry = rtcNewGeometry(impl_->device.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertex = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), mesh.vertices.size()));
    auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), mesh.triangles.size()));
    solid.lower.fill(std::numeric_limits<double>::infinity());
    solid.upper.fill(-std::numeric_limits<double>::infinity());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      for (int k = 0; k < 3; ++k) {
        vertex[3 * v + k] = mesh.vertices[v][k];
        solid.lower[k] = std::min(solid.lower[k], static_cast<double>(mesh.vertices[v][k]));
        solid.upper[k] = std::max(solid.upper[k], static_cast<double>(mesh.vertices[v][k]));
      }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) index[3 * t + k] = mesh.triangles[t][k];
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(solid.scene.get(), geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(solid.scene.get());
    const RTCError error = rtcGetDeviceError(impl_->device.get());
    if (error != RTC_ERROR_NONE)
      throw std::runtime_error("Embree: building the ray-query scene failed (error " + std::to_string(error) + ")");
    impl_->solids.push_back(std::move(solid));
  }
}

bool SolidMeshRays::empty() const { return !impl_; }

std::optional<WallStop> SolidMeshRays::firstCrossing(const Vec3& from, const Vec3& to, double timeFrom, double timeTo,
                                                     double offset) const {
  if (!impl_) return std::nullopt;
  double first = 2.0;  // segment fraction of the first hit so far (> 1: none)
  const MeshSolid* hitSolid = nullptr;
  Vec3 normal{}, a{}, b{};
  for (const MeshSolid& solid : impl_->solids) {
    const Vec3 sa = minus(from, pathTranslation(solid.path, timeFrom));
    const Vec3 sb = minus(to, pathTranslation(solid.path, timeTo));
    if (sa == sb || missesBounds(solid, sa, sb, offset)) continue;
    const auto found = impl_->hit(solid, sa, sb);
    if (!found || found->first >= first) continue;
    first = found->first;
    normal = found->second;
    hitSolid = &solid;
    a = sa;
    b = sb;
  }
  if (hitSolid == nullptr) return std::nullopt;
  const Vec3 move = minus(b, a);
  const double length = std::sqrt(dot(move, move));
  const double n = std::sqrt(dot(normal, normal));
  const double facing = dot(normal, move) > 0.0 ? -1.0 / n : 1.0 / n;  // towards the side of `from`
  WallStop stop;
  const double back = std::max(0.0, first - offset / length);
  Vec3 local{};
  for (int k = 0; k < 3; ++k) {
    stop.normal[k] = facing * normal[k];
    local[k] = a[k] + back * move[k] + offset * stop.normal[k];
  }
  // Stepping off the surface along its normal could, in a concave corner narrower than
  // `offset`, cross another face: then stay where the move began (known to be on this side).
  if (impl_->hit(*hitSolid, a, local)) local = a;
  const Vec3 d1 = pathTranslation(hitSolid->path, timeTo);
  for (int k = 0; k < 3; ++k) stop.position[k] = local[k] + d1[k];
  if (timeTo > timeFrom) {
    const Vec3 d0 = pathTranslation(hitSolid->path, timeFrom);
    for (int k = 0; k < 3; ++k) stop.wallVelocity[k] = (d1[k] - d0[k]) / (timeTo - timeFrom);
  } else {
    stop.wallVelocity = pathVelocity(hitSolid->path, timeFrom);
  }
  return stop;
}

bool SolidMeshRays::crosses(const Vec3& a, const Vec3& b, double time) const {
  if (!impl_) return false;
  for (const MeshSolid& solid : impl_->solids) {
    const Vec3 d = pathTranslation(solid.path, time);
    const Vec3 sa = minus(a, d), sb = minus(b, d);
    if (sa == sb || missesBounds(solid, sa, sb, 0.0)) continue;
    if (impl_->hit(solid, sa, sb)) return true;
  }
  return false;
}

}  // namespace fluidsound::sim
