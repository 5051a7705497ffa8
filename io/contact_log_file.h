// io/contact_log_file.h — the rigid-body stage's contact log on disk, `contacts.bin`
// (`fluidsound.contacts/1`; docs/solids.md, Contact log): sim::ContactLog
// (sim/core/contact_record.h) bit for bit. Binary and little-endian whatever this machine's byte
// order (an exchange format between the stages, unlike the modal cache); every field is read as it
// is checked, and an error names the file, the field as a JSON-like path (`bodies[1].mass`,
// `records[12].normal`), what was expected and what was found.
//
// The layout, in order (u8/u32/u64/i32: unsigned/signed integers; f64: IEEE 754 binary64):
//
//   magic          the 22 bytes `fluidsound.contacts/1\n`
//   bodies         u32 body count (at most 4096)
//   substep        f64, finite, in (0, 1e-3] [s]
//   duration       f64, finite, >= 0 [s]
//   per body:      u32 name length (at most 1024) + the name's UTF-8 bytes; f64 mass [kg] (finite,
//                  >= 0, 0 if and only if static); u8 isStatic (0 or 1); f64 contactRadius [m]
//                  (finite, > 0)
//   records        u64 record count (the rest of the file must be exactly count × 236 bytes)
//   per record, 236 bytes, the fields of sim::ContactRecord in declaration order:
//                  f64 time; i32 bodyA; i32 bodyB; 3×f64 position; 3×f64 normal; f64 normalImpulse;
//                  3×f64 frictionImpulse; f64 normalSpeed; f64 tangentialSpeed; f64 rollingRate;
//                  i32 lifetime; 3×f64 localPointA; 3×f64 localPointB; 4×f64 orientationA
//                  (w, x, y, z); 4×f64 orientationB
//
// A record's checks: every f64 finite; time >= 0, not before the record before, and at most
// duration + substep; bodyA in [0, bodies); bodyB in (bodyA, bodies), or in [−6, −1] for a wall of
// the domain; normal of unit length within 1e-6; normalImpulse, tangentialSpeed and rollingRate
// >= 0 (normalSpeed is signed: negative while the surfaces separate); lifetime >= 1; orientations
// unit quaternions within 1e-6; among the records of one time, (bodyA, bodyB) non-decreasing.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "sim/core/contact_record.h"

namespace fluidsound::io {

/// The format's first bytes.
inline constexpr std::string_view kContactLogMagic = "fluidsound.contacts/1\n";
/// At most this many bodies, and this many bytes in a body's name.
inline constexpr std::size_t kMaxContactLogBodies = 4096;
inline constexpr std::size_t kMaxContactLogNameBytes = 1024;
/// The bytes of one record in the file.
inline constexpr std::size_t kContactRecordBytes = 236;

/// The bytes of `log` as a fluidsound.contacts/1 file (nothing is checked: see writeContactLog).
std::string encodeContactLog(const sim::ContactLog& log);

/// @brief The log in `bytes`; `file` only names it in errors.
/// @throws InputError(file, field, expected, found) naming the first problem, its field as a path
///         such as `records[12].normal` or `bodies[1].mass`; a record count the remaining bytes
///         cannot hold is refused before anything is allocated for it
sim::ContactLog decodeContactLog(std::string_view bytes, const std::string& file);

/// @brief Reads and decodes a contact log file.
/// @throws InputError if the file is missing, not a regular file or unreadable, or as
///         decodeContactLog
sim::ContactLog readContactLog(const std::filesystem::path& file);

/// @brief Writes `log` atomically (temporary file beside it, then rename), only onto a regular file
///        (or a symlink's regular target) or a new name.
/// @throws OutputError if it cannot be written, or the path is a folder, a FIFO, a device or
///         anything else that is not a regular file (left alone)
/// @throws std::invalid_argument if `log` breaks the format (decodeContactLog would refuse it): the
///         message is that InputError's; nothing is written
void writeContactLog(const std::filesystem::path& file, const sim::ContactLog& log);

}  // namespace fluidsound::io
