// io/json_validation.cpp — typed, range-checked reading of JSON input files (see
// json_validation.h).
#include "io/json_validation.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <set>
#include <system_error>
#include <utility>
#include <vector>

#include "io/file_kind.h"

namespace fluidsound::io {
namespace {

using nlohmann::json;

/// Longest string quoted in an error message, in bytes; a longer one is cut and marked "...".
constexpr std::size_t kMaxQuotedBytes = 60;

/// Largest integer that a JSON number written with a fraction part (7.0) carries exactly: 2^53.
constexpr double kMaxExactInteger = 9007199254740992.0;

/// Keys starting with `x_` or `x-` are extension fields (where KeyRules allow them).
bool isExtensionKey(std::string_view key) {
  return key.size() > 2 && key[0] == 'x' && (key[1] == '_' || key[1] == '-');
}

/// The number of single-character insertions, deletions and substitutions that turn `a` into
/// `b` (Levenshtein distance).
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// Parser callback that limits the nesting depth to kMaxJsonDepth (checked as each array or object
/// opens, so a deeply nested document stops before it costs more than a few levels) and, with
/// DuplicateKeys::Rejected, rejects a key given twice in one object (nlohmann would keep the last
/// silently, hiding a typo-level mistake). Each open level holds its index or key, not its path:
/// the path is built only for an error message.
class ParseCheck {
 public:
  ParseCheck(const std::string& file, DuplicateKeys duplicates) : file_(&file), duplicates_(duplicates) {}

  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (open_.size() >= kMaxJsonDepth) {
          throw InputError(*file_, childPath(),
                           "at most " + std::to_string(kMaxJsonDepth) + " nested arrays and objects",
                           "a deeper " + std::string(event == json::parse_event_t::array_start ? "array" : "object"));
        }
        advance();
        open_.push_back({event == json::parse_event_t::array_start, 0, {}, {}});
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        open_.pop_back();
        break;
      case json::parse_event_t::key: {
        Container& object = open_.back();
        object.key = parsed.get<std::string>();
        if (duplicates_ == DuplicateKeys::Rejected && !object.keys.insert(object.key).second) {
          throw InputError(*file_, childPath(), "each key at most once in an object",
                           quotedText(object.key) + " a second time");
        }
        break;
      }
      case json::parse_event_t::value:
        advance();  // counts array elements
        break;
    }
    return true;
  }

 private:
  struct Container {
    bool isArray = false;
    std::size_t nextIndex = 0;  ///< arrays: the index of the next element
    std::string key;            ///< objects: the member being read
    std::set<std::string> keys; ///< objects: the keys read so far (DuplicateKeys::Rejected)
  };

  /// Moves past the value that starts now (the next index inside an array).
  void advance() {
    if (!open_.empty() && open_.back().isArray) ++open_.back().nextIndex;
  }

  /// The JSON path of the value that starts now (before advance()): in the innermost array the
  /// next index, in the arrays around it the element being read.
  std::string childPath() const {
    std::string path;
    for (std::size_t i = 0; i < open_.size(); ++i) {
      const Container& level = open_[i];
      const bool innermost = i + 1 == open_.size();
      path = level.isArray ? elementPath(path, innermost ? level.nextIndex : level.nextIndex - 1)
                           : memberPath(path, level.key);
    }
    return path;
  }

  const std::string* file_;
  DuplicateKeys duplicates_;
  std::vector<Container> open_;
};

}  // namespace

// ---- text for error messages ---------------------------------------------------------------

std::string formatNumber(double value) { return json(value).dump(); }

std::string quotedText(std::string_view text) { return json(std::string(text)).dump(); }

std::string describe(const json& value) {
  switch (value.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return value.get<bool>() ? "true" : "false";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return value.dump();
    case json::value_t::string: {
      const std::string& text = value.get_ref<const std::string&>();
      if (text.size() <= kMaxQuotedBytes) return quotedText(text);
      std::size_t cut = kMaxQuotedBytes;
      while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xc0) == 0x80) --cut;  // UTF-8
      return quotedText(text.substr(0, cut)) + "...";
    }
    case json::value_t::array:
      if (value.empty()) return "an empty array";
      return "an array of " + std::to_string(value.size()) +
             (value.size() == 1 ? " value" : " values");
    case json::value_t::object:
      return "an object";
    default:
      return "an unsupported value";
  }
}

