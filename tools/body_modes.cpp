// tools/body_modes.cpp — see body_modes.h.
#include "tools/body_modes.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <sstream>
#include <variant>

#include "io/input_error.h"
#include "io/modal_model_file.h"
#include "sim/body_motion.h"
#include "tools/body_voxels.h"

namespace fluidsound::tools {

namespace {

/// The body's voxels in its rigid-body frame, `resolution` along its longest side.
acoustics::VoxelSolid bodyVoxels(const sim::RigidBodySpec& spec, int resolution) {
  if (const auto* mesh = std::get_if<sim::TriangleMesh>(&spec.shape)) return voxeliseBody(*mesh, 1.0, resolution);
  Eigen::Vector3d half;
  std::function<bool(const Eigen::Vector3d&)> inside;
  if (const auto* sphere = std::get_if<sim::SphereShape>(&spec.shape)) {
    half.setConstant(sphere->radius);
    inside = [r = sphere->radius](const Eigen::Vector3d& x) { return x.norm() < r; };
  } else {
    const auto& box = std::get<sim::BoxShape>(spec.shape);
    half = {box.halfExtents[0], box.halfExtents[1], box.halfExtents[2]};
    inside = [half](const Eigen::Vector3d& x) { return (x.cwiseAbs() - half).maxCoeff() < 0.0; };
  }
  return acoustics::voxelSolidFromInside(inside, -half, half, 2.0 * half.maxCoeff() / resolution);
}

}  // namespace

BodyModes bodyModes(const sim::Scene& scene, std::size_t index, const std::filesystem::path& cacheFolder,
                    double maxFrequency) {
  const auto start = std::chrono::steady_clock::now();
  const sim::SceneBody& body = scene.bodies[index];
  const sim::RigidBodySpec spec = sim::rigidBodySpec(body);
  const acoustics::VoxelSolid solid = bodyVoxels(spec, body.resolution);
  if (const std::string problem = voxelResolutionProblem(solid, body.resolution); !problem.empty())
    throw io::InputError(scene.file.string(), "bodies[" + std::to_string(index) + "].resolution",
                         "a resolution at which the body holds at least one voxel", problem);
  acoustics::ModalSettings settings;
  settings.maxFrequency = maxFrequency;
  // The key: the shape in the body's frame and every setting that shapes the modes.
  std::ostringstream key;
  key.precision(17);
  const SolidMaterial& m = body.material;
  key << "run body material " << m.density << ' ' << m.youngsModulus << ' ' << m.poissonsRatio << ' '
      << m.rayleighMass << ' ' << m.rayleighStiffness << " resolution " << body.resolution << " modes "
      << settings.maxModes << " max " << settings.maxFrequency;
  std::uint64_t cacheKey = 0;
  if (const auto* mesh = std::get_if<sim::MeshFile>(&body.shape)) {
    key << " mesh scale " << body.scale;
    cacheKey = io::modalCacheKey(mesh->file, key.str());
  } else if (const auto* sphere = std::get_if<sim::SphereShape>(&spec.shape)) {
    key << " sphere " << sphere->radius;
    cacheKey = io::modalCacheKey(key.str());
  } else {
    const auto& h = std::get<sim::BoxShape>(spec.shape).halfExtents;
    key << " box " << h[0] << ' ' << h[1] << ' ' << h[2];
    cacheKey = io::modalCacheKey(key.str());
  }
  BodyModes out;
  out.voxels = solid.cells.size();
  out.voxelSize = solid.voxelSize;
  if (std::optional<acoustics::ModalModel> cached = io::readCachedModes(cacheFolder, cacheKey)) {
    out.model = std::move(*cached);
    out.cache = "read";
  } else {
    out.model = acoustics::analyseModes(solid, body.material, settings);
    const auto problem = io::writeCachedModes(cacheFolder, cacheKey, out.model);
    out.cache = problem ? "not written: " + *problem : "written";
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace fluidsound::tools
