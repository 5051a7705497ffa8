// io/json_validation.h — input boundary: typed, range-checked reading of JSON input files, every
// failure an InputError naming the file, the JSON path, what was expected and what was found.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <span>
#include <string_view>

#include "io/input_error.h"
#include "sim/core/vec3.h"

namespace fluidsound::io {

/// What `found` says when a required key is absent.
inline constexpr std::string_view kMissing = "nothing (required)";

// ---- text for error messages ---------------------------------------------------------------

/// @brief A number as JSON writes it: the shortest text that reads back to the same double.
std::string formatNumber(double value);

/// @brief `text` as a JSON string literal, quotes and escapes included.
std::string quotedText(std::string_view text);

/// @brief A short, one-line description of a JSON value for the `found` part of an error:
///        `null`, `true`, `0.25`, a quoted string (cut after 60 bytes and marked "..."),
///        `an empty array`, `an array of 3 values`, `an object`.
std::string describe(const nlohmann::json& value);

/// @brief nlohmann's message without its `[json.exception.parse_error.101] ` prefix.
std::string shortJsonMessage(const nlohmann::json::exception& error);

// ---- JSON paths (DESIGN.md notation: `bubbles[3].track[0].t`) and members ------------------

/// @brief `path.key`, or `key` at the top level (empty `path`).
std::string memberPath(const std::string& path, std::string_view key);

/// @brief `path[index]`.
std::string elementPath(const std::string& path, std::size_t index);

/// @brief The member `key` of the JSON object `object`, or nullptr when absent.
const nlohmann::json* findMember(const nlohmann::json& object, std::string_view key);

// ---- unknown keys --------------------------------------------------------------------------

/// @brief Lower case without `_` and `-`, so `sampleRate`, `Sample-Rate` and `sample_rate`
///        compare equal.
std::string normalizedKey(std::string_view key);

/// @brief The known key (or word) an unknown one was probably meant to be, or empty: equal up
///        to case and separators, a prefix of at least 3 characters, 1 edit away (2 for keys of
///        5+ characters), or, with `matchSharedStart`, sharing its first 4 characters
///        (`rotation` → `rotate`). Among several, the first of the nearest.
std::string closestKey(std::string_view unknown, std::span<const std::string_view> known, bool matchSharedStart);
inline std::string closestKey(std::string_view unknown, std::initializer_list<std::string_view> known,
                              bool matchSharedStart) {
  return closestKey(unknown, std::span<const std::string_view>(known.begin(), known.size()), matchSharedStart);
}

/// How a file format treats object keys it does not define.
struct KeyRules {
  /// Keys starting with `x_` or `x-` are extension fields, accepted anywhere and ignored
  /// (`fluidsound.bubbles/1`); when false they are unknown keys like any other.
  bool allowExtensionKeys = false;
  /// closestKey's `matchSharedStart` for the suggestion in an unknown-key error.
  bool matchSharedStart = true;
  /// The `found` part of an unknown-key error; empty leaves it out.
  std::string_view unknownKeyFound = "an unknown key";
};

// ---- parsing -------------------------------------------------------------------------------

/// Deepest nesting of arrays and objects an input file may have (scenes and bubble-track files
/// need fewer than 8 levels); beyond this limit the document is refused as it is read, before the
/// parse work and memory that grow with the depth.
inline constexpr std::size_t kMaxJsonDepth = 64;

/// Whether a key given twice in one JSON object is an error or the last one silently wins.
enum class DuplicateKeys { LastWins, Rejected };

/// @brief Parses JSON text.
/// @param file        the input file's name, for error messages
/// @param duplicates  with DuplicateKeys::Rejected a key given twice in one object is an error
///                    naming its JSON path (nlohmann would otherwise keep the last silently)
/// @throws InputError "expected valid JSON" with nlohmann's message (a number such as 1e999
///         included), "expected each key at most once in an object", or "expected at most 64
///         nested arrays and objects" naming the path of the first level too deep
nlohmann::json parseJson(std::string_view text, const std::string& file, DuplicateKeys duplicates);

/// @brief What stands at `path` when it is not a regular file an input can be read from: "no such
///        file", "a folder", "a FIFO", "a character device", "a block device", "a socket"; empty
///        for a regular file (symbolic links are followed). Inputs are read from regular files
///        only: a FIFO or a device would block or never end (docs/cli.md, "Inputs").
std::string nonRegularInput(const std::filesystem::path& path);

/// @brief The whole content of an input file, which must be a regular file.
/// @throws InputError "expected a readable file" if `path` does not exist, is not a regular file
///         (a folder, FIFO, device, socket) or cannot be read
std::string readInputFile(const std::filesystem::path& path);

/// @brief Everything on standard input (`-` as an input file, as in sox and ffmpeg).
/// @throws InputError naming `name` if it cannot be read
std::string readStandardInput(const std::string& name);

// ---- the validator -------------------------------------------------------------------------

/// @brief Reads typed values out of one parsed JSON input file. Every check that fails throws
///        InputError(file, JSON path, expected, found); `found` is describe(value), or kMissing
///        for an absent required key. Paths are built by the caller with memberPath and
///        elementPath; `parentPath` is the path of `parent` ("" for the document root).
class JsonValidator {
 public:
  using json = nlohmann::json;