std::string shortJsonMessage(const json::exception& error) {
  std::string text = error.what();
  if (!text.empty() && text.front() == '[') {
    const std::size_t end = text.find("] ");
    if (end != std::string::npos) text.erase(0, end + 2);
  }
  return text;
}

// ---- JSON paths and members ------------------------------------------------------------------

std::string memberPath(const std::string& path, std::string_view key) {
  std::string out = path;
  if (!out.empty()) out += '.';
  out += key;
  return out;
}

std::string elementPath(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

const json* findMember(const json& object, std::string_view key) {
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

// ---- unknown keys --------------------------------------------------------------------------

std::string normalizedKey(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c != '_' && c != '-') out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

std::string closestKey(std::string_view unknown, std::span<const std::string_view> known, bool matchSharedStart) {
  const std::string typed = normalizedKey(unknown);
  std::string best;
  std::size_t bestDistance = std::string::npos;
  for (std::string_view candidate : known) {
    const std::string target = normalizedKey(candidate);
    std::size_t distance = editDistance(typed, target);
    if (typed.size() >= 3 && target.starts_with(typed))
      distance = std::min<std::size_t>(distance, 1);
    if (matchSharedStart) {
      const auto mismatch = std::mismatch(typed.begin(), typed.end(), target.begin(), target.end());
      if (mismatch.first - typed.begin() >= 4) distance = std::min<std::size_t>(distance, 2);
    }
    const std::size_t allowed = target.size() >= 5 ? 2 : 1;
    if (distance <= allowed && distance < bestDistance) {
      best = std::string(candidate);
      bestDistance = distance;
    }
  }
  return best;
}

// ---- parsing -------------------------------------------------------------------------------

json parseJson(std::string_view text, const std::string& file, DuplicateKeys duplicates) {
  try {
    return json::parse(text.begin(), text.end(), ParseCheck(file, duplicates));
  } catch (const json::exception& error) {  // parse_error, or out_of_range for 1e999
    throw InputError(file, "", "valid JSON", shortJsonMessage(error));
  }
}

std::string nonRegularInput(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_type type = fs::status(path, ec).type();
  if (type == fs::file_type::regular) return "";
  if (ec && type != fs::file_type::not_found) return ec.message();
  return fileKindName(type);
}

std::string readStandardInput(const std::string& name) {
  std::string text;
  char buffer[1 << 16];
  std::size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof buffer, stdin)) > 0) text.append(buffer, count);
  if (std::ferror(stdin) != 0)
    throw InputError(name, "", "readable standard input", std::generic_category().message(errno));
  return text;
}

std::string readInputFile(const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::string kind = nonRegularInput(path);
  if (!kind.empty()) throw InputError(name, "", "a readable file", kind);
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr)
    throw InputError(name, "", "a readable file", std::generic_category().message(errno));
  std::string text;
  char buffer[1 << 16];
  std::size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, count);
  const bool failed = std::ferror(file) != 0;
  const int error = errno;
  std::fclose(file);
  if (failed) throw InputError(name, "", "a readable file", std::generic_category().message(error));
  return text;
}

// ---- the validator -------------------------------------------------------------------------

void JsonValidator::fail(const std::string& field, const std::string& expected,
                         const std::string& found) const {
  throw InputError(file_, field, expected, found);
}

void JsonValidator::requireFormat(const json& root, std::string_view tag) const {
  if (!root.is_object()) {
    // Built by append: g++ 12 warns falsely (-Wrestrict, GCC bug 105329) on "literal" + string&&.
    std::string expected = "a JSON object (a ";
    expected.append(tag).append(" document)");
    fail("", expected, describe(root));
  }
  const std::string quotedTag = quotedText(tag);
  const json* format = findMember(root, "format");
  if (format == nullptr) fail("format", quotedTag, std::string(kMissing));
  if (!format->is_string() || format->get_ref<const std::string&>() != tag)
    fail("format", quotedTag, describe(*format));
}

