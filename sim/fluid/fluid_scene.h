// sim/fluid/fluid_scene.h — the part of a scene (`fluidsound.scene/1`, DESIGN.md; docs/scene.md)
// the liquid solver reads, as value types: the domain, the liquid, its sources, the solids, time
// and the solver's settings. sim/scene.h adds what later stages read (listeners, audio, bubbles).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/triangle_mesh.h"

namespace fluidsound::sim {

/// Axis-aligned box [m], min < max on every axis.
struct Box {
  Vec3 min{}, max{};
  bool operator==(const Box&) const = default;
};

/// Sphere [m].
struct Sphere {
  Vec3 center{};
  double radius = 0.0;
  bool operator==(const Sphere&) const = default;
};

/// A triangle mesh file (OBJ or PLY), path resolved against the scene file's folder, and once
/// read (io::loadSceneMeshes) its triangles placed in the scene. The solver computes the
/// distances it needs from them on its own grid (sim/fluid/scene_mesh_distances.h).
struct MeshFile {
  std::filesystem::path file;
  /// The triangles [m], once read: a liquid region's as written, a solid's placed by its scale,
  /// rotation and translation (not its path). The solver's mesh distance and the ray queries
  /// against thin walls (sim/fluid/solid_mesh_rays.h) read them.
  std::shared_ptr<const TriangleMesh> surface{};
  /// Two references are equal when they name the same file (the triangles follow from it).
  bool operator==(const MeshFile& other) const { return file == other.file; }
};

using Shape = std::variant<Box, Sphere, MeshFile>;

/// An initial region of liquid.
struct LiquidRegion {
  Shape shape;
  Vec3 velocity{};  ///< initial velocity [m/s]
  bool operator==(const LiquidRegion&) const = default;
};

/// A liquid source: a disk nozzle emitting along its normal.
struct Emitter {
  Vec3 center{};        ///< [m]
  Vec3 normal{};        ///< unit vector (normalised by the parser)
  double radius = 0.0;  ///< [m], > 0
  double speed = 0.0;   ///< [m/s], > 0
  double start = 0.0;   ///< [s]
  double end = 0.0;     ///< [s], > start
  bool operator==(const Emitter&) const = default;
};

/// A key of a kinematic solid's path: translation at a time (linear in between).
struct PathKey {
  double time = 0.0;  ///< [s], strictly increasing along the path
  Vec3 translate{};   ///< [m]
  bool operator==(const PathKey&) const = default;
};

/// A solid obstacle. The shape is scaled (about the origin), rotated (degrees about x, then y,
/// then z, about the shape's centre) and translated; then moved along its path, if any.
struct Solid {
  Shape shape;
  double scale = 1.0;            ///< [-], > 0
  Vec3 rotateDegrees{};          ///< [degrees] (boxes and meshes; e.g. a sloped floor)
  Vec3 translate{};              ///< [m]
  std::vector<PathKey> path;     ///< empty: static
  bool operator==(const Solid&) const = default;
};

/// The simulated box; its faces are solid walls except those listed open.
struct Domain {
  Vec3 min{}, max{};            ///< [m]
  double cell = 0.0;            ///< cell size h [m], > 0
  /// Open faces, in the order −x, +x, −y, +y, −z, +z: liquid leaving there is deleted.
  std::array<bool, 6> open{};
  bool operator==(const Domain&) const = default;
};

struct TimeSettings {
  double duration = 0.0;  ///< simulated time [s], > 0
  double fps = 30.0;      ///< frames per second of the output, > 0
  double cfl = 1.0;       ///< substep CFL number (cells a particle may travel per substep), > 0
  bool operator==(const TimeSettings&) const = default;
};

/// How velocity moves between particles and grid.
enum class TransferScheme {
  Apic,  ///< affine particle-in-cell (Jiang et al. 2015). Default.
  Flip,  ///< FLIP/PIC blend (Zhu & Bridson 2005) with `flipRatio`
};

/// Numerical settings of the liquid solver (the scene's optional "solver" block).
/// The liquid surface the pressure solve sees (docs/solver.md, step 4).
enum class SurfaceMethod {
  Particles,  ///< re-derived from the particles every substep (Zhu & Bridson 2005)
  LevelSet,   ///< a grid level set carried with the liquid and held to the particles
};

struct SolverSettings {
  TransferScheme transfer = TransferScheme::Apic;
  double flipRatio = 0.95;        ///< FLIP share of the FLIP/PIC blend [-], 0 … 1
  int particlesPerCell = 8;       ///< seeding density (jittered), 1 … 64
  double pressureTolerance = 1e-6;  ///< relative residual of the pressure solve
  int maxPressureIterations = 1000;
  SurfaceMethod surface = SurfaceMethod::LevelSet;
  bool operator==(const SolverSettings&) const = default;
};

/// Substeps one frame may take (docs/scene.md, "Substeps"): a scene whose fastest possible speed
/// needs more is refused when it is read (io/scene_file.cpp), and FluidSolver::advanceTo stops a
/// frame that reaches it (a CFL of 1e-12 or an emitter at 10⁶ m/s would make a frame that never
/// ends). A rule of the scene, so it lives with the record.
inline constexpr int kMaxSubstepsPerFrame = 10000;

/// What the liquid solver reads of a scene.
struct FluidScene {
  Domain domain;
  Vec3 gravity{0.0, -9.81, 0.0};  ///< [m/s²]
  TimeSettings time;
  std::uint64_t seed = 1;
  std::vector<LiquidRegion> liquid;
  std::vector<Emitter> emitters;
  std::vector<Solid> solids;
  SolverSettings solver;
  bool operator==(const FluidScene&) const = default;

  /// The grid of the domain: cells = round((max − min)/cell) per axis.
  GridGeometry grid() const;
};

}  // namespace fluidsound::sim