  /// @param file   named in every error; must outlive the validator
  /// @param rules  how rejectUnknownKeys treats keys the format does not define
  JsonValidator(const std::string& file, KeyRules rules) : file_(file), rules_(rules) {}

  /// @brief Throws InputError(the file, field, expected, found).
  [[noreturn]] void fail(const std::string& field, const std::string& expected,
                         const std::string& found) const;

  /// @brief Checks that `root` is an object whose "format" is the string `tag`, before any other
  ///        key, so a file of another format or version says so rather than tripping on its keys.
  void requireFormat(const json& root, std::string_view tag) const;

  /// @brief Every key of `object` (at `path`) must be one of `known`, except extension keys where
  ///        the rules allow them. The error for another key expects "one of KNOWN" plus the
  ///        closest known key (`(did you mean 'radius'?)`) or, if none and extension keys are
  ///        allowed, `(or an extension key starting with x_ or x-)`.
  void rejectUnknownKeys(const json& object, const std::string& path,
                         std::initializer_list<std::string_view> known) const;

  /// @brief Requires `value` (at `path`) to be an object.
  void requireObject(const json& value, const std::string& path, const std::string& expected) const;
  /// @return the member `key` of `parent`, which must be present and an object
  const json& requiredObject(const json& parent, const std::string& parentPath,
                             std::string_view key, const std::string& expected) const;
  /// @return the member `key` of `parent` if it is an object, or nullptr when absent
  const json* optionalObject(const json& parent, const std::string& parentPath,
                             std::string_view key, const std::string& expected) const;

  /// @return the member `key` of `parent`, which must be present and an array
  const json& requiredArray(const json& parent, const std::string& parentPath, std::string_view key,
                            const std::string& expected) const;
  /// @return the member `key` of `parent` if it is an array, or nullptr when absent
  const json* optionalArray(const json& parent, const std::string& parentPath, std::string_view key,
                            const std::string& expected) const;

  /// @brief A finite JSON number for which `isValid(number)` holds (a `bool(double)` callable
  ///        such as positive, nonNegative, anyValue or a lambda).
  template <class Predicate>
  double number(const json& value, const std::string& path, const std::string& expected,
                Predicate isValid) const {
    if (!value.is_number()) fail(path, expected, describe(value));
    const double v = value.get<double>();
    if (!std::isfinite(v) || !isValid(v)) fail(path, expected, describe(value));
    return v;
  }

  /// @brief As number(), for the member `key` of `parent`, which must be present.
  template <class Predicate>
  double requiredNumber(const json& parent, const std::string& parentPath, std::string_view key,
                        const std::string& expected, Predicate isValid) const {
    const json* value = findMember(parent, key);
    if (value == nullptr) fail(memberPath(parentPath, key), expected, std::string(kMissing));
    return number(*value, memberPath(parentPath, key), expected, isValid);
  }

  /// @brief As number(), for the member `key` of `parent`.
  /// @return the number, or `fallback` when absent
  template <class Predicate>
  double optionalNumber(const json& parent, const std::string& parentPath, std::string_view key,
                        double fallback, const std::string& expected, Predicate isValid) const {
    const json* value = findMember(parent, key);
    return value == nullptr ? fallback
                            : number(*value, memberPath(parentPath, key), expected, isValid);
  }

  /// @brief An integer in [low, high]: a JSON integer, or a number without fraction part (7.0)
  ///        up to 2^53, the largest such number that is exact.
  std::uint64_t wholeNumber(const json& value, const std::string& path, const std::string& expected,
                            std::uint64_t low, std::uint64_t high) const;

  /// @brief [x, y, z]: exactly 3 finite numbers, expected as "an array of 3 numbers [x, y, z]
  ///        (UNIT)" and each as "a number (UNIT)".
  Vec3 vector(const json& value, const std::string& path, const std::string& unit) const;
  /// @brief As vector(), for the member `key` of `parent`, which must be present.
  Vec3 requiredVector(const json& parent, const std::string& parentPath, std::string_view key,
                      const std::string& unit) const;

  /// @brief A JSON string.
  const std::string& text(const json& value, const std::string& path,
                          const std::string& expected) const;
  /// @brief A JSON string that is not empty.
  const std::string& nonEmptyText(const json& value, const std::string& path,
                                  const std::string& expected) const;

 private:
  const std::string& file_;
  KeyRules rules_;
};

/// Predicates for JsonValidator::number and its variants.
inline bool positive(double v) { return v > 0; }
inline bool nonNegative(double v) { return v >= 0; }
inline bool anyValue(double) { return true; }

}  // namespace fluidsound::io
