// io/bubble_track_file.cpp — `fluidsound.bubbles/1` (docs/bubbles-format.md): JSON through
// nlohmann-json, validated field by field into acoustics::BubbleTrackSet, and written back.
#include "io/bubble_track_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "io/atomic_file.h"
#include "io/input_error.h"

namespace fluidsound::io {
namespace {

using acoustics::BubbleTrack;
using acoustics::BubbleTrackSet;
using acoustics::TrackSample;
using nlohmann::json;

constexpr std::string_view kFormatTag = "fluidsound.bubbles/1";

/// Longest string quoted in an error message, in bytes; a longer one is cut and marked "...".
constexpr std::size_t kMaxQuotedBytes = 60;

/// What `found` says when a required key is absent.
constexpr std::string_view kMissing = "nothing (required)";

// ---- error text helpers -------------------------------------------------------------------------

/// A number as JSON writes it: the shortest text that reads back to the same double.
std::string formatNumber(double value) { return json(value).dump(); }

/// A short, one-line description of a JSON value for the `found` part of an error.
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
      std::string text = value.get<std::string>();
      if (text.size() <= kMaxQuotedBytes) return json(text).dump();
      std::size_t cut = kMaxQuotedBytes;
      while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xc0) == 0x80) --cut;  // UTF-8
      return json(text.substr(0, cut)).dump() + "...";
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

/// nlohmann's message without its `[json.exception.parse_error.101] ` prefix.
std::string shortJsonMessage(const json::exception& error) {
  std::string text = error.what();
  if (!text.empty() && text.front() == '[') {
    const std::size_t end = text.find("] ");
    if (end != std::string::npos) text.erase(0, end + 2);
  }
  return text;
}

