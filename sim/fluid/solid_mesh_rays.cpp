// sim/fluid/solid_mesh_rays.cpp — see solid_mesh_rays.h. Embree 3 API (Debian 12 has no Embree 4).
#include "sim/fluid/solid_mesh_rays.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include <embree3/rtcore.h>

#include "sim/fluid/solid_geometry.h"

namespace fluidsound::sim {
namespace {

Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

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
  std::size_t sceneIndex = 0;  ///< its place among the scene's solids
  std::vector<PathKey> path;
  Vec3 lower{}, upper{};         ///< bounding box of the triangles in the solid's frame [m]
  std::vector<Vec3> outward;     ///< unit normal of each triangle, out of the solid
};

/// Unit normals out of a closed mesh: (v1 − v0) × (v2 − v0), turned round when the mesh is
/// oriented inward (negative enclosed volume; io/mesh_closedness.h accepts either way round).
std::vector<Vec3> outwardNormals(const TriangleMesh& mesh) {
  std::vector<Vec3> normal(mesh.triangles.size());
  double volume6 = 0.0;  // 6 × the signed enclosed volume
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    Vec3 v[3];
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) v[c][k] = mesh.vertices[mesh.triangles[t][c]][k];
    const Vec3 e1 = minus(v[1], v[0]), e2 = minus(v[2], v[0]);
    normal[t] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    volume6 += dot(v[0], {v[1][1] * v[2][2] - v[1][2] * v[2][1], v[1][2] * v[2][0] - v[1][0] * v[2][2],
                          v[1][0] * v[2][1] - v[1][1] * v[2][0]});
  }
  const double sign = volume6 < 0.0 ? -1.0 : 1.0;
  for (Vec3& n : normal) {
    const double length = std::sqrt(dot(n, n));
    for (double& c : n) c = length > 0.0 ? sign * c / length : 0.0;
  }
  return normal;
}


/// Whether the segment's bounding box, widened by `margin`, misses the solid's box.
bool missesBounds(const MeshSolid& solid, const Vec3& a, const Vec3& b, double margin) {
  for (int k = 0; k < 3; ++k)
    if (std::max(a[k], b[k]) + margin < solid.lower[k] || std::min(a[k], b[k]) - margin > solid.upper[k]) return true;
  return false;
}

