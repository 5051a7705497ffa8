// tools/modes_command.cpp — `fluidsound modes` (see modes_command.h).
#include "tools/modes_command.h"

#include <chrono>
#include <optional>
#include <sstream>
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "acoustics/modal/modal_analysis.h"
#include "acoustics/modal/mode_compression.h"
#include "acoustics/modal/solid_material.h"
#include "io/input_error.h"
#include "io/mesh_file.h"
#include "io/modal_model_file.h"
#include "tools/body_voxels.h"
#include "tools/number_checks.h"

namespace fluidsound::tools {
namespace {

std::string materialNames() {
  std::string names;
  for (const acoustics::NamedSolidMaterial& m : acoustics::solidMaterials())
    names += (names.empty() ? "" : ", ") + std::string(m.name);
  return names;
}

SolidMaterial chosenMaterial(const ModesOptions& o) {
  SolidMaterial material = *acoustics::findSolidMaterial(o.material);
  if (o.density) material.density = *o.density;
  if (o.youngsModulus) material.youngsModulus = *o.youngsModulus;
  if (o.poissonsRatio) material.poissonsRatio = *o.poissonsRatio;
  if (o.rayleighMass) material.rayleighMass = *o.rayleighMass;
  if (o.rayleighStiffness) material.rayleighStiffness = *o.rayleighStiffness;
  return material;
}

/// Nodes on the face `face` (−x … +z) of the solid's cell box, within half a voxel.
std::function<bool(const Eigen::Vector3d&)> clampedFace(const std::string& face, const acoustics::VoxelSolid& solid) {
  if (face.empty()) return {};
  const int axis = face[1] - 'x';
  int lo = solid.cells.front()[axis], hi = lo;
  for (const Eigen::Vector3i& c : solid.cells) lo = std::min(lo, c[axis]), hi = std::max(hi, c[axis]);
  const double h = solid.voxelSize;
  const double plane = solid.origin[axis] + h * (face[0] == '-' ? lo : hi + 1);
  return [axis, plane, h](const Eigen::Vector3d& x) { return std::abs(x[axis] - plane) < 0.5 * h; };
}

}  // namespace

CLI::App* addModesCommand(CLI::App& app, ModesOptions& o) {
  CLI::App* c = app.add_subcommand("modes", "list a body's vibration modes (frequency, decay, compressed count)");
  c->add_option("mesh", o.mesh, "the body: a closed triangle mesh (OBJ or PLY), metres after --scale")->required();
  c->add_option("--material", o.material, "material from the table: " + materialNames())
      ->check([](const std::string& name) {
        return acoustics::findSolidMaterial(name) ? std::string() : "unknown material; known: " + materialNames();
      });
  c->add_option("--density", o.density, "override the material's density, kg/m^3")->check(finitePositive());
  c->add_option("--youngs-modulus", o.youngsModulus, "override Young's modulus, Pa")->check(finitePositive());
  c->add_option("--poissons-ratio", o.poissonsRatio, "override Poisson's ratio, in (-1, 0.5)")
      ->check(CLI::Validator(
          [](const std::string& text) {
            try {
              const double nu = std::stod(text);
              if (nu > -1.0 && nu < 0.5) return std::string();
            } catch (const std::exception&) {
            }
            return std::string("must be a number in (-1, 0.5)");
          },
          "(-1, 0.5)"));
  c->add_option("--rayleigh-mass", o.rayleighMass, "override the mass-proportional damping a_M, 1/s")
      ->check(finiteRange(0.0, 1e9));
  c->add_option("--rayleigh-stiffness", o.rayleighStiffness, "override the stiffness-proportional damping b_K, s")
      ->check(finiteRange(0.0, 1.0));
  c->add_option("--scale", o.scale, "mesh units to metres")->check(finitePositive());
  c->add_option("--resolution", o.resolution, "voxels along the body's longest side")->check(CLI::Range(2, 2000));
  c->add_option("--modes", o.maxModes, "most modes computed (the lowest)")->check(CLI::Range(1, 5000));
  c->add_option("--max-frequency", o.maxFrequency, "highest mode kept, Hz")->check(finitePositive());
  c->add_option("--clamp", o.clamp, "hold one face of the body's box fixed (a cantilever)")
      ->check(CLI::IsMember({"-x", "+x", "-y", "+y", "-z", "+z"}));
  c->add_flag("--json", o.json, "print JSON instead of a table");
  c->add_option("--cache", o.cache, "folder of cached modal models (made if missing): reused when the mesh and settings match");
  addCommonOptions(*c, o.common);
  return c;
}

int runModesCommand(const ModesOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const sim::TriangleMesh mesh = io::readMeshFile(o.mesh);
  io::requireClosedMesh(mesh, o.mesh);
  const SolidMaterial material = chosenMaterial(o);
  if (const auto problem = acoustics::solidMaterialProblem(material))
    throw CLI::ValidationError("--material", std::string(*problem));
  const acoustics::VoxelSolid solid = voxeliseBody(mesh, o.scale, o.resolution);
  if (const std::string problem = voxelResolutionProblem(solid, o.resolution); !problem.empty())
    throw io::InputError(o.mesh, "", "a body that holds at least one voxel", problem);
  acoustics::ModalSettings settings;
  settings.maxModes = o.maxModes;
  settings.maxFrequency = o.maxFrequency;
  settings.clamped = clampedFace(o.clamp, solid);
  if (!o.common.quiet)
    std::fprintf(stderr, "fluidsound: modes of %s: %zu voxels of %.3g mm\n", o.mesh.c_str(), solid.cells.size(),
                 solid.voxelSize * 1e3);
  // The cache key: the mesh's bytes and every setting that shapes the modes.
  std::ostringstream key;
  key.precision(17);
  key << "scale " << o.scale << " material " << material.density << ' ' << material.youngsModulus << ' '
      << material.poissonsRatio << ' ' << material.rayleighMass << ' ' << material.rayleighStiffness << " resolution "
      << o.resolution << " modes " << o.maxModes << " max " << o.maxFrequency << " clamp " << o.clamp;
  const std::uint64_t cacheKey = o.cache.empty() ? 0 : io::modalCacheKey(o.mesh, key.str());
  std::optional<acoustics::ModalModel> cached;
  if (!o.cache.empty()) cached = io::readCachedModes(o.cache, cacheKey);
  const acoustics::ModalModel model = cached ? *cached : acoustics::analyseModes(solid, material, settings);
  std::string cacheUse = o.cache.empty() ? "none" : cached ? "read" : "written";
  if (!o.cache.empty() && !cached) {
    if (const auto problem = io::writeCachedModes(o.cache, cacheKey, model)) {
      cacheUse = "not written";
      if (!o.common.quiet) std::fprintf(stderr, "fluidsound: note: modes not cached: %s\n", problem->c_str());
    }
  }
  const acoustics::ModeGroups groups = acoustics::groupIndistinguishableModes(model.frequency);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (o.json) {
    nlohmann::ordered_json out;
    out["mesh"] = o.mesh;
    out["material"] = {{"name", o.material}, {"density", material.density}, {"youngs_modulus", material.youngsModulus},
                       {"poissons_ratio", material.poissonsRatio}, {"rayleigh_mass", material.rayleighMass},
                       {"rayleigh_stiffness", material.rayleighStiffness}};
    out["scale"] = o.scale;
    out["resolution"] = o.resolution;
    out["voxel_size_m"] = solid.voxelSize;
    out["voxels"] = solid.cells.size();
    out["clamped"] = o.clamp.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(o.clamp);
    out["dof"] = model.dofCount;
    out["rigid_modes_dropped"] = model.rigidModesDropped;
    out["modes"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < model.frequency.size(); ++i)
      out["modes"].push_back({{"frequency_hz", model.frequency[i]},
                              {"damped_frequency_hz", model.dampedFrequency[i]},
                              {"decay_per_s", model.decayRate[i]},
                              {"group", groups.group[i]},
                              {"surface_motion_xyz", acoustics::surfaceMotionShares(model, i)}});
    out["compressed_modes"] = groups.first.size();
    out["cache"] = cacheUse;
    if (!o.cache.empty()) out["cache_file"] = io::modalCacheFile(o.cache, cacheKey).string();
    out["seconds"] = seconds;
    std::printf("%s\n", out.dump(2).c_str());
  } else {
    std::printf("%s: %zu voxels of %.4g mm, %d degrees of freedom, %d rigid modes dropped\n", o.mesh.c_str(),
                solid.cells.size(), solid.voxelSize * 1e3, model.dofCount, model.rigidModesDropped);
    std::printf("%6s %14s %14s %12s %6s  %s\n", "mode", "frequency_Hz", "damped_Hz", "decay_1/s", "group",
                "surface motion x/y/z");
    for (std::size_t i = 0; i < model.frequency.size(); ++i) {
      const std::array<double, 3> motion = acoustics::surfaceMotionShares(model, i);
      std::printf("%6zu %14.2f %14.2f %12.4g %6zu  %.2f/%.2f/%.2f\n", i + 1, model.frequency[i],
                  model.dampedFrequency[i], model.decayRate[i], groups.group[i] + 1, motion[0], motion[1], motion[2]);
    }
    std::printf("%zu modes up to %.0f Hz; %zu after compression (modes within the ear's frequency "
                "discrimination merged); %.2f s\n",
                model.frequency.size(), o.maxFrequency, groups.first.size(), seconds);
    if (!o.cache.empty())
      std::printf("cache: %s (%s)\n", cacheUse.c_str(), io::modalCacheFile(o.cache, cacheKey).c_str());
  }
  return kExitSuccess;
}

}  // namespace fluidsound::tools
