// io/contact_log_file.cpp — `fluidsound.contacts/1` (see contact_log_file.h): written byte by byte
// in little-endian order, read back through a cursor that checks each field as it is read.
#include "io/contact_log_file.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "io/atomic_file.h"
#include "io/input_error.h"
#include "io/json_validation.h"

namespace fluidsound::io {
namespace {

using sim::ContactLog;
using sim::ContactLogBody;
using sim::ContactRecord;
using sim::Quaternion;

static_assert(sizeof(double) == 8 && std::numeric_limits<double>::is_iec559,
              "f64 is IEEE 754 binary64");

/// How far from 1 the length of a normal or an orientation may be.
constexpr double kUnitTolerance = 1e-6;
/// The largest substep the rigid-body stage takes [s].
constexpr double kMaxSubstep = 1e-3;
/// The walls of the domain box are bodyB = −1 … −6.
constexpr int kWallCount = 6;
/// A record's fields, as encodeContactLog writes them and RecordBytes reads them.
static_assert(kContactRecordBytes == 8 + 4 + 4 + 3 * 8 + 3 * 8 + 8 + 3 * 8 + 8 + 8 + 8 + 4 + 3 * 8 +
                                         3 * 8 + 4 * 8 + 4 * 8);

// ---- writing -----------------------------------------------------------------------------------

/// The `Size` little-endian bytes of `value` at `at`, whatever the host's byte order (compilers
/// make the loop one store on a little-endian host).
template <std::size_t Size>
void storeLittleEndian(char* at, std::uint64_t value) {
  for (std::size_t i = 0; i < Size; ++i) at[i] = static_cast<char>((value >> (8 * i)) & 0xffu);
}

/// The unsigned integer whose `Size` little-endian bytes are at `at`.
template <std::size_t Size>
std::uint64_t loadLittleEndian(const char* at) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < Size; ++i)
    value |= std::uint64_t{static_cast<unsigned char>(at[i])} << (8 * i);
  return value;
}

/// Writes values in little-endian order into a string of the file's exact size.
class LittleEndianWriter {
 public:
  explicit LittleEndianWriter(std::size_t size) : bytes_(size, '\0'), at_(bytes_.data()) {}
  void text(std::string_view text) {
    std::memcpy(at_, text.data(), text.size());
    at_ += text.size();
  }
  void u8(std::uint8_t value) { put<1>(value); }
  void u32(std::uint32_t value) { put<4>(value); }
  void u64(std::uint64_t value) { put<8>(value); }
  void i32(std::int32_t value) { u32(static_cast<std::uint32_t>(value)); }
  void f64(double value) { u64(std::bit_cast<std::uint64_t>(value)); }
  void vec3(const Vec3& v) {
    for (double c : v) f64(c);
  }
  void quaternion(const Quaternion& q) {
    for (double c : {q.w, q.x, q.y, q.z}) f64(c);
  }
  /// The bytes, every one written.
  std::string take() && {
    if (at_ != bytes_.data() + bytes_.size())
      throw std::logic_error("contact log: the bytes written are not the size computed");
    return std::move(bytes_);
  }

 private:
  template <std::size_t Size>
  void put(std::uint64_t value) {
    storeLittleEndian<Size>(at_, value);
    at_ += Size;
  }
  std::string bytes_;
  char* at_;
};

// ---- text for error messages -------------------------------------------------------------------

/// A number as an error prints it: the shortest text that reads back the same, or nan / inf.
std::string numberText(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return formatNumber(value);
}

/// `[a, b, c]`. Built by append: g++ 12 warns falsely (-Wrestrict, GCC bug 105329) on
/// "literal" + string&&.
std::string listText(std::initializer_list<double> values) {
  std::string text(1, '[');
  for (const double v : values) text.append(text.size() > 1 ? ", " : "").append(numberText(v));
  return text.append("]");
}

std::string vectorText(const Vec3& v) { return listText({v[0], v[1], v[2]}); }

std::string quaternionText(const Quaternion& q) { return listText({q.w, q.x, q.y, q.z}); }

/// Bytes as one quoted line: printable ASCII as it is, `\n`, `\"`, `\\`, anything else `\xNN`.
std::string quotedBytes(std::string_view bytes) {
  std::string text = "\"";
  for (const char c : bytes) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      text += "\\n";
    } else if (c == '"' || c == '\\') {
      text += '\\';
      text += c;
    } else if (byte >= 0x20 && byte < 0x7f) {
      text += c;
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      text += escaped;
    }
  }
  return text + "\"";
}

