// sim/scene.h — a scene (`fluidsound.scene/1`, DESIGN.md; docs/scene.md) as value types: what
// the simulation reads (the liquid solver's part, sim/fluid/fluid_scene.h, and the bubble model's)
// and what the later stages read (listeners, audio rate). io/scene_file.h parses and validates the
// JSON into these records.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sim/bubbles/bubble_settings.h"
#include "sim/core/solid_material.h"
#include "sim/fluid/fluid_scene.h"

namespace fluidsound::sim {

/// How a head is turned (docs/binaural.md): where its nose points and where its top is.
struct HeadOrientation {
  Vec3 facing{};  ///< any length > 0
  Vec3 up{};      ///< any length > 0, not parallel to facing
  bool operator==(const HeadOrientation&) const = default;
};

/// A listener: one output channel, or two (left and right ear) when it is a head.
struct Listener {
  std::string name;
  Vec3 position{};  ///< [m]; a head's centre
  std::optional<HeadOrientation> head;  ///< a binaural head, heard through the scene's HRTF set
  bool operator==(const Listener&) const = default;
};

/// The acoustic transfer model the transfer stage uses (docs/transfer.md).
enum class TransferModel {
  Geometric,  ///< each frame's real liquid and solids, by reciprocity
  Image,      ///< image source under a locally flat surface, no solids (the default for now:
              ///< docs/transfer.md, "Choosing the model", says why)
};

/// The geometric model's air side (docs/transfer.md, "The air side").
enum class AirModel {
  RigidSurface,  ///< free field doubled by a rigid liquid surface, nothing in the way
  Wave,          ///< a wave solve of the air with the frame's liquid and solids in place
};

/// The scene's optional "transfer" block (docs/scene.md). The numbers apply to the geometric
/// model; empty means the model's own default (acoustics::GeometricTransferOptions), which the
/// record does not repeat. The ranges are checked where the block is read (io/scene_file.cpp).
struct TransferSettings {
  TransferModel model = TransferModel::Image;
  std::optional<int> maxBands;       ///< upper limit of bands per frame, 2 … 4096
  std::optional<double> maxFrequency;  ///< [Hz], (0, 100000]; empty: the grid's limit c_a/(4h)
  std::optional<double> lossFactor;  ///< η of the water's k_w² = (ω/c_w)²(1 − iη), (0, 0.1]
  AirModel air = AirModel::RigidSurface;
  std::optional<double> airInterval;  ///< [s] between the wave air side's solves, (0, 10]
  std::optional<double> airCell;      ///< [m] the wave air side's cell, (0, 0.1]
  bool operator==(const TransferSettings&) const = default;
};

/// A rigid body that moves under gravity and contacts and sounds (docs/scene.md, "bodies";
/// docs/solids.md): its shape where it is at t = 0, placed as a solid's.
struct SceneBody {
  std::string name;               ///< for messages and reports; default "body N"
  Shape shape;                    ///< box, sphere or mesh, as a solid's
  double scale = 1.0;             ///< [-], > 0 (meshes)
  Vec3 rotateDegrees{};           ///< [degrees] about x, y, z (boxes and meshes)
  Vec3 translate{};               ///< [m] (meshes)
  std::string materialName;       ///< the table's name, or empty when given as numbers
  SolidMaterial material;         ///< its constants (the table's, or the scene's own)
  bool isStatic = false;          ///< fixed in place (a table, a floor); it still sounds
  Vec3 velocity{};                ///< initial [m/s]
  Vec3 angularVelocity{};         ///< initial [rad/s]
  double friction = 0.5;          ///< Coulomb μ, ≥ 0 (the pair's is the product)
  double restitution = 0.3;       ///< e in [0, 1] (the pair's is the product)
  int resolution = 32;            ///< voxels along its longest side, for its modes
  bool operator==(const SceneBody&) const = default;
};

/// Recorded collision sounds of one pair of materials, for the sample-playback baseline
/// (`run --solids samples`; docs/solids.md, "Sample playback in run").
struct CollisionSamples {
  /// the two materials' table names (in either order), or "domain" for the domain's walls
  std::array<std::string, 2> materials;
  /// the recordings (WAV or FLAC), resolved against the scene file's folder; empty: none
  std::filesystem::path impact, slide, roll;
  double peakPascals = 1.0;  ///< [Pa] of a full-scale sample 1 m from the pair's loudest event
  bool operator==(const CollisionSamples&) const = default;
};

/// A whole scene: the fluid's part and the rest.
struct Scene : FluidScene {
  std::filesystem::path file;       ///< the scene file (for messages); paths inside are resolved
  std::vector<Listener> listeners;  ///< default: one listener 0.5 m above the domain centre
  double sampleRate = 48000.0;      ///< [Hz], the "audio" block
  std::optional<std::filesystem::path> hrtf;  ///< the heads' SOFA file ("audio.hrtf"); default MIT KEMAR
  BubbleSettings bubbles;           ///< the "bubbles" block (docs/bubbles.md); defaults if absent
  TransferSettings transfer;        ///< the "transfer" block; defaults if absent
  std::vector<SceneBody> bodies;    ///< the "bodies" array (docs/solids.md); none if absent
  std::vector<CollisionSamples> collisionSamples;  ///< the "collision_samples" array; none if absent
  bool operator==(const Scene&) const = default;
};

}  // namespace fluidsound::sim
