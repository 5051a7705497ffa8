// io/cache_file.h — `fluidsound.cache/1` (issue 21; docs/import.md): what a liquid simulated
// elsewhere (Houdini, Blender, or `fluidsound simulate` itself) cannot say in its OpenVDB frames —
// where they are, their rate, their grids' names, units and up axis — and the scene's sound part
// (solids, listeners, audio, bubbles, transfer), read and validated like a scene.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "io/cache_frame.h"
#include "sim/scene.h"

namespace fluidsound::io {

/// The axis that points up in a cache's frames.
enum class UpAxis { Y, Z };

/// The box a cache's liquid was simulated in (Houdini's FLIP container, Blender's fluid domain,
/// `fluidsound simulate`'s domain), in fluidsound's frame [m, y up]: the import's grid ends at it
/// and its closed faces are walls, as the solver's domain is.
struct Container {
  Vec3 min{}, max{};
  std::array<bool, 6> open{};  ///< −x, +x, −y, +y, −z, +z
};

/// A parsed cache file.
struct CacheDescription {
  std::filesystem::path file;       ///< the cache file (for messages); paths inside are relative to its folder
  std::string frames;               ///< the frames' pattern (io/frame_sequence.h), as given
  double fps = 0.0;                 ///< frames per second
  CacheGridNames grids;             ///< the names the frames' grids are looked for under
  double metresPerUnit = 1.0;       ///< the frames' length unit [m] (0.01 for centimetres)
  UpAxis up = UpAxis::Y;            ///< Houdini and fluidsound: y; Blender: z
  std::optional<std::string> particles;  ///< the particles' pattern (PLY or OpenVDB points), if any
  std::optional<Container> container;    ///< none: the frames' liquid bounds the grid, no walls
  /// The sound part, read by the scene rules (docs/scene.md): solids, listeners, audio, bubbles,
  /// transfer, seed. Its domain and time are stand-ins (a 1 m box, 1 s): the frames will give them
  /// when the import stage reads them (issue 21, not built yet; docs/import.md).
  sim::Scene scene;
  bool defaultListener = true;      ///< no `listeners` given: one above the liquid, once it is known
};

/// @brief Parses a `fluidsound.cache/1` document; `file` names it in errors and is the folder
///        paths are relative to.
/// @throws InputError naming the file, the field (JSON path) and what was expected: a wrong format
///         tag, an unknown key, `frames` or `fps` missing or out of range, grid names that are not
///         non-empty strings, `units.metres_per_unit` not positive, `units.up` not "y" or "z", or
///         any scene field as a scene would have it
CacheDescription parseCacheFile(std::string_view text, const std::filesystem::path& file);

/// @brief Reads and parses a cache file.
/// @throws InputError if it is missing, not a regular file or unreadable, or as parseCacheFile
CacheDescription readCacheFile(const std::filesystem::path& file);

}  // namespace fluidsound::io