/// "1 byte", "12 bytes".
std::string bytesText(std::size_t count) {
  return std::to_string(count) + (count == 1 ? " byte" : " bytes");
}

/// "the end of the file", with how many bytes of the wanted part were there.
std::string endOfFileText(std::size_t bytesLeft) {
  if (bytesLeft == 0) return "the end of the file";
  return "the end of the file after " + bytesText(bytesLeft);
}

/// The offset of the first byte of `text` that does not begin a well-formed UTF-8 sequence
/// (Unicode 15, table 3-7: no overlong forms, no surrogates, nothing above U+10FFFF), or npos.
std::size_t firstNonUtf8Byte(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto lead = static_cast<unsigned char>(text[i]);
    if (lead < 0x80) {
      ++i;
      continue;
    }
    std::size_t length = 0;
    unsigned char low = 0x80, high = 0xbf;  // the range of the second byte
    if (lead >= 0xc2 && lead <= 0xdf) {
      length = 2;
    } else if (lead == 0xe0) {
      length = 3, low = 0xa0;
    } else if (lead == 0xed) {
      length = 3, high = 0x9f;
    } else if (lead >= 0xe1 && lead <= 0xef) {
      length = 3;
    } else if (lead == 0xf0) {
      length = 4, low = 0x90;
    } else if (lead == 0xf4) {
      length = 4, high = 0x8f;
    } else if (lead >= 0xf1 && lead <= 0xf3) {
      length = 4;
    } else {
      return i;
    }
    if (text.size() - i < length) return i;
    for (std::size_t k = 1; k < length; ++k) {
      const auto byte = static_cast<unsigned char>(text[i + k]);
      if (byte < (k == 1 ? low : 0x80) || byte > (k == 1 ? high : 0xbf)) return i;
    }
    i += length;
  }
  return std::string_view::npos;
}

