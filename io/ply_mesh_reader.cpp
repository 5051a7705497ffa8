// io/ply_mesh_reader.cpp — PLY meshes (see mesh_readers.h), our own small reader: Debian 12's
// Assimp 5.2.5 loops forever on a PLY file cut inside its header and aborts the process on one
// cut inside its data (measured), and no other PLY library is packaged. Format: Greg Turk's PLY
// (1994) as Blender, MeshLab and Houdini write it: a text header, then the elements in order.
#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "io/mesh_readers.h"

namespace fluidsound::io {
namespace {

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct PlyTypeName {
  std::string_view name;
  PlyType type;
};

/// Both spellings of the PLY 1.0 specification.
constexpr PlyTypeName kTypeNames[] = {
    {"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
    {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
    {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
    {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
    {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
    {"float64", PlyType::Float64}};

std::optional<PlyType> typeNamed(std::string_view name) {
  for (const PlyTypeName& t : kTypeNames)
    if (t.name == name) return t.type;
  return std::nullopt;
}

std::string_view typeName(PlyType type) {
  for (const PlyTypeName& t : kTypeNames)
    if (t.type == type) return t.name;
  return "?";
}

std::size_t typeSize(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8:
      return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
      return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
      return 4;
    case PlyType::Float64:
      return 8;
  }
  return 0;
}

bool isInteger(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

struct PlyProperty {
  std::string name;
  bool isList = false;
  PlyType countType = PlyType::UInt8;  ///< lists only
  PlyType valueType = PlyType::Float32;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::size_t dataOffset = 0;  ///< first byte after the `end_header` line
};

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isSpace(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !isSpace(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

std::string headerLine(std::size_t number) { return "line " + std::to_string(number); }

/// One line of the header, split into words, with its place for messages.
struct HeaderLine {
  std::string_view text;
  const std::vector<std::string_view>& words;
  std::string place;  ///< "line N"
  [[noreturn]] void fail(const std::string& expected, const MeshErrorReporter& report) const {
    report.fail(place, expected, quotedExcerpt(text));
  }
};

constexpr const char* kFormatExpected =
    "\"format ascii 1.0\", \"format binary_little_endian 1.0\" or \"format binary_big_endian 1.0\"";

/// `format ENCODING 1.0`.
PlyFormat formatOf(const HeaderLine& at, const MeshErrorReporter& report) {
  const auto& w = at.words;
  if (w.size() != 3 || w[2] != "1.0") at.fail(kFormatExpected, report);
  if (w[1] == "ascii") return PlyFormat::Ascii;
  if (w[1] == "binary_little_endian") return PlyFormat::BinaryLittleEndian;
  if (w[1] == "binary_big_endian") return PlyFormat::BinaryBigEndian;
  at.fail(kFormatExpected, report);
}

/// `element NAME COUNT`.
PlyElement elementOf(const HeaderLine& at, const MeshErrorReporter& report) {
  const auto& w = at.words;
  PlyElement element;
  std::uint64_t count = 0;
  bool valid = w.size() == 3;
  if (valid) {
    const auto [end, error] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), count);
    valid = error == std::errc{} && end == w[2].data() + w[2].size();
  }
  if (!valid) at.fail("\"element NAME COUNT\" with a whole COUNT >= 0", report);
  element.name = std::string(w[1]);
  element.count = count;
  return element;
}

/// `property TYPE NAME` or `property list COUNT_TYPE VALUE_TYPE NAME`.
PlyProperty propertyOf(const HeaderLine& at, const MeshErrorReporter& report) {
  const auto& w = at.words;
  const std::string types = "char, uchar, short, ushort, int, uint, float or double";
  PlyProperty property;
  if (w.size() == 5 && w[1] == "list") {
    const auto countType = typeNamed(w[2]), valueType = typeNamed(w[3]);
    if (!countType || !isInteger(*countType) || !valueType)
      at.fail(
          "\"property list COUNT_TYPE VALUE_TYPE NAME\" with an integer COUNT_TYPE and each type "
          "one of " +
              types,
          report);
    property.isList = true;
    property.countType = *countType;
    property.valueType = *valueType;
    property.name = std::string(w[4]);
  } else {
    const auto type = w.size() == 3 ? typeNamed(w[1]) : std::nullopt;
    if (!type) at.fail("\"property TYPE NAME\" with TYPE one of " + types, report);
    property.valueType = *type;
    property.name = std::string(w[2]);
  }
  return property;
}

PlyHeader parseHeader(std::string_view bytes, const MeshErrorReporter& report) {
  PlyHeader header;
  std::size_t offset = 0, lineNumber = 0;
  bool formatSeen = false;
  while (true) {
    const std::size_t end = bytes.find('\n', offset);
    if (end == std::string_view::npos) {
      report.fail("", "a PLY header ending in a line \"end_header\"",
                  "end of file after " + std::to_string(lineNumber) + " header lines");
    }
    std::string_view line = bytes.substr(offset, end - offset);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    offset = end + 1;
    ++lineNumber;
    const std::vector<std::string_view> w = words(line);

    if (lineNumber == 1) {
      if (line != "ply")
        report.fail("", "a PLY file starting with the line \"ply\"", quotedExcerpt(line));
      continue;
    }
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") break;
    const HeaderLine at{line, w, headerLine(lineNumber)};
    if (w[0] == "format") {
      if (formatSeen) at.fail(kFormatExpected, report);
      header.format = formatOf(at, report);
      formatSeen = true;
    } else if (w[0] == "element") {
      header.elements.push_back(elementOf(at, report));
    } else if (w[0] == "property") {
      if (header.elements.empty()) at.fail("an \"element\" line before the first property", report);
      header.elements.back().properties.push_back(propertyOf(at, report));
    } else {
      report.fail(headerLine(lineNumber),
                  "a PLY header line (format, element, property, comment, obj_info or end_header)",
                  quotedExcerpt(line));
    }
  }
  if (!formatSeen) report.fail("", "a \"format\" line in the PLY header", "none before end_header");
  header.dataOffset = offset;
  return header;
}

/// Reads the values of the data section one after the other, in the file's encoding.
class PlyValueReader {
 public:
  PlyValueReader(std::string_view data, PlyFormat format) : data_(data), format_(format) {}

  /// The next value of type `type`; nullopt at the end of the data; `bad` set to the offending
  /// word when ASCII text does not parse as that type.
  std::optional<double> next(PlyType type, std::string& bad) {
    if (format_ == PlyFormat::Ascii) return nextWord(type, bad);
    const std::size_t size = typeSize(type);
    if (data_.size() - position_ < size) return std::nullopt;
    unsigned char raw[8];
    std::memcpy(raw, data_.data() + position_, size);
    position_ += size;
    const bool fileIsLittle = format_ == PlyFormat::BinaryLittleEndian;
    if (fileIsLittle != (std::endian::native == std::endian::little)) std::reverse(raw, raw + size);
    switch (type) {
      case PlyType::Int8:
        return decode<std::int8_t>(raw);
      case PlyType::UInt8:
        return decode<std::uint8_t>(raw);
      case PlyType::Int16:
        return decode<std::int16_t>(raw);
      case PlyType::UInt16:
        return decode<std::uint16_t>(raw);
      case PlyType::Int32:
        return decode<std::int32_t>(raw);
      case PlyType::UInt32:
        return decode<std::uint32_t>(raw);
      case PlyType::Float32:
        return decode<float>(raw);
      case PlyType::Float64:
        return decode<double>(raw);
    }
    return std::nullopt;
  }

 private:
  template <typename T>
  static double decode(const unsigned char* raw) {
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return static_cast<double>(value);
  }

  std::optional<double> nextWord(PlyType type, std::string& bad) {
    while (position_ < data_.size() && isSpace(data_[position_])) ++position_;
    if (position_ == data_.size()) return std::nullopt;
    const std::size_t start = position_;
    while (position_ < data_.size() && !isSpace(data_[position_])) ++position_;
    std::string_view word = data_.substr(start, position_ - start);
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    const char* first = word.data();
    const char* last = word.data() + word.size();
    if (isInteger(type)) {
      std::int64_t value = 0;
      const auto [end, error] = std::from_chars(first, last, value);
      if (error == std::errc{} && end == last && fitsInteger(type, value)) return double(value);
    } else {
      double value = 0.0;
      const auto [end, error] = std::from_chars(first, last, value);
      if (error == std::errc{} && end == last) return value;
    }
    bad = std::string(data_.substr(start, position_ - start));
    return std::nullopt;
  }

  static bool fitsInteger(PlyType type, std::int64_t v) {
    switch (type) {
      case PlyType::Int8:
        return v >= INT8_MIN && v <= INT8_MAX;
      case PlyType::UInt8:
        return v >= 0 && v <= UINT8_MAX;
      case PlyType::Int16:
        return v >= INT16_MIN && v <= INT16_MAX;
      case PlyType::UInt16:
        return v >= 0 && v <= UINT16_MAX;
      case PlyType::Int32:
        return v >= INT32_MIN && v <= INT32_MAX;
      case PlyType::UInt32:
        return v >= 0 && v <= std::int64_t{UINT32_MAX};
      default:
        return true;
    }
  }

  std::string_view data_;
  PlyFormat format_;
  std::size_t position_ = 0;
};

/// Which property of `element` is named one of `names`; -1 if none.
int propertyIndex(const PlyElement& element, std::initializer_list<std::string_view> names) {
  for (std::size_t p = 0; p < element.properties.size(); ++p)
    for (std::string_view name : names)
      if (element.properties[p].name == name) return static_cast<int>(p);
  return -1;
}

}  // namespace

namespace {

/// The elements the mesh is read from: the vertex element and its x, y, z properties; the face
/// element (if any) and its index list property.
struct MeshElements {
  const PlyElement* vertex = nullptr;
  const PlyElement* face = nullptr;
  std::array<int, 3> xyz{-1, -1, -1};
  int indexList = -1;
};

MeshElements meshElements(const PlyHeader& header, const MeshErrorReporter& report) {
  MeshElements m;
  for (const PlyElement& e : header.elements) {
    if (e.name == "vertex" && !m.vertex) m.vertex = &e;
    if (e.name == "face" && !m.face) m.face = &e;
  }
  if (m.vertex) {
    m.xyz = {propertyIndex(*m.vertex, {"x"}), propertyIndex(*m.vertex, {"y"}),
             propertyIndex(*m.vertex, {"z"})};
  }
  const std::string vertexExpected = "an element \"vertex\" with scalar properties x, y and z";
  if (!m.vertex) report.fail("", vertexExpected, "no vertex element in the header");
  for (int a = 0; a < 3; ++a) {
    if (m.xyz[a] < 0 || m.vertex->properties[m.xyz[a]].isList)
      report.fail("", vertexExpected, std::string("no scalar property ") + "xyz"[a]);
  }
  if (m.vertex->count > std::numeric_limits<std::uint32_t>::max())
    report.fail("", "at most 4294967295 vertices", std::to_string(m.vertex->count));
  if (m.face) {
    m.indexList = propertyIndex(*m.face, {"vertex_indices", "vertex_index"});
    if (m.indexList < 0 || !m.face->properties[m.indexList].isList ||
        !isInteger(m.face->properties[m.indexList].valueType))
      report.fail("", "an element \"face\" with an integer list property vertex_indices",
                  "no such list among its properties");
  }
  return m;
}

/// What the data section holds for the mesh: the vertices and the faces' corners, flat (face f
/// has corners[faceStart[f] … faceStart[f + 1])).
struct PlyData {
  std::vector<std::array<float, 3>> vertices;
  std::vector<std::int64_t> corners;
  std::vector<std::size_t> faceStart{0};
};

/// Reads one item of `element` (`isVertex`: its position into data.vertices; `indexList`: the
/// index of the face list property, or −1).
void readItem(const PlyElement& element, std::uint64_t item, PlyValueReader& values,
              const MeshElements& m, PlyData& data, const MeshErrorReporter& report) {
  const bool isVertex = &element == m.vertex;
  const bool isFace = &element == m.face;
  const auto location = [&] { return element.name + " " + std::to_string(item); };
  std::array<double, 3> position{};
  for (std::size_t p = 0; p < element.properties.size(); ++p) {
    const PlyProperty& property = element.properties[p];
    std::string bad;
    const auto read = [&](PlyType type, const std::string& what) {
      const std::optional<double> value = values.next(type, bad);
      if (!value) {
        report.fail(
            location(),
            what + " of property \"" + property.name + "\" (" + std::string(typeName(type)) + ")",
            bad.empty() ? "end of file" : quotedExcerpt(bad));
      }
      return *value;
    };
    if (!property.isList) {
      const double value = read(property.valueType, "a value");
      if (isVertex)
        for (int a = 0; a < 3; ++a)
          if (static_cast<int>(p) == m.xyz[a]) position[a] = value;
      continue;
    }
    const double length = read(property.countType, "a list length");
    if (length < 0)
      report.fail(location(), "a list length >= 0 of property \"" + property.name + "\"",
                  numberText(length));
    const bool isIndexList = isFace && static_cast<int>(p) == m.indexList;
    if (isIndexList && length < 3)
      report.fail(location(), "a face of at least 3 vertex indices",
                  numberText(length) + " indices");
    for (std::uint64_t k = 0; k < static_cast<std::uint64_t>(length); ++k) {
      const double value = read(property.valueType, "a list entry");
      if (isIndexList) data.corners.push_back(static_cast<std::int64_t>(value));
    }
    if (isIndexList) data.faceStart.push_back(data.corners.size());
  }
  if (isVertex) {
    const std::array<float, 3> v{static_cast<float>(position[0]), static_cast<float>(position[1]),
                                 static_cast<float>(position[2])};
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
      report.fail(location(), "finite coordinates x, y, z within float range (|x| <= 3.4e38)",
                  pointText(position[0], position[1], position[2]));
    data.vertices.push_back(v);
  }
}

/// The faces as triangle fans, their indices checked against the vertex count.
void addFans(const PlyData& data, const MeshErrorReporter& report, sim::TriangleMesh& mesh) {
  const std::int64_t vertexCount = static_cast<std::int64_t>(mesh.vertices.size());
  for (std::size_t f = 0; f + 1 < data.faceStart.size(); ++f) {
    const std::span<const std::int64_t> polygon(data.corners.data() + data.faceStart[f],
                                                data.faceStart[f + 1] - data.faceStart[f]);
    for (const std::int64_t index : polygon) {
      if (index < 0 || index >= vertexCount)
        report.fail("face " + std::to_string(f),
                    "vertex indices from 0 to " + std::to_string(vertexCount - 1) +
                        " (the file has " + std::to_string(vertexCount) + " vertices)",
                    std::to_string(index));
    }
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
      mesh.triangles.push_back({static_cast<std::uint32_t>(polygon[0]),
                                static_cast<std::uint32_t>(polygon[k]),
                                static_cast<std::uint32_t>(polygon[k + 1])});
  }
}

}  // namespace

sim::TriangleMesh parsePlyMesh(std::string_view bytes, const MeshErrorReporter& report) {
  const PlyHeader header = parseHeader(bytes, report);
  const MeshElements m = meshElements(header, report);
  PlyData data;
  // Reserve no more than the data could hold, so a lying header cannot exhaust memory.
  const std::size_t dataBytes = bytes.size() - header.dataOffset;
  data.vertices.reserve(std::min<std::uint64_t>(m.vertex->count, dataBytes));
  PlyValueReader values(bytes.substr(header.dataOffset), header.format);
  for (const PlyElement& element : header.elements) {
    if (element.properties.empty()) continue;  // nothing to read, however many
    for (std::uint64_t item = 0; item < element.count; ++item)
      readItem(element, item, values, m, data, report);
  }
  sim::TriangleMesh mesh;
  mesh.vertices = std::move(data.vertices);
  addFans(data, report, mesh);
  return mesh;
}

}  // namespace fluidsound::io
