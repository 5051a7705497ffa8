// tests/io/scene_field_errors_test.cpp — `fluidsound.scene/1`, field by field (docs/scene.md,
// "Fields"): every field of the contract given with a wrong type, out of range or, where required,
// absent is rejected with one line naming the file, the exact JSON path and what was expected.
// One table row per field and kind of mistake, each a change to the valid fullScene(); the cases
// already in scene_file_errors_test.cpp are not repeated here.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "io/scene_documents.h"

namespace fluidsound::io {
namespace {

using namespace scene_test;

/// One bad field: withChange(fullScene(), pointer, value) must be rejected with exactly
/// `tank.json: FIELD: expected EXPECTED, found FOUND`.
struct FieldCase {
  const char* name;      ///< test name suffix
  const char* pointer;   ///< JSON pointer (RFC 6901) into fullScene()
  const char* value;     ///< JSON text replacing (or adding) the value there, or kRemove
  std::string field;     ///< the JSON path the error must name
  std::string expected;  ///< what the message says was expected
  std::string found;     ///< what the message says was found
};

/// `value` that removes the key.
constexpr const char* kRemove = nullptr;

/// `found` for an absent required key.
const std::string kRequired = "nothing (required)";
const std::string kMeshPath =
    "the path of a readable mesh file (OBJ or PLY; relative to the scene file's folder)";

/// `expected` for an [x, y, z] vector in `unit`.
std::string vector3(const std::string& unit) {
  return "an array of 3 numbers [x, y, z] (" + unit + ")";
}

const std::vector<FieldCase> kFieldCases = {
    // ---- format ---------------------------------------------------------------------------------
    {"format_number", "/format", "1", "format", R"("fluidsound.scene/1")", "1"},
    {"format_null", "/format", "null", "format", R"("fluidsound.scene/1")", "null"},
    {"format_other_version", "/format", R"("fluidsound.scene/2")", "format",
     R"("fluidsound.scene/1")", R"("fluidsound.scene/2")"},

    // ---- domain ---------------------------------------------------------------------------------
    {"domain_array", "/domain", "[0, 0, 0]", "domain", "an object with min, max and cell",
     "an array of 3 values"},
    {"domain_min_missing", "/domain/min", kRemove, "domain.min", vector3("metres"), kRequired},
    {"domain_min_string", "/domain/min", R"("origin")", "domain.min", vector3("metres"),
     R"("origin")"},
    {"domain_min_two_values", "/domain/min", "[0, 0]", "domain.min", vector3("metres"),
     "an array of 2 values"},
    {"domain_min_component_string", "/domain/min/0", R"("0")", "domain.min[0]", "a number (metres)",
     R"("0")"},
    {"domain_max_missing", "/domain/max", kRemove, "domain.max", vector3("metres"), kRequired},
    {"domain_max_object", "/domain/max", "{}", "domain.max", vector3("metres"), "an object"},
    {"domain_max_component_bool", "/domain/max/2", "true", "domain.max[2]", "a number (metres)",
     "true"},
    {"domain_max_equal_to_min_x", "/domain/max/0", "0", "domain.max[0]",
     "a number > min[0] = 0.0 (metres)", "0"},
    {"domain_max_below_min_z", "/domain/max/2", "-0.1", "domain.max[2]",
     "a number > min[2] = 0.0 (metres)", "-0.1"},
    {"domain_cell_missing", "/domain/cell", kRemove, "domain.cell", "a number > 0 (metres)",
     kRequired},
    {"domain_cell_string", "/domain/cell", R"("0.005")", "domain.cell", "a number > 0 (metres)",
     R"("0.005")"},
    {"domain_cell_null", "/domain/cell", "null", "domain.cell", "a number > 0 (metres)", "null"},
    {"domain_open_object", "/domain/open", R"({"+y": true})", "domain.open",
     R"(an array of face names from "-x", "+x", "-y", "+y", "-z", "+z")", "an object"},
    {"domain_open_item_number", "/domain/open/0", "3", "domain.open[0]",
     R"(one of "-x", "+x", "-y", "+y", "-z", "+z")", "3"},
    {"domain_open_item_upper_case", "/domain/open/1", R"("-X")", "domain.open[1]",
     R"(one of "-x", "+x", "-y", "+y", "-z", "+z")", R"("-X")"},

    // ---- gravity --------------------------------------------------------------------------------
    // ---- bubbles: lengths in cells and the rate, bounded (1e308 crashed and hung the model)
    // ------
    {"bubbles_band_cells_huge", "/bubbles", R"({"band_cells": 1e308})", "bubbles.band_cells",
     "a number > 0 and <= 64 (cells)", "1e+308"},
    {"bubbles_entrainment_depth_cells_huge", "/bubbles", R"({"entrainment_depth_cells": 1e308})",
     "bubbles.entrainment_depth_cells", "a number > 0 and <= 64 (cells)", "1e+308"},
    {"bubbles_jitter_cells_huge", "/bubbles", R"({"jitter_cells": 65})", "bubbles.jitter_cells",
     "a number >= 0 and <= 64 (cells)", "65"},
    {"bubbles_rate_huge", "/bubbles", R"({"rate": 1e308})", "bubbles.rate",
     "a number >= 0 and <= 10000 (creation attempts per second per unit potential)", "1e+308"},
    {"gravity_huge", "/gravity", "[0, -1e30, 0]", "gravity",
     "an acceleration of at most 1000 m/s^2 (about 100 g)", "|g| = 1e+30 m/s^2"},
    {"gravity_string", "/gravity", R"("down")", "gravity", vector3("m/s^2"), R"("down")"},
    {"gravity_four_values", "/gravity", "[0, -9.8, 0, 0]", "gravity", vector3("m/s^2"),
     "an array of 4 values"},
    {"gravity_empty", "/gravity", "[]", "gravity", vector3("m/s^2"), "an empty array"},
    {"gravity_component_string", "/gravity/1", R"("-9.8")", "gravity[1]", "a number (m/s^2)",
     R"("-9.8")"},

    // ---- time -----------------------------------------------------------------------------------
    {"time_number", "/time", "2.0", "time", "an object with duration (seconds)", "2.0"},
    {"time_duration_missing", "/time/duration", kRemove, "time.duration", "a number > 0 (seconds)",
     kRequired},
    {"time_duration_zero", "/time/duration", "0", "time.duration", "a number > 0 (seconds)", "0"},
    {"time_duration_string", "/time/duration", R"("2")", "time.duration", "a number > 0 (seconds)",
     R"("2")"},
    {"time_too_many_frames", "/time/duration", "1e300", "time", "duration × fps ≤ 1000000 frames",
     "6e+301 frames"},
    {"time_fps_negative", "/time/fps", "-30", "time.fps",
     "a number > 0 and <= 1000 (frames per second)", "-30"},
    {"time_fps_string", "/time/fps", R"("60")", "time.fps",
     "a number > 0 and <= 1000 (frames per second)", R"("60")"},
    {"time_fps_above_limit", "/time/fps", "44100.5", "time.fps",
     "a number > 0 and <= 1000 (frames per second)", "44100.5"},
    {"time_cfl_zero", "/time/cfl", "0", "time.cfl", "a number > 0 (cells per substep)", "0"},
    {"time_cfl_negative", "/time/cfl", "-1", "time.cfl", "a number > 0 (cells per substep)", "-1"},
    {"time_cfl_string", "/time/cfl", R"("1")", "time.cfl", "a number > 0 (cells per substep)",
     R"("1")"},
    {"time_cfl_tiny", "/time/cfl", "1e-12", "time.cfl",
     "at most 10000 substeps per frame (fastest speed / (time.cfl × domain.cell × time.fps))",
     "2.05e+13 substeps: up to 6.144 m/s (2 from emitters and liquid velocity, 4.144 from gravity "
     "over the domain) / "
     "(1e-12 × 0.005 m × 60 fps)"},
    {"time_fps_tiny", "/time/fps", "0.001", "time.fps",
     "at most 10000 substeps per frame (fastest speed / (time.cfl × domain.cell × time.fps))",
     "4.91e+05 substeps: up to 6.144 m/s (2 from emitters and liquid velocity, 4.144 from gravity "
     "over the domain) / "
     "(2.5 × 0.005 m × 0.001 fps)"},
    {"time_duration_audio_too_long", "/time", R"({"duration": 30000, "fps": 30})", "time.duration",
     "a duration whose audio (duration × audio.sample_rate × channels) is at most 2^31 samples",
     "30000 s × 44100 Hz × 2 = 2.646e+09 samples"},
    {"time_unknown_key", "/time/frame_rate", "30", "time.frame_rate", "one of duration, fps, cfl",
     "an unknown key"},

    // ---- seed -----------------------------------------------------------------------------------
    {"seed_above_2_to_the_64", "/seed", "18446744073709551616", "seed", "an integer >= 0",
     "1.8446744073709552e+19"},
    {"seed_null", "/seed", "null", "seed", "an integer >= 0", "null"},
    {"seed_bool", "/seed", "true", "seed", "an integer >= 0", "true"},

    // ---- liquid ---------------------------------------------------------------------------------
    {"liquid_object", "/liquid", "{}", "liquid", "an array of liquid regions", "an object"},
    {"liquid_item_string", "/liquid/0", R"("box")", "liquid[0]",
     "an object with one of box, sphere or mesh", R"("box")"},
    {"liquid_box_array", "/liquid/0/box", "[0, 0, 0]", "liquid[0].box",
     "an object with min and max (metres)", "an array of 3 values"},
    {"liquid_box_min_missing", "/liquid/0/box/min", kRemove, "liquid[0].box.min", vector3("metres"),
     kRequired},
    {"liquid_box_max_missing", "/liquid/0/box/max", kRemove, "liquid[0].box.max", vector3("metres"),
     kRequired},
    {"liquid_box_min_two_values", "/liquid/0/box/min", "[0, 0]", "liquid[0].box.min",
     vector3("metres"), "an array of 2 values"},
    {"liquid_box_max_component_string", "/liquid/0/box/max/2", R"("0.1")", "liquid[0].box.max[2]",
     "a number (metres)", R"("0.1")"},
    {"liquid_box_max_equal_to_min_x", "/liquid/0/box/max/0", "0", "liquid[0].box.max[0]",
     "a number > min[0] = 0.0 (metres)", "0"},
    {"liquid_box_unknown_key", "/liquid/0/box/size", "1", "liquid[0].box.size", "one of min, max",
     "an unknown key"},
    {"liquid_sphere_number", "/liquid/1/sphere", "0.02", "liquid[1].sphere",
     "an object with center and radius (metres)", "0.02"},
    {"liquid_sphere_center_missing", "/liquid/1/sphere/center", kRemove, "liquid[1].sphere.center",
     vector3("metres"), kRequired},
    {"liquid_sphere_center_two_values", "/liquid/1/sphere/center", "[0.3, 0.05]",
     "liquid[1].sphere.center", vector3("metres"), "an array of 2 values"},
    {"liquid_sphere_radius_missing", "/liquid/1/sphere/radius", kRemove, "liquid[1].sphere.radius",
     "a number > 0 (metres)", kRequired},
    {"liquid_sphere_radius_zero", "/liquid/1/sphere/radius", "0", "liquid[1].sphere.radius",
     "a number > 0 (metres)", "0"},
    {"liquid_sphere_radius_string", "/liquid/1/sphere/radius", R"("0.02")",
     "liquid[1].sphere.radius", "a number > 0 (metres)", R"("0.02")"},
    {"liquid_sphere_unknown_key", "/liquid/1/sphere/centre", "[0, 0, 0]", "liquid[1].sphere.centre",
     "one of center, radius (did you mean 'center'?)", "an unknown key"},
    {"liquid_mesh_number", "/liquid/0", R"({"mesh": 7})", "liquid[0].mesh", kMeshPath, "7"},
    {"liquid_mesh_empty", "/liquid/0", R"({"mesh": ""})", "liquid[0].mesh", kMeshPath, R"("")"},
    {"liquid_velocity_huge", "/liquid/1/velocity", "[0, -1e6, 0]", "liquid[1].velocity",
     "a velocity of at most 1000 m/s (two thirds of the speed of sound in water)",
     "|v| = 1000000.0 m/s"},
    {"liquid_velocity_two_values", "/liquid/1/velocity", "[0, -2]", "liquid[1].velocity",
     vector3("m/s"), "an array of 2 values"},
    {"liquid_velocity_string", "/liquid/1/velocity", R"("down")", "liquid[1].velocity",
     vector3("m/s"), R"("down")"},
    {"liquid_velocity_component_null", "/liquid/1/velocity/1", "null", "liquid[1].velocity[1]",
     "a number (m/s)", "null"},
    {"liquid_unknown_key", "/liquid/1/velocty", "[0, 0, 0]", "liquid[1].velocty",
     "one of box, sphere, mesh, velocity (did you mean 'velocity'?)", "an unknown key"},

    // ---- emitters -------------------------------------------------------------------------------
    {"emitters_object", "/emitters", "{}", "emitters", "an array of emitters", "an object"},
    {"emitter_item_array", "/emitters/0", "[]", "emitters[0]", "an object with disk and speed",
     "an empty array"},
    {"emitter_disk_missing", "/emitters/0/disk", kRemove, "emitters[0].disk",
     "an object with center, normal and radius", kRequired},
    {"emitter_disk_string", "/emitters/0/disk", R"("nozzle")", "emitters[0].disk",
     "an object with center, normal and radius", R"("nozzle")"},
    {"emitter_disk_center_missing", "/emitters/0/disk/center", kRemove, "emitters[0].disk.center",
     vector3("metres"), kRequired},
    {"emitter_disk_center_four_values", "/emitters/0/disk/center", "[0.3, 0.25, 0.05, 1]",
     "emitters[0].disk.center", vector3("metres"), "an array of 4 values"},
    {"emitter_disk_center_component_string", "/emitters/0/disk/center/0", R"("0.3")",
     "emitters[0].disk.center[0]", "a number (metres)", R"("0.3")"},
    {"emitter_disk_normal_missing", "/emitters/0/disk/normal", kRemove, "emitters[0].disk.normal",
     vector3("a direction, any length"), kRequired},
    {"emitter_disk_normal_string", "/emitters/0/disk/normal", R"("down")",
     "emitters[0].disk.normal", vector3("a direction, any length"), R"("down")"},
    {"emitter_disk_normal_component_null", "/emitters/1/disk/normal/2", "null",
     "emitters[1].disk.normal[2]", "a number (a direction, any length)", "null"},
    {"emitter_disk_radius_missing", "/emitters/0/disk/radius", kRemove, "emitters[0].disk.radius",
     "a number > 0 (metres)", kRequired},
    {"emitter_disk_radius_negative", "/emitters/0/disk/radius", "-0.004", "emitters[0].disk.radius",
     "a number > 0 (metres)", "-0.004"},
    {"emitter_disk_radius_zero", "/emitters/0/disk/radius", "0", "emitters[0].disk.radius",
     "a number > 0 (metres)", "0"},
    {"emitter_disk_radius_string", "/emitters/0/disk/radius", R"("4mm")", "emitters[0].disk.radius",
     "a number > 0 (metres)", R"("4mm")"},
    {"emitter_disk_radius_beyond_domain", "/emitters/0/disk/radius", "7.0",
     "emitters[0].disk.radius", "a number > 0 and at most the domain's diagonal, 0.678233 (metres)",
     "7.0"},
    {"emitter_disk_center_far_outside", "/emitters/0/disk/center/1", "1e308",
     "emitters[0].disk.center",
     "a disk that meets the domain [0, 0, 0] to [0.6, 0.3, 0.1] (metres; the disk of radius 0.004 "
     "lies "
     "wholly outside it)",
     "[0.3, 1e+308, 0.05]"},
    {"emitter_disk_center_just_outside", "/emitters/1/disk/center/2", "-0.0013",
     "emitters[1].disk.center",
     "a disk that meets the domain [0, 0, 0] to [0.6, 0.3, 0.1] (metres; the disk of radius 0.002 "
     "lies "
     "wholly outside it)",
     "[0.1, 0.25, -0.0013]"},
    {"emitter_disk_unknown_key", "/emitters/0/disk/diameter", "0.008", "emitters[0].disk.diameter",
     "one of center, normal, radius", "an unknown key"},
    {"emitter_speed_zero", "/emitters/0/speed", "0", "emitters[0].speed",
     "a number > 0 and <= 1000 (m/s; two thirds of the speed of sound in water)", "0"},
    {"emitter_speed_negative", "/emitters/1/speed", "-0.5", "emitters[1].speed",
     "a number > 0 and <= 1000 (m/s; two thirds of the speed of sound in water)", "-0.5"},
    {"emitter_speed_string", "/emitters/0/speed", R"("fast")", "emitters[0].speed",
     "a number > 0 and <= 1000 (m/s; two thirds of the speed of sound in water)", R"("fast")"},
    {"emitter_speed_huge", "/emitters/0/speed", "1e6", "emitters[0].speed",
     "a number > 0 and <= 1000 (m/s; two thirds of the speed of sound in water)", "1000000.0"},
    {"emitter_start_negative", "/emitters/0/start", "-0.1", "emitters[0].start",
     "a number >= 0 (seconds)", "-0.1"},
    {"emitter_start_string", "/emitters/0/start", R"("0")", "emitters[0].start",
     "a number >= 0 (seconds)", R"("0")"},
    {"emitter_end_before_start", "/emitters/0/end", "0.1", "emitters[0].end",
     "a number > start = 0.25 (seconds)", "0.1"},
    {"emitter_end_zero_with_default_start", "/emitters/1/end", "0", "emitters[1].end",
     "a number > start = 0.0 (seconds)", "0"},
    {"emitter_end_string", "/emitters/0/end", R"("1.5")", "emitters[0].end",
     "a number > start = 0.25 (seconds)", R"("1.5")"},
    {"emitter_end_null", "/emitters/0/end", "null", "emitters[0].end",
     "a number > start = 0.25 (seconds)", "null"},
    {"emitter_unknown_key", "/emitters/0/velocity", "[0, -1, 0]", "emitters[0].velocity",
     "one of disk, speed, start, end", "an unknown key"},

    // ---- solids ---------------------------------------------------------------------------------
    {"solids_string", "/solids", R"("glass")", "solids", "an array of solids", R"("glass")"},
    {"solid_item_number", "/solids/0", "1", "solids[0]",
     "an object with one of box, sphere or mesh", "1"},
    {"solid_without_shape", "/solids/0", R"({"scale": 2})", "solids[0]",
     "exactly one shape: box, sphere or mesh", "none of them"},
    {"solid_two_shapes", "/solids/1/box", R"({"min": [0, 0, 0], "max": [1, 1, 1]})", "solids[1]",
     "exactly one shape: box, sphere or mesh", "box and sphere"},
    {"solid_box_min_missing", "/solids/0/box/min", kRemove, "solids[0].box.min", vector3("metres"),
     kRequired},
    {"solid_box_max_equal_to_min_y", "/solids/0/box/max/1", "0", "solids[0].box.max[1]",
     "a number > min[1] = 0.0 (metres)", "0"},
    {"solid_sphere_center_string", "/solids/1/sphere/center", R"("c")", "solids[1].sphere.center",
     vector3("metres"), R"("c")"},
    {"solid_sphere_radius_zero", "/solids/1/sphere/radius", "0", "solids[1].sphere.radius",
     "a number > 0 (metres)", "0"},
    {"solid_mesh_number", "/solids/0", R"({"mesh": 3})", "solids[0].mesh", kMeshPath, "3"},
    {"solid_mesh_absent_file", "/solids/0", R"({"mesh": "fluidsound-no-such-glass.obj"})",
     "solids[0].mesh", kMeshPath,
     R"("fluidsound-no-such-glass.obj" (fluidsound-no-such-glass.obj: no such file))"},
    {"solid_scale_negative", "/solids/0/scale", "-2", "solids[0].scale",
     "a number > 0 (scale factor)", "-2"},
    {"solid_scale_string", "/solids/0/scale", R"("2")", "solids[0].scale",
     "a number > 0 (scale factor)", R"("2")"},
    {"solid_scale_vector", "/solids/0/scale", "[2, 2, 2]", "solids[0].scale",
     "a number > 0 (scale factor)", "an array of 3 values"},
    {"solid_rotate_two_values", "/solids/0/rotate", "[0, 15]", "solids[0].rotate",
     vector3("degrees about x, y, z"), "an array of 2 values"},
    {"solid_rotate_number", "/solids/0/rotate", "15", "solids[0].rotate",
     vector3("degrees about x, y, z"), "15"},
    {"solid_rotate_component_string", "/solids/0/rotate/2", R"("15")", "solids[0].rotate[2]",
     "a number (degrees about x, y, z)", R"("15")"},
    {"solid_translate_four_values", "/solids/0/translate", "[0.01, 0, 0, 0]", "solids[0].translate",
     vector3("metres"), "an array of 4 values"},
    {"solid_translate_string", "/solids/0/translate", R"("x")", "solids[0].translate",
     vector3("metres"), R"("x")"},
    {"solid_translate_component_null", "/solids/0/translate/0", "null", "solids[0].translate[0]",
     "a number (metres)", "null"},
    {"solid_path_object", "/solids/1/path", "{}", "solids[1].path",
     "an array of keys {t (seconds), translate (metres)}", "an object"},
    {"solid_path_key_number", "/solids/1/path/0", "0.0", "solids[1].path[0]",
     "an object with t (seconds) and translate (metres)", "0.0"},
    {"solid_path_t_missing", "/solids/1/path/0/t", kRemove, "solids[1].path[0].t",
     "a number >= 0 (seconds)", kRequired},
    {"solid_path_t_negative", "/solids/1/path/0/t", "-0.1", "solids[1].path[0].t",
     "a number >= 0 (seconds)", "-0.1"},
    {"solid_path_t_string", "/solids/1/path/0/t", R"("0")", "solids[1].path[0].t",
     "a number >= 0 (seconds)", R"("0")"},
    {"solid_path_t_equal_to_previous", "/solids/1/path/1/t", "0.0", "solids[1].path[1].t",
     "a time greater than path[0].t = 0.0 (keys in time order; seconds)", "0.0"},
    {"solid_path_translate_missing", "/solids/1/path/1/translate", kRemove,
     "solids[1].path[1].translate", vector3("metres"), kRequired},
    {"solid_path_translate_two_values", "/solids/1/path/1/translate", "[0, -0.15]",
     "solids[1].path[1].translate", vector3("metres"), "an array of 2 values"},
    {"solid_path_translate_component_string", "/solids/1/path/1/translate/1", R"("-0.15")",
     "solids[1].path[1].translate[1]", "a number (metres)", R"("-0.15")"},
    {"solid_path_unknown_key", "/solids/1/path/0/time", "0", "solids[1].path[0].time",
     "one of t, translate", "an unknown key"},

    // ---- listeners ------------------------------------------------------------------------------
    {"listeners_object", "/listeners", R"({"name": "left"})", "listeners",
     "an array of 1 or more listeners {name, position}", "an object"},
    {"listener_item_string", "/listeners/0", R"("left")", "listeners[0]",
     "an object with name and position", R"("left")"},
    {"listener_name_missing", "/listeners/0/name", kRemove, "listeners[0].name",
     "a non-empty string (the channel's name)", kRequired},
    {"listener_name_number", "/listeners/1/name", "2", "listeners[1].name",
     "a non-empty string (the channel's name)", "2"},
    {"listener_position_missing", "/listeners/1/position", kRemove, "listeners[1].position",
     vector3("metres"), kRequired},
    {"listener_position_two_values", "/listeners/0/position", "[0.25, 0.4]",
     "listeners[0].position", vector3("metres"), "an array of 2 values"},
    {"listener_position_component_string", "/listeners/0/position/2", R"("0.3")",
     "listeners[0].position[2]", "a number (metres)", R"("0.3")"},
    {"listener_unknown_key", "/listeners/0/gain", "1", "listeners[0].gain", "one of name, position, head",
     "an unknown key"},

    // ---- audio ----------------------------------------------------------------------------------
    {"audio_number", "/audio", "48000", "audio", "an object with sample_rate (Hz)", "48000"},
    {"audio_sample_rate_string", "/audio/sample_rate", R"("48000")", "audio.sample_rate",
     "an integer from 8000 to 768000 (Hz)", R"("48000")"},
    {"audio_sample_rate_negative", "/audio/sample_rate", "-48000", "audio.sample_rate",
     "an integer from 8000 to 768000 (Hz)", "-48000"},
    {"audio_sample_rate_just_below", "/audio/sample_rate", "7999", "audio.sample_rate",
     "an integer from 8000 to 768000 (Hz)", "7999"},
    {"audio_sample_rate_just_above", "/audio/sample_rate", "768001", "audio.sample_rate",
     "an integer from 8000 to 768000 (Hz)", "768001"},
    {"audio_unknown_key", "/audio/sampleRate", "48000", "audio.sampleRate",
     "one of sample_rate, hrtf (did you mean 'sample_rate'?)", "an unknown key"},

    // ---- solver ---------------------------------------------------------------------------------
    {"solver_string", "/solver", R"("apic")", "solver", "an object of solver settings",
     R"("apic")"},
    {"solver_transfer_number", "/solver/transfer", "1", "solver.transfer", R"("apic" or "flip")",
     "1"},
    {"solver_transfer_empty", "/solver/transfer", R"("")", "solver.transfer", R"("apic" or "flip")",
     R"("")"},
    {"solver_flip_ratio_negative", "/solver/flip_ratio", "-0.1", "solver.flip_ratio",
     "a number from 0 to 1 (FLIP share of the FLIP/PIC blend)", "-0.1"},
    {"solver_flip_ratio_string", "/solver/flip_ratio", R"("0.9")", "solver.flip_ratio",
     "a number from 0 to 1 (FLIP share of the FLIP/PIC blend)", R"("0.9")"},
    {"solver_particles_per_cell_zero", "/solver/particles_per_cell", "0",
     "solver.particles_per_cell", "an integer from 1 to 64", "0"},
    {"solver_particles_per_cell_fraction", "/solver/particles_per_cell", "2.5",
     "solver.particles_per_cell", "an integer from 1 to 64", "2.5"},
    {"solver_particles_per_cell_string", "/solver/particles_per_cell", R"("8")",
     "solver.particles_per_cell", "an integer from 1 to 64", R"("8")"},
    {"solver_pressure_tolerance_zero", "/solver/pressure_tolerance", "0",
     "solver.pressure_tolerance", "a number > 0 and <= 0.01 (relative residual)", "0"},
    {"solver_pressure_tolerance_string", "/solver/pressure_tolerance", R"("1e-6")",
     "solver.pressure_tolerance", "a number > 0 and <= 0.01 (relative residual)", R"("1e-6")"},
    {"solver_max_pressure_iterations_above_int", "/solver/max_pressure_iterations", "2147483648",
     "solver.max_pressure_iterations", "an integer from 1 to 2147483647", "2147483648"},
    {"solver_max_pressure_iterations_fraction", "/solver/max_pressure_iterations", "10.5",
     "solver.max_pressure_iterations", "an integer from 1 to 2147483647", "10.5"},
    {"solver_max_pressure_iterations_string", "/solver/max_pressure_iterations", R"("1000")",
     "solver.max_pressure_iterations", "an integer from 1 to 2147483647", R"("1000")"},
    {"solver_surface_unknown", "/solver/surface", R"("grid")", "solver.surface",
     R"("particles" or "level_set")", R"("grid")"},
    {"solver_surface_number", "/solver/surface", "1", "solver.surface",
     R"("particles" or "level_set")", "1"},
    {"solver_unknown_key", "/solver/tolerance", "1e-6", "solver.tolerance",
     "one of transfer, surface, flip_ratio, particles_per_cell, pressure_tolerance, "
     "max_pressure_iterations",
     "an unknown key"},
};

/// gtest prints a failing row by its name.
void PrintTo(const FieldCase& row, std::ostream* out) { *out << row.name; }

class SceneField : public ::testing::TestWithParam<FieldCase> {};

TEST_P(SceneField, IsRejectedNamingFileFieldAndExpectation) {
  const FieldCase& row = GetParam();
  const InputError error = parseError(withChange(fullScene(), row.pointer, row.value).dump());
  expectError(error, row.field, row.expected + ", found " + row.found);
  EXPECT_EQ(error.expected(), row.expected);
  EXPECT_EQ(error.found(), row.found);
  EXPECT_EQ(std::string(error.what()),
            "tank.json: " + row.field + ": expected " + row.expected + ", found " + row.found);
}

INSTANTIATE_TEST_SUITE_P(SceneFieldErrors, SceneField, ::testing::ValuesIn(kFieldCases),
                         [](const ::testing::TestParamInfo<FieldCase>& info) {
                           return std::string(info.param.name);
                         });

// Each row changes one field of fullScene(), which must be valid as it stands.
TEST(SceneFieldErrors, BaseSceneIsValid) {
  EXPECT_NO_THROW(parseScene(fullScene().dump(), "tank.json"));
}

// Claim: the emitter's domain rule refuses only a disk wholly outside the domain: a tilted disk
// (normal [3, 0, 4], radius 2 mm, so 1.2 mm of half-width along z) centred 1.1 mm beyond the z = 0
// face still reaches into it and is accepted, as is a radius equal to the domain's diagonal and
// an fps of exactly 1000. Reference: docs/scene.md, emitters and time (the rows above refuse
// 1.3 mm beyond, a radius of 7 m and 44100.5 fps).
TEST(SceneFieldErrors, EmitterDiskReachingIntoTheDomainAndTheLimitsThemselvesAreAccepted) {
  nlohmann::json scene = fullScene();
  scene["emitters"][1]["disk"]["center"][2] = -0.0011;
  EXPECT_NO_THROW(parseScene(scene.dump(), "tank.json"));
  scene = fullScene();
  scene["emitters"][0]["disk"]["radius"] = std::hypot(0.6, 0.3, 0.1);
  EXPECT_NO_THROW(parseScene(scene.dump(), "tank.json"));
  scene = fullScene();
  scene["time"]["fps"] = 1000;
  scene["time"]["duration"] = 0.5;
  EXPECT_NO_THROW(parseScene(scene.dump(), "tank.json"));
}

}  // namespace
}  // namespace fluidsound::io