bool isFinite(const Vec3& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

bool isFinite(const Quaternion& q) {
  return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

double length(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

double length(const Quaternion& q) {
  return std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
}

bool isUnit(double norm) { return std::abs(norm - 1.0) <= kUnitTolerance; }

// ---- reading -----------------------------------------------------------------------------------

/// The fields of one record's bytes, in order; their length is checked before, so nothing fails
/// here and no field's name is made unless a check fails.
class RecordBytes {
 public:
  explicit RecordBytes(std::string_view bytes) : rest_(bytes) {}
  double f64() { return std::bit_cast<double>(next<8>()); }
  std::int32_t i32() {  // two's complement (C++20)
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(next<4>()));
  }
  Vec3 vec3() { return {f64(), f64(), f64()}; }  // a braced list is evaluated in order
  Quaternion quaternion() { return {f64(), f64(), f64(), f64()}; }

 private:
  template <std::size_t Size>
  std::uint64_t next() {
    const std::uint64_t value = loadLittleEndian<Size>(rest_.data());
    rest_.remove_prefix(Size);
    return value;
  }
  std::string_view rest_;
};

/// Reads a whole file's bytes in order, each value checked as it is read; the first problem throws
/// InputError(file, field, expected, found).
class Decoder {
 public:
  Decoder(std::string_view bytes, const std::string& file) : rest_(bytes), file_(file) {}

  ContactLog decode() {
    requireMagic();
    ContactLog log;
    const std::uint32_t bodyCount = u32("bodies", "a uint32 body count");
    if (bodyCount > kMaxContactLogBodies)
      fail("bodies", "at most " + std::to_string(kMaxContactLogBodies) + " bodies",
           std::to_string(bodyCount));
    log.substep = f64("substep");
    if (!(std::isfinite(log.substep) && log.substep > 0.0 && log.substep <= kMaxSubstep))
      fail("substep", "a finite number > 0 and <= " + numberText(kMaxSubstep) + " (seconds)",
           numberText(log.substep));
    log.duration = f64("duration");
    if (!(std::isfinite(log.duration) && log.duration >= 0.0))
      fail("duration", "a finite number >= 0 (seconds)", numberText(log.duration));

    log.bodies.reserve(bodyCount);  // at most kMaxContactLogBodies
    for (std::uint32_t i = 0; i < bodyCount; ++i)
      log.bodies.push_back(body(elementPath("bodies", i)));

    // The count is checked against the bytes left before anything is allocated for the records.
    const std::uint64_t recordCount = u64("records", "a uint64 record count");
    const std::size_t whole = rest_.size() / kContactRecordBytes;
    if (recordCount > whole) {
      fail(elementPath("records", whole),
           "a whole record of " + std::to_string(kContactRecordBytes) +
               " bytes (the record count is " + std::to_string(recordCount) + ")",
           endOfFileText(rest_.size() % kContactRecordBytes));
    }
    const auto count = static_cast<std::size_t>(recordCount);
    if (rest_.size() != count * kContactRecordBytes) {
      fail("records",
           "the end of the file after " + std::to_string(count) +
               (count == 1 ? " record" : " records") + " of " +
               std::to_string(kContactRecordBytes) + " bytes",
           bytesText(rest_.size() - count * kContactRecordBytes) + " more");
    }
    log.records.reserve(count);
    for (std::size_t i = 0; i < count; ++i) log.records.push_back(record(log, i));
    return log;
  }

 private:
  [[noreturn]] void fail(const std::string& field, const std::string& expected,
                         const std::string& found) const {
    throw InputError(file_, field, expected, found);
  }

  void requireMagic() {
    const std::string expected =
        "the bytes " + quotedBytes(kContactLogMagic) + " (a fluidsound contact log)";
    const std::string_view start = rest_.substr(0, kContactLogMagic.size());
    if (start != kContactLogMagic) {
      const bool cutShort =
          start.size() < kContactLogMagic.size() && kContactLogMagic.starts_with(start);
      fail("format", expected, cutShort ? endOfFileText(start.size()) : quotedBytes(start));
    }
    rest_.remove_prefix(kContactLogMagic.size());
  }

  /// The next `count` bytes of `field`, which the file must still hold.
  std::string_view take(std::size_t count, const std::string& field, const std::string& what) {
    if (rest_.size() < count) fail(field, what, endOfFileText(rest_.size()));
    const std::string_view taken = rest_.substr(0, count);
    rest_.remove_prefix(count);
    return taken;
  }

  /// The next `Size` bytes of `field` as a little-endian unsigned integer.
  template <std::size_t Size>
  std::uint64_t unsignedValue(const std::string& field, std::string_view what) {
    if (rest_.size() < Size)
      fail(field, std::string(what) + " (" + std::to_string(Size) + " bytes)",
           endOfFileText(rest_.size()));
    const std::uint64_t value = loadLittleEndian<Size>(rest_.data());
    rest_.remove_prefix(Size);
    return value;
  }

  std::uint8_t u8(const std::string& field, std::string_view what) {
    return static_cast<std::uint8_t>(unsignedValue<1>(field, what));
  }
  std::uint32_t u32(const std::string& field, std::string_view what) {
    return static_cast<std::uint32_t>(unsignedValue<4>(field, what));
  }
  std::uint64_t u64(const std::string& field, std::string_view what) {
    return unsignedValue<8>(field, what);
  }
  double f64(const std::string& field) { return std::bit_cast<double>(u64(field, "a float64")); }

  ContactLogBody body(const std::string& path) {
    ContactLogBody body;
    const std::string namePath = memberPath(path, "name");
    const std::uint32_t nameBytes = u32(namePath, "a uint32 name length");
    if (nameBytes > kMaxContactLogNameBytes)
      fail(namePath, "a name of at most " + std::to_string(kMaxContactLogNameBytes) + " bytes",
           "a length of " + std::to_string(nameBytes) + " bytes");
    body.name = std::string(
        take(nameBytes, namePath, "the name's " + std::to_string(nameBytes) + " bytes"));
    if (const std::size_t bad = firstNonUtf8Byte(body.name); bad != std::string_view::npos)
      fail(namePath, "a name in UTF-8", "a byte that is not UTF-8 at byte " + std::to_string(bad));

    const std::string massPath = memberPath(path, "mass");
    body.mass = f64(massPath);
    if (!(std::isfinite(body.mass) && body.mass >= 0.0))
      fail(massPath, "a finite number >= 0 (kg)", numberText(body.mass));
    const std::string staticPath = memberPath(path, "isStatic");
    const std::uint8_t isStatic = u8(staticPath, "a uint8");
    if (isStatic > 1) fail(staticPath, "0 or 1 (moving or static)", std::to_string(isStatic));
    body.isStatic = isStatic == 1;
    if (body.isStatic && body.mass != 0.0)
      fail(massPath, "0 for a static body (kg)", numberText(body.mass));
    if (!body.isStatic && body.mass == 0.0)
      fail(massPath, "a number > 0 for a body that is not static (kg)", numberText(body.mass));
    const std::string radiusPath = memberPath(path, "contactRadius");
    body.contactRadius = f64(radiusPath);
    if (!(std::isfinite(body.contactRadius) && body.contactRadius > 0.0))
      fail(radiusPath, "a finite number > 0 (metres)", numberText(body.contactRadius));
    return body;
  }

  /// Record i of `log`, whose bodies and records before i are read.
  ContactRecord record(const ContactLog& log, std::size_t i) {
    const auto field = [i](std::string_view key) {
      return memberPath(elementPath("records", i), key);
    };
    RecordBytes in(rest_.substr(0, kContactRecordBytes));
    rest_.remove_prefix(kContactRecordBytes);
    const ContactRecord* previous = i > 0 ? &log.records[i - 1] : nullptr;
    const int bodies = static_cast<int>(log.bodies.size());
    ContactRecord r;

    r.time = in.f64();
    const double latest = log.duration + log.substep;
    if (!(std::isfinite(r.time) && r.time >= 0.0 && r.time <= latest))
      fail(field("time"),
           "a number from 0 to duration + substep = " + numberText(latest) + " (seconds)",
           numberText(r.time));
    if (previous != nullptr && r.time < previous->time)
      fail(field("time"),
           "a time >= " + numberText(previous->time) + " (seconds), that of " +
               elementPath("records", i - 1),
           numberText(r.time));

    r.bodyA = in.i32();
    if (bodies == 0)
      fail(field("bodyA"), "no record (the log has no bodies)", std::to_string(r.bodyA));
    if (r.bodyA < 0 || r.bodyA >= bodies)
      fail(field("bodyA"), "a body index from 0 to " + std::to_string(bodies - 1),
           std::to_string(r.bodyA));
    r.bodyB = in.i32();
    const bool isWall = r.bodyB >= -kWallCount && r.bodyB <= -1;
    if (!isWall && !(r.bodyB > r.bodyA && r.bodyB < bodies)) {
      const std::string wall = "a wall of the domain (-" + std::to_string(kWallCount) + " to -1)";
      fail(field("bodyB"),
           r.bodyA + 1 < bodies
               ? "a body after bodyA (" + std::to_string(r.bodyA + 1) + " to " +
                     std::to_string(bodies - 1) + ") or " + wall
               : wall + ", bodyA " + std::to_string(r.bodyA) + " being the last body",
           std::to_string(r.bodyB));
    }
    if (previous != nullptr && previous->time == r.time &&
        std::pair(r.bodyA, r.bodyB) < std::pair(previous->bodyA, previous->bodyB)) {
      fail(field(r.bodyA < previous->bodyA ? "bodyA" : "bodyB"),
           "a pair (bodyA, bodyB) not before (" + std::to_string(previous->bodyA) + ", " +
               std::to_string(previous->bodyB) + ") of " + elementPath("records", i - 1) +
               ", at the same time",
           "(" + std::to_string(r.bodyA) + ", " + std::to_string(r.bodyB) + ")");
    }

    r.position = in.vec3();
    if (!isFinite(r.position))
      fail(field("position"), "3 finite numbers (metres)", vectorText(r.position));
    r.normal = in.vec3();
    if (!isFinite(r.normal) || !isUnit(length(r.normal)))
      fail(field("normal"), "a unit vector (length within " + numberText(kUnitTolerance) + " of 1)",
           vectorText(r.normal) +
               (isFinite(r.normal) ? " (length " + numberText(length(r.normal)) + ")" : ""));
    r.normalImpulse = in.f64();
    if (!(std::isfinite(r.normalImpulse) && r.normalImpulse >= 0.0))
      fail(field("normalImpulse"), "a finite number >= 0 (newton seconds)",
           numberText(r.normalImpulse));
    r.frictionImpulse = in.vec3();
    if (!isFinite(r.frictionImpulse))
      fail(field("frictionImpulse"), "3 finite numbers (newton seconds)",
           vectorText(r.frictionImpulse));
    r.normalSpeed = in.f64();
    if (!std::isfinite(r.normalSpeed))
      fail(field("normalSpeed"), "a finite number (m/s)", numberText(r.normalSpeed));
    r.tangentialSpeed = in.f64();
    if (!(std::isfinite(r.tangentialSpeed) && r.tangentialSpeed >= 0.0))
      fail(field("tangentialSpeed"), "a finite number >= 0 (m/s)", numberText(r.tangentialSpeed));
    r.rollingRate = in.f64();
    if (!(std::isfinite(r.rollingRate) && r.rollingRate >= 0.0))
      fail(field("rollingRate"), "a finite number >= 0 (rad/s)", numberText(r.rollingRate));
    r.lifetime = in.i32();
    if (r.lifetime < 1)
      fail(field("lifetime"), "an integer >= 1 (substeps)", std::to_string(r.lifetime));
    r.localPointA = in.vec3();
    if (!isFinite(r.localPointA))
      fail(field("localPointA"), "3 finite numbers (metres, in A's frame)",
           vectorText(r.localPointA));
    r.localPointB = in.vec3();
    if (!isFinite(r.localPointB))
      fail(field("localPointB"), "3 finite numbers (metres, in B's frame)",
           vectorText(r.localPointB));
    for (const auto& [key, q] :
         {std::pair{"orientationA", &r.orientationA}, std::pair{"orientationB", &r.orientationB}}) {
      *q = in.quaternion();
      if (!isFinite(*q) || !isUnit(length(*q)))
        fail(
            field(key),
            "a unit quaternion (w, x, y, z; length within " + numberText(kUnitTolerance) + " of 1)",
            quaternionText(*q) + (isFinite(*q) ? " (length " + numberText(length(*q)) + ")" : ""));
    }
    return r;
  }

  std::string_view rest_;
  const std::string& file_;
};

}  // namespace

std::string encodeContactLog(const ContactLog& log) {
  std::size_t size =
      kContactLogMagic.size() + 4 + 8 + 8 + 8 + log.records.size() * kContactRecordBytes;
  for (const ContactLogBody& body : log.bodies) size += 4 + body.name.size() + 8 + 1 + 8;
  LittleEndianWriter w(size);
  w.text(kContactLogMagic);
  w.u32(static_cast<std::uint32_t>(log.bodies.size()));
  w.f64(log.substep);
  w.f64(log.duration);
  for (const ContactLogBody& body : log.bodies) {
    w.u32(static_cast<std::uint32_t>(body.name.size()));
    w.text(body.name);
    w.f64(body.mass);
    w.u8(body.isStatic ? 1 : 0);
    w.f64(body.contactRadius);
  }
  w.u64(log.records.size());
  for (const ContactRecord& r : log.records) {
    w.f64(r.time);
    w.i32(r.bodyA);
    w.i32(r.bodyB);
    w.vec3(r.position);
    w.vec3(r.normal);
    w.f64(r.normalImpulse);
    w.vec3(r.frictionImpulse);
    w.f64(r.normalSpeed);
    w.f64(r.tangentialSpeed);
    w.f64(r.rollingRate);
    w.i32(r.lifetime);
    w.vec3(r.localPointA);
    w.vec3(r.localPointB);
    w.quaternion(r.orientationA);
    w.quaternion(r.orientationB);
  }
  return std::move(w).take();
}

ContactLog decodeContactLog(std::string_view bytes, const std::string& file) {
  return Decoder(bytes, file).decode();
}

ContactLog readContactLog(const std::filesystem::path& file) {
  return decodeContactLog(readInputFile(file), file.string());
}

void writeContactLog(const std::filesystem::path& file, const ContactLog& log) {
  const std::string bytes = encodeContactLog(log);
  // Never write a file that the reader would refuse (a NaN, a bad normal, records out of order).
  try {
    decodeContactLog(bytes, file.string());
  } catch (const InputError& error) {
    throw std::invalid_argument("cannot write an invalid contact log: " +
                                std::string(error.what()));
  }
  AtomicFile out(file);  // refuses anything but a regular file or a new name (output_file.h)
  {
    std::ofstream stream(out.temporaryPath(), std::ios::binary | std::ios::trunc);
    stream.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    stream.close();
    if (!stream)
      throw OutputError(file.string() + ": cannot write: writing the temporary file failed");
  }
  out.commit();
}

}  // namespace fluidsound::io