void JsonValidator::rejectUnknownKeys(const json& object, const std::string& path,
                                      std::initializer_list<std::string_view> known) const {
  for (const auto& item : object.items()) {
    const std::string& key = item.key();
    if (rules_.allowExtensionKeys && isExtensionKey(key)) continue;
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    std::string expected = "one of ";
    for (auto it = known.begin(); it != known.end(); ++it) {
      if (it != known.begin()) expected += ", ";
      expected += *it;
    }
    const std::string suggestion = closestKey(key, known, rules_.matchSharedStart);
    if (!suggestion.empty()) {
      expected += " (did you mean '" + suggestion + "'?)";
    } else if (rules_.allowExtensionKeys) {
      expected += " (or an extension key starting with x_ or x-)";
    }
    fail(memberPath(path, key), expected, std::string(rules_.unknownKeyFound));
  }
}

void JsonValidator::requireObject(const json& value, const std::string& path,
                                  const std::string& expected) const {
  if (!value.is_object()) fail(path, expected, describe(value));
}

const json& JsonValidator::requiredObject(const json& parent, const std::string& parentPath,
                                          std::string_view key, const std::string& expected) const {
  const json* value = findMember(parent, key);
  if (value == nullptr) fail(memberPath(parentPath, key), expected, std::string(kMissing));
  requireObject(*value, memberPath(parentPath, key), expected);
  return *value;
}

const json* JsonValidator::optionalObject(const json& parent, const std::string& parentPath,
                                          std::string_view key, const std::string& expected) const {
  const json* value = findMember(parent, key);
  if (value != nullptr) requireObject(*value, memberPath(parentPath, key), expected);
  return value;
}

const json& JsonValidator::requiredArray(const json& parent, const std::string& parentPath,
                                         std::string_view key, const std::string& expected) const {
  const json* value = findMember(parent, key);
  if (value == nullptr) fail(memberPath(parentPath, key), expected, std::string(kMissing));
  if (!value->is_array()) fail(memberPath(parentPath, key), expected, describe(*value));
  return *value;
}

const json* JsonValidator::optionalArray(const json& parent, const std::string& parentPath,
                                         std::string_view key, const std::string& expected) const {
  const json* value = findMember(parent, key);
  if (value != nullptr && !value->is_array())
    fail(memberPath(parentPath, key), expected, describe(*value));
  return value;
}

std::uint64_t JsonValidator::wholeNumber(const json& value, const std::string& path,
                                         const std::string& expected, std::uint64_t low,
                                         std::uint64_t high) const {
  std::uint64_t n = 0;
  if (value.is_number_unsigned()) {
    n = value.get<std::uint64_t>();
  } else if (value.is_number_float()) {
    const double v = value.get<double>();
    if (!(v >= 0 && v <= kMaxExactInteger && v == std::floor(v)))
      fail(path, expected, describe(value));
    n = static_cast<std::uint64_t>(v);
  } else {  // a negative integer, or not a number
    fail(path, expected, describe(value));
  }
  if (n < low || n > high) fail(path, expected, describe(value));
  return n;
}

Vec3 JsonValidator::vector(const json& value, const std::string& path,
                                          const std::string& unit) const {
  if (!value.is_array() || value.size() != 3)
    fail(path, "an array of 3 numbers [x, y, z] (" + unit + ")", describe(value));
  Vec3 v{};
  for (std::size_t a = 0; a < 3; ++a)
    v[a] = number(value[a], elementPath(path, a), "a number (" + unit + ")", anyValue);
  return v;
}

Vec3 JsonValidator::requiredVector(const json& parent, const std::string& parentPath,
                                                  std::string_view key,
                                                  const std::string& unit) const {
  const json* value = findMember(parent, key);
  if (value == nullptr) {
    fail(memberPath(parentPath, key), "an array of 3 numbers [x, y, z] (" + unit + ")",
         std::string(kMissing));
  }
  return vector(*value, memberPath(parentPath, key), unit);
}

const std::string& JsonValidator::text(const json& value, const std::string& path,
                                       const std::string& expected) const {
  if (!value.is_string()) fail(path, expected, describe(value));
  return value.get_ref<const std::string&>();
}

const std::string& JsonValidator::nonEmptyText(const json& value, const std::string& path,
                                               const std::string& expected) const {
  const std::string& out = text(value, path, expected);
  if (out.empty()) fail(path, expected, describe(value));
  return out;
}

}  // namespace fluidsound::io