std::string memberPath(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string elementPath(const std::string& path, std::size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

/// Keys starting with `x_` or `x-` are extension fields: accepted anywhere and ignored.
bool isExtensionKey(std::string_view key) {
  return key.size() > 2 && key[0] == 'x' && (key[1] == '_' || key[1] == '-');
}

/// Lower case without `_` and `-`, so `sampleRate`, `Sample-Rate` and `sample_rate` compare equal.
std::string normalizedKey(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c != '_' && c != '-') out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

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

/// The known key an unknown one was probably meant to be, or empty: equal up to case and
/// separators, a prefix of at least 3 characters, or 1 edit away (2 for keys of 5+ characters).
std::string closestKey(std::string_view unknown, std::initializer_list<std::string_view> known) {
  const std::string typed = normalizedKey(unknown);
  std::string best;
  std::size_t bestDistance = std::string::npos;
  for (std::string_view candidate : known) {
    const std::string target = normalizedKey(candidate);
    std::size_t distance = editDistance(typed, target);
    if (typed.size() >= 3 && target.starts_with(typed))
      distance = std::min<std::size_t>(distance, 1);
    const std::size_t allowed = target.size() >= 5 ? 2 : 1;
    if (distance <= allowed && distance < bestDistance) {
      best = std::string(candidate);
      bestDistance = distance;
    }
  }
  return best;
}

// ---- the validating reader ----------------------------------------------------------------------

/// Turns a parsed JSON document into a BubbleTrackSet, or throws InputError at the first problem.
class TrackSetReader {
 public:
  TrackSetReader(const std::string& fileName, TransferValues transfer)
      : file_(fileName), transferRule_(transfer) {}

  BubbleTrackSet read(const json& root) {
    if (!root.is_object())
      fail("", "a JSON object (a fluidsound.bubbles/1 document)", describe(root));
    // The tag first: a file of another format or version should say so, not trip on its keys.
    const json* format = find(root, "format");
    // Built by append: g++ 12 warns falsely (-Wrestrict, GCC bug 105329) on "literal" + string&&.
    std::string quotedTag(1, '"');
    quotedTag.append(kFormatTag).push_back('"');
    if (format == nullptr) fail("format", quotedTag, std::string(kMissing));
    if (!format->is_string() || format->get<std::string>() != kFormatTag) {
      fail("format", quotedTag, describe(*format));
    }
    rejectUnknownKeys(root, "", {"format", "sample_rate", "duration", "listeners", "bubbles"});

    BubbleTrackSet set;
    if (const json* rate = find(root, "sample_rate")) {
      set.sampleRate =
          number(*rate, "sample_rate", "a number > 0 (Hz)", [](double v) { return v > 0; });
    }
    if (const json* duration = find(root, "duration")) {
      set.duration =
          number(*duration, "duration", "a number > 0 (seconds)", [](double v) { return v > 0; });
    }
    if (const json* listeners = find(root, "listeners")) {
      if (!listeners->is_array())
        fail("listeners", "an array of listener names (strings)", describe(*listeners));
      for (std::size_t i = 0; i < listeners->size(); ++i) {
        const json& name = (*listeners)[i];
        if (!name.is_string())
          fail(elementPath("listeners", i), "a string (listener name)", describe(name));
        set.listeners.push_back(name.get<std::string>());
      }
    }
    channelCount_ = set.channelCount();
    transferExpected_ = "an array of " + std::to_string(channelCount_) +
                        (channelCount_ == 1 ? " number" : " numbers") + " (one per listener" +
                        (set.listeners.empty() ? "; no listeners: one channel)" : ")");

    const json* bubbles = find(root, "bubbles");
    if (bubbles == nullptr) fail("bubbles", "an array of bubbles", std::string(kMissing));
    if (!bubbles->is_array()) fail("bubbles", "an array of bubbles", describe(*bubbles));
    set.bubbles.reserve(bubbles->size());
    for (std::size_t i = 0; i < bubbles->size(); ++i) {
      set.bubbles.push_back(bubble((*bubbles)[i], elementPath("bubbles", i)));
    }
    // With TransferValues::Optional, `transfer` is all or nothing: a file written before the
    // transfer stage has none.
    if (!firstWithTransfer_.empty() && !firstWithoutTransfer_.empty()) {
      fail(memberPath(firstWithoutTransfer_, "transfer"),
           transferExpected_ + ", as in " + firstWithTransfer_, std::string(kMissing));
    }
    return set;
  }

 private:
  [[noreturn]] void fail(const std::string& field, const std::string& expected,
                         const std::string& found) const {
    throw InputError(file_, field, expected, found);
  }

  static const json* find(const json& object, std::string_view key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  void rejectUnknownKeys(const json& object, const std::string& path,
                         std::initializer_list<std::string_view> known) const {
    for (const auto& item : object.items()) {
      const std::string& key = item.key();
      if (isExtensionKey(key) || std::find(known.begin(), known.end(), key) != known.end())
        continue;
      std::string expected = "one of ";
      for (auto it = known.begin(); it != known.end(); ++it) {
        expected += (it == known.begin() ? "" : ", ") + std::string(*it);
      }
      const std::string suggestion = closestKey(key, known);
      expected += suggestion.empty() ? " (or an extension key starting with x_ or x-)"
                                     : " (did you mean '" + suggestion + "'?)";
      fail(memberPath(path, key), expected, "");
    }
  }

  /// A finite JSON number that satisfies `isValid`, else an error naming `path` and `expected`.
  template <class Predicate>
  double number(const json& value, const std::string& path, const std::string& expected,
                Predicate isValid) const {
    if (!value.is_number()) fail(path, expected, describe(value));
    const double v = value.get<double>();
    if (!std::isfinite(v) || !isValid(v)) fail(path, expected, describe(value));
    return v;
  }

  BubbleTrack bubble(const json& object, const std::string& path) {
    if (!object.is_object()) fail(path, "an object with radius and birth", describe(object));
    rejectUnknownKeys(object, path, {"radius", "birth", "amplitude", "track"});
    BubbleTrack bubble;
    const std::string radiusExpected = "a number > 0 (metres)";
    const json* radius = find(object, "radius");
    if (radius == nullptr) fail(memberPath(path, "radius"), radiusExpected, std::string(kMissing));
    bubble.radius =
        number(*radius, memberPath(path, "radius"), radiusExpected, [](double v) { return v > 0; });
    const std::string birthExpected = "a number >= 0 (seconds)";
    const json* birth = find(object, "birth");
    if (birth == nullptr) fail(memberPath(path, "birth"), birthExpected, std::string(kMissing));
    bubble.birth =
        number(*birth, memberPath(path, "birth"), birthExpected, [](double v) { return v >= 0; });
    if (const json* amplitude = find(object, "amplitude")) {
      bubble.amplitude = number(*amplitude, memberPath(path, "amplitude"),
                                "a number > 0 (Pa at 1 m)", [](double v) { return v > 0; });
    }
    if (const json* track = find(object, "track")) {
      const std::string trackPath = memberPath(path, "track");
      if (!track->is_array()) fail(trackPath, "an array of track samples", describe(*track));
      bubble.track.reserve(track->size());
      for (std::size_t j = 0; j < track->size(); ++j) {
        bubble.track.push_back(sample((*track)[j], trackPath, j, bubble));
      }
    }
    return bubble;
  }

  /// Sample j of a bubble's track; `bubble` holds the radius and the samples before j.
  TrackSample sample(const json& object, const std::string& trackPath, std::size_t j,
                     const BubbleTrack& bubble) {
    const std::string path = elementPath(trackPath, j);
    if (!object.is_object()) fail(path, "an object with t, depth and transfer", describe(object));
    rejectUnknownKeys(object, path, {"t", "depth", "transfer", "position"});
    TrackSample sample;

    const std::string timeExpected = "a number >= 0 (seconds)";
    const json* time = find(object, "t");
    if (time == nullptr) fail(memberPath(path, "t"), timeExpected, std::string(kMissing));
    sample.time =
        number(*time, memberPath(path, "t"), timeExpected, [](double v) { return v >= 0; });
    if (j > 0 && !(sample.time > bubble.track.back().time)) {
      fail(memberPath(path, "t"),
           "a time greater than track[" + std::to_string(j - 1) +
               "].t = " + formatNumber(bubble.track.back().time) + " (samples in time order)",
           describe(*time));
    }

    const std::string depthExpected = "a number > radius (" + formatNumber(bubble.radius) + " m)";
    const json* depth = find(object, "depth");
    if (depth == nullptr) fail(memberPath(path, "depth"), depthExpected, std::string(kMissing));
    sample.depth = number(*depth, memberPath(path, "depth"), depthExpected,
                          [&](double v) { return v > bubble.radius; });

    if (const json* transfer = find(object, "transfer")) {
      const std::string transferPath = memberPath(path, "transfer");
      if (!transfer->is_array() || transfer->size() != channelCount_) {
        fail(transferPath, transferExpected_, describe(*transfer));
      }
      for (std::size_t k = 0; k < transfer->size(); ++k) {
        sample.transfer.push_back(number((*transfer)[k], elementPath(transferPath, k),
                                         "a number (pressure ratio)", [](double) { return true; }));
      }
      if (firstWithTransfer_.empty()) firstWithTransfer_ = path;
    } else if (transferRule_ == TransferValues::Required) {
      fail(memberPath(path, "transfer"), transferExpected_, std::string(kMissing));
    } else if (firstWithoutTransfer_.empty()) {
      firstWithoutTransfer_ = path;
    }

    if (const json* position = find(object, "position")) {
      const std::string positionPath = memberPath(path, "position");
      if (!position->is_array() || position->size() != 3) {
        fail(positionPath, "an array of 3 numbers [x, y, z] (metres)", describe(*position));
      }
      std::array<double, 3> xyz{};
      for (std::size_t k = 0; k < 3; ++k) {
        xyz[k] = number((*position)[k], elementPath(positionPath, k), "a number (metres)",
                        [](double) { return true; });
      }
      sample.position = xyz;
    }
    return sample;
  }

  const std::string& file_;
  TransferValues transferRule_;
  std::size_t channelCount_ = 1;
  std::string transferExpected_;
  std::string firstWithTransfer_;     ///< path of the first sample with `transfer`, if any
  std::string firstWithoutTransfer_;  ///< path of the first sample without it, if any
};

// ---- writing ------------------------------------------------------------------------------------

/// The document text: header fields one per line, one line per bubble and per track sample, so
/// large files stay readable and diff well. Numbers are nlohmann's shortest exact form.
std::string formatTrackSet(const BubbleTrackSet& set) {
  std::ostringstream out;
  out << "{\n  \"format\": " << json(kFormatTag).dump() << ",\n";
  out << "  \"sample_rate\": " << formatNumber(set.sampleRate) << ",\n";
  if (set.duration) out << "  \"duration\": " << formatNumber(*set.duration) << ",\n";
  if (!set.listeners.empty()) out << "  \"listeners\": " << json(set.listeners).dump() << ",\n";
  out << "  \"bubbles\": [";
  for (std::size_t i = 0; i < set.bubbles.size(); ++i) {
    const BubbleTrack& bubble = set.bubbles[i];
    out << (i == 0 ? "\n" : ",\n") << "    {\"radius\":" << formatNumber(bubble.radius)
        << ",\"birth\":" << formatNumber(bubble.birth);
    if (bubble.amplitude) out << ",\"amplitude\":" << formatNumber(*bubble.amplitude);
    if (!bubble.track.empty()) {
      out << ",\"track\":[";
      for (std::size_t j = 0; j < bubble.track.size(); ++j) {
        const TrackSample& s = bubble.track[j];
        nlohmann::ordered_json line;
        line["t"] = s.time;
        line["depth"] = s.depth;
        if (!s.transfer.empty()) line["transfer"] = s.transfer;
        if (s.position) line["position"] = *s.position;
        out << (j == 0 ? "\n      " : ",\n      ") << line.dump();
      }
      out << "\n    ]";
    }
    out << "}";
  }
  out << (set.bubbles.empty() ? "]\n}\n" : "\n  ]\n}\n");
  return out.str();
}

}  // namespace

acoustics::BubbleTrackSet parseBubbleTracks(std::string_view text, const std::string& fileName) {
  return parseBubbleTracks(text, fileName, TransferValues::Required);
}

acoustics::BubbleTrackSet parseBubbleTracks(std::string_view text, const std::string& fileName,
                                            TransferValues transfer) {
  json root;
  try {
    root = json::parse(text.begin(), text.end());
  } catch (const json::exception& error) {  // parse_error, or out_of_range for 1e999
    throw InputError(fileName, "", "valid JSON", shortJsonMessage(error));
  }
  return TrackSetReader(fileName, transfer).read(root);
}

acoustics::BubbleTrackSet readBubbleTracks(const std::filesystem::path& path) {
  return readBubbleTracks(path, TransferValues::Required);
}

acoustics::BubbleTrackSet readBubbleTracks(const std::filesystem::path& path,
                                           TransferValues transfer) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError(name, "", "a readable file", "no such file");
  if (std::filesystem::is_directory(path, ec))
    throw InputError(name, "", "a readable file", "a folder");
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    throw InputError(name, "", "a readable file", std::generic_category().message(errno));
  }
  std::string text;
  char buffer[1 << 16];
  std::size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, count);
  const bool failed = std::ferror(file) != 0;
  const int error = errno;
  std::fclose(file);
  if (failed) throw InputError(name, "", "a readable file", std::generic_category().message(error));
  return parseBubbleTracks(text, name, transfer);
}

void writeBubbleTracks(const std::filesystem::path& path, const acoustics::BubbleTrackSet& tracks) {
  std::string text;
  try {
    text = formatTrackSet(tracks);
  } catch (const json::exception& error) {  // a listener name that is not valid UTF-8
    throw std::invalid_argument(path.string() +
                                ": cannot write bubble tracks: " + shortJsonMessage(error));
  }
  // Never write a file that this reader would reject (NaN, a depth below the radius, …); the
  // simulation writes tracks before the transfer stage, so transfer may be absent (all or none).
  try {
    parseBubbleTracks(text, path.string(), TransferValues::Optional);
  } catch (const InputError& error) {
    throw std::invalid_argument("cannot write invalid bubble tracks: " + std::string(error.what()));
  }

  AtomicFile output(path);
  std::FILE* file = std::fopen(output.temporaryPath().c_str(), "wb");
  if (file == nullptr) {
    throw OutputError(path.string() + ": cannot write: " + std::generic_category().message(errno));
  }
  const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  const int writeError = errno;
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed) {
    const int error = written ? errno : writeError;
    throw OutputError(path.string() + ": cannot write: " + std::generic_category().message(error));
  }
  output.commit();
}

}  // namespace fluidsound::io