RTCRayHit segmentRay(const Vec3& a, const Vec3& b, float tnear) {
  RTCRayHit r;
  std::memset(&r, 0, sizeof r);
  r.ray.org_x = static_cast<float>(a[0]);
  r.ray.org_y = static_cast<float>(a[1]);
  r.ray.org_z = static_cast<float>(a[2]);
  r.ray.dir_x = static_cast<float>(b[0] - a[0]);
  r.ray.dir_y = static_cast<float>(b[1] - a[1]);
  r.ray.dir_z = static_cast<float>(b[2] - a[2]);
  r.ray.tnear = tnear;
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

  /// Fraction t ∈ [tnear, 1] of the segment a → b (in the solid's frame) at its first surface
  /// crossing, with the outward normal of the triangle hit; nothing when it misses.
  std::optional<std::pair<double, Vec3>> hit(const MeshSolid& solid, const Vec3& a, const Vec3& b,
                                             float tnear = 0.0f) const {
    RTCRayHit r = segmentRay(a, b, tnear);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(solid.scene.get(), &context, &r);
    if (r.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    return std::pair<double, Vec3>{r.ray.tfar, solid.outward[r.hit.primID]};
  }

  /// The first crossing of a → b that enters the solid (against its outward normal): crossings
  /// out of it (a mover that float rounding left a hair inside) are passed through.
  std::optional<std::pair<double, Vec3>> entry(const MeshSolid& solid, const Vec3& a, const Vec3& b) const {
    const Vec3 move = minus(b, a);
    float tnear = 0.0f;
    for (int exits = 0; exits < kMaxExitsPassed; ++exits) {
      const auto found = hit(solid, a, b, tnear);
      if (!found || dot(found->second, move) < 0.0) return found;
      tnear = std::nextafter(static_cast<float>(found->first), 2.0f);
    }
    return std::nullopt;
  }
  static constexpr int kMaxExitsPassed = 4;
};

SolidMeshRays::SolidMeshRays() = default;
SolidMeshRays::~SolidMeshRays() = default;
SolidMeshRays::SolidMeshRays(SolidMeshRays&&) noexcept = default;
SolidMeshRays& SolidMeshRays::operator=(SolidMeshRays&&) noexcept = default;

SolidMeshRays::SolidMeshRays(std::span<const Solid> solids) {
  std::vector<std::size_t> meshSolids;
  for (std::size_t i = 0; i < solids.size(); ++i)
    if (const auto* mesh = std::get_if<MeshFile>(&solids[i].shape); mesh != nullptr && mesh->surface)
      meshSolids.push_back(i);
  if (meshSolids.empty()) return;
  impl_ = std::make_unique<Impl>();
  impl_->device.reset(rtcNewDevice(nullptr));
  if (!impl_->device)
    throw std::runtime_error("Embree: cannot create a device (error " + std::to_string(rtcGetDeviceError(nullptr)) + ")");
  for (const std::size_t i : meshSolids) {
    const Solid* s = &solids[i];
    const TriangleMesh& mesh = *std::get<MeshFile>(s->shape).surface;
    MeshSolid solid;
    solid.sceneIndex = i;
    solid.path = s->path;
    solid.outward = outwardNormals(mesh);
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

void SolidMeshRays::extendPath(std::size_t sceneIndex, std::span<const PathKey> keys) {
  if (!impl_) return;
  for (MeshSolid& solid : impl_->solids)
    if (solid.sceneIndex == sceneIndex) solid.path.insert(solid.path.end(), keys.begin(), keys.end());
}

std::optional<WallStop> SolidMeshRays::firstCrossing(const Vec3& from, const Vec3& to, double timeFrom, double timeTo,
                                                     double offset) const {
  if (!impl_) return std::nullopt;
  // The segment tested runs from ½·offset behind `from` to `offset` beyond `to` (in the solid's
  // frame): a mover never ends closer than `offset` to a wall straight ahead of it, and one that
  // float rounding left a hair inside a surface and that moves on inwards is caught by the
  // surface behind it. Only entries into a solid count (outward normals), so a mover is always
  // put back on the outside of the surface it met, whichever side the ray started.
  double first = 2.0;  // fraction of the extended segment at the first entry so far (> 1: none)
  const MeshSolid* hitSolid = nullptr;
  Vec3 normal{}, a{}, b{};
  for (const MeshSolid& solid : impl_->solids) {
    Vec3 sa = minus(from, pathTranslation(solid.path, timeFrom));
    Vec3 sb = minus(to, pathTranslation(solid.path, timeTo));
    const Vec3 move = minus(sb, sa);
    const double length = std::sqrt(dot(move, move));
    if (length == 0.0 || missesBounds(solid, sa, sb, offset)) continue;
    for (int k = 0; k < 3; ++k) {
      sa[k] -= 0.5 * offset * move[k] / length;
      sb[k] += offset * move[k] / length;
    }
    const auto found = impl_->entry(solid, sa, sb);
    if (!found || found->first >= first) continue;
    first = found->first;
    normal = found->second;
    hitSolid = &solid;
    a = sa;
    b = sb;
  }
  if (hitSolid == nullptr) return std::nullopt;
  WallStop stop;
  stop.normal = normal;
  Vec3 surface{}, local{};
  for (int k = 0; k < 3; ++k) {
    surface[k] = a[k] + first * (b[k] - a[k]);
    local[k] = surface[k] + offset * normal[k];
  }
  // Stepping off the surface along its normal could, in a concave corner narrower than
  // `offset`, cross another face: then stay where the move began.
  Vec3 justOutside{};
  for (int k = 0; k < 3; ++k) justOutside[k] = surface[k] + 1e-3 * offset * normal[k];
  const Vec3 d1 = pathTranslation(hitSolid->path, timeTo);
  if (impl_->hit(*hitSolid, justOutside, local)) local = minus(from, pathTranslation(hitSolid->path, timeFrom));
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

bool SolidMeshRays::cutsBox(const Vec3& lo, const Vec3& hi, double time) const {
  if (!impl_) return false;
  const auto corner = [&](int c) { return Vec3{c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]}; };
  for (int c = 0; c < 8; ++c)
    for (int bit : {1, 2, 4})
      if (!(c & bit) && crosses(corner(c), corner(c | bit), time)) return true;
  return false;
}

}  // namespace fluidsound::sim
