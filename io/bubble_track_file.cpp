// io/bubble_track_file.cpp — `fluidsound.bubbles/1` (docs/bubbles-format.md): read in one pass when
// plain (bubble_track_fast_reader.h), else through nlohmann-json and validated field by field into
// acoustics::BubbleTrackSet; written back as text directly.
#include "io/bubble_track_file.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include "io/bubble_track_fast_reader.h"
#include "io/bubble_track_limits.h"
#include "io/input_error.h"
#include "io/json_validation.h"
#include "io/output_file.h"

namespace fluidsound::io {
namespace {

using acoustics::BubbleTrack;
using acoustics::BubbleTrackSet;
using acoustics::TrackSample;
using nlohmann::json;

constexpr std::string_view kFormatTag = "fluidsound.bubbles/1";

/// Unlike a scene, a bubble-track file may carry extension keys (`x_…`, `x-…`) anywhere; an
/// unknown-key error leaves `found` out and suggests only close spellings.
constexpr KeyRules kBubbleKeyRules{
    .allowExtensionKeys = true, .matchSharedStart = false, .unknownKeyFound = ""};

/// A bound as a reader writes it: 1e-06, 1, 11000.
std::string boundText(double bound) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", bound);
  return text;
}

/// "a number from LOW to HIGH (UNIT)", the expected text of a bounded field.
std::string rangeText(double low, double high, const std::string& unit) {
  return "a number from " + boundText(low) + " to " + boundText(high) + " (" + unit + ")";
}

// ---- the validating reader ----------------------------------------------------------------------

/// Turns a parsed JSON document into a BubbleTrackSet, or throws InputError at the first problem.
class TrackSetReader {
 public:
  TrackSetReader(const std::string& fileName, TransferValues transfer)
      : check_(fileName, kBubbleKeyRules), transferRule_(transfer) {}

  BubbleTrackSet read(const json& root) {
    check_.requireFormat(root, kFormatTag);
    check_.rejectUnknownKeys(root, "",
                             {"format", "sample_rate", "duration", "listeners", "heads", "hrtf",
                              "bubbles"});

    BubbleTrackSet set;
    if (const json* rate = findMember(root, "sample_rate")) {
      set.sampleRate = static_cast<double>(check_.wholeNumber(
          *rate, "sample_rate",
          "an integer from " + std::to_string(kMinTrackSampleRate) + " to " + std::to_string(kMaxTrackSampleRate) + " (Hz)",
          kMinTrackSampleRate, kMaxTrackSampleRate));
    }
    if (const json* duration = findMember(root, "duration")) {
      set.duration = check_.number(*duration, "duration",
                                   "a number > 0 and <= " + boundText(kMaxTrackTime) + " (seconds)", isTrackDuration);
    }
    if (const json* listeners =
            check_.optionalArray(root, "", "listeners", "an array of listener names (strings)")) {
      for (std::size_t i = 0; i < listeners->size(); ++i) {
        set.listeners.push_back(
            check_.text((*listeners)[i], elementPath("listeners", i), "a string (listener name)"));
      }
    }
    if (const json* heads = check_.optionalArray(root, "", "heads", "an array of heads"))
      for (std::size_t i = 0; i < heads->size(); ++i)
        set.heads.push_back(head((*heads)[i], elementPath("heads", i), set));
    if (const json* hrtf = findMember(root, "hrtf"))
      set.hrtf = check_.nonEmptyText(*hrtf, "hrtf", "the path of a SOFA file (string)");
    channelCount_ = set.channelCount();
    transferExpected_ = "an array of " + std::to_string(channelCount_) +
                        (channelCount_ == 1 ? " number" : " numbers") + " (one per listener" +
                        (set.listeners.empty() ? "; no listeners: one channel)" : ")");

    const json& bubbles = check_.requiredArray(root, "", "bubbles", "an array of bubbles");
    set.bubbles.reserve(bubbles.size());
    for (std::size_t i = 0; i < bubbles.size(); ++i) {
      set.bubbles.push_back(bubble(bubbles[i], elementPath("bubbles", i)));
      if (!set.heads.empty()) requireDirection(set.bubbles.back(), elementPath("bubbles", i), set);
    }
    // With TransferValues::Optional, `transfer` is all or nothing: a file written before the
    // transfer stage has none.
    if (!firstWithTransfer_.empty() && !firstWithoutTransfer_.empty()) {
      check_.fail(memberPath(firstWithoutTransfer_, "transfer"),
                  transferExpected_ + ", as in " + firstWithTransfer_, std::string(kMissing));
    }
    return set;
  }

 private:
  /// A listener that is a head: a listener's name (once), its centre and its orientation.
  acoustics::ListenerHead head(const json& object, const std::string& path, const BubbleTrackSet& set) {
    check_.requireObject(object, path, "an object with listener, position, facing and up");
    check_.rejectUnknownKeys(object, path, {"listener", "position", "facing", "up"});
    acoustics::ListenerHead head;
    const std::string namePath = memberPath(path, "listener");
    const std::string nameExpected = "the name of a listener in listeners, not used by another head";
    const json* name = findMember(object, "listener");
    if (name == nullptr) check_.fail(namePath, nameExpected, std::string(kMissing));
    head.listener = check_.text(*name, namePath, nameExpected);
    if (std::find(set.listeners.begin(), set.listeners.end(), head.listener) == set.listeners.end() ||
        set.head(head.listener) != nullptr)
      check_.fail(namePath, nameExpected, describe(*name));
    head.position = check_.requiredVector(object, path, "position", "metres");
    head.facing = check_.requiredVector(object, path, "facing", "direction");
    head.up = check_.requiredVector(object, path, "up", "direction");
    if (!acoustics::isHeadOrientation(head.facing, head.up))
      check_.fail(memberPath(path, "up"), "a direction not parallel to facing, both non-zero",
                  describe(object["up"]));
    return head;
  }

  /// With heads, every bubble needs a direction: a track sample with a position.
  void requireDirection(const BubbleTrack& bubble, const std::string& path, const BubbleTrackSet& set) {
    for (const TrackSample& s : bubble.track)
      if (s.position) return;
    check_.fail(memberPath(path, "track"),
                "a track sample with a position (listener \"" + set.heads.front().listener +
                    "\" is a head, which hears each bubble from its direction)",
                bubble.track.empty() ? "no track" : "no position");
  }

  /// A bubble's `ring`: the resonator's frequency and decay, and per listener a gain and a phase.
  acoustics::ResonatorRing resonatorRing(const json& object, const std::string& path) {
    check_.rejectUnknownKeys(object, path, {"frequency", "decay_rate", "gain", "phase"});
    acoustics::ResonatorRing ring;
    ring.frequency = check_.requiredNumber(object, path, "frequency", rangeText(1, 100000, "Hz"),
                                           [](double v) { return v >= 1 && v <= 100000; });
    ring.decayRate = check_.requiredNumber(object, path, "decay_rate", rangeText(0.1, 1e6, "1/s"),
                                           [](double v) { return v >= 0.1 && v <= 1e6; });
    const auto list = [&](std::string_view key, double bound, const std::string& unit) {
      const std::string listPath = memberPath(path, key);
      const std::string expected = "an array of " + std::to_string(channelCount_) + " numbers (one per listener)";
      const json* values = findMember(object, key);
      if (values == nullptr) check_.fail(listPath, expected, std::string(kMissing));
      if (!values->is_array() || values->size() != channelCount_) check_.fail(listPath, expected, describe(*values));
      std::vector<double> out;
      for (std::size_t k = 0; k < values->size(); ++k)
        out.push_back(check_.number((*values)[k], elementPath(listPath, k), rangeText(-bound, bound, unit),
                                    [bound](double v) { return v >= -bound && v <= bound; }));
      return out;
    };
    ring.gain = list("gain", kMaxTransfer, "ratio");
    for (std::size_t k = 0; k < ring.gain.size(); ++k)
      if (ring.gain[k] < 0) check_.fail(elementPath(memberPath(path, "gain"), k), "a number >= 0 (ratio)", formatNumber(ring.gain[k]));
    ring.phase = list("phase", 4.0, "radians");
    return ring;
  }

  BubbleTrack bubble(const json& object, const std::string& path) {
    check_.requireObject(object, path, "an object with radius and birth");
    check_.rejectUnknownKeys(object, path, {"radius", "birth", "amplitude", "rings", "track"});
    BubbleTrack bubble;
    bubble.radius = check_.requiredNumber(object, path, "radius",
                                          rangeText(kMinBubbleRadius, kMaxBubbleRadius, "metres"), isBubbleRadius);
    bubble.birth =
        check_.requiredNumber(object, path, "birth", rangeText(0, kMaxTrackTime, "seconds"), isTrackTime);
    if (const json* amplitude = findMember(object, "amplitude")) {
      bubble.amplitude = check_.number(*amplitude, memberPath(path, "amplitude"),
                                       rangeText(kMinBubbleAmplitude, kMaxBubbleAmplitude, "Pa at 1 m"),
                                       isBubbleAmplitude);
    }
    if (const json* rings = check_.optionalArray(object, path, "rings", "an array of rings")) {
      for (std::size_t k = 0; k < rings->size(); ++k) {
        const std::string ringPath = elementPath(memberPath(path, "rings"), k);
        check_.requireObject((*rings)[k], ringPath, "an object with frequency, decay_rate, gain and phase");
        bubble.rings.push_back(resonatorRing((*rings)[k], ringPath));
      }
    }
    if (const json* track =
            check_.optionalArray(object, path, "track", "an array of track samples")) {
      const std::string trackPath = memberPath(path, "track");
      bubble.track.reserve(track->size());
      for (std::size_t j = 0; j < track->size(); ++j)
        bubble.track.push_back(sample((*track)[j], trackPath, j, bubble));
    }
    return bubble;
  }

  /// Sample j of a bubble's track; `bubble` holds the radius and the samples before j.
  TrackSample sample(const json& object, const std::string& trackPath, std::size_t j,
                     const BubbleTrack& bubble) {
    const std::string path = elementPath(trackPath, j);
    check_.requireObject(object, path, "an object with t, depth and transfer");
    check_.rejectUnknownKeys(object, path, {"t", "depth", "transfer", "position"});
    TrackSample sample;

    sample.time = check_.requiredNumber(object, path, "t", rangeText(0, kMaxTrackTime, "seconds"), isTrackTime);
    if (j > 0 && !(sample.time > bubble.track.back().time)) {
      check_.fail(memberPath(path, "t"),
                  "a time greater than track[" + std::to_string(j - 1) + "].t = " +
                      formatNumber(bubble.track.back().time) + " (samples in time order)",
                  describe(object["t"]));
    }

    sample.depth = check_.requiredNumber(
        object, path, "depth",
        "a number > radius (" + formatNumber(bubble.radius) + " m) and <= " + boundText(kMaxBubbleDepth) + " (metres)",
        [&](double v) { return isBubbleDepth(v, bubble.radius); });

    if (const json* transfer = findMember(object, "transfer")) {
      const std::string transferPath = memberPath(path, "transfer");
      if (!transfer->is_array() || transfer->size() != channelCount_)
        check_.fail(transferPath, transferExpected_, describe(*transfer));
      for (std::size_t k = 0; k < transfer->size(); ++k) {
        sample.transfer.push_back(check_.number((*transfer)[k], elementPath(transferPath, k),
                                                rangeText(-kMaxTransfer, kMaxTransfer, "pressure ratio"),
                                                isTransfer));
      }
      if (firstWithTransfer_.empty()) firstWithTransfer_ = path;
    } else if (transferRule_ == TransferValues::Required) {
      check_.fail(memberPath(path, "transfer"), transferExpected_, std::string(kMissing));
    } else if (firstWithoutTransfer_.empty()) {
      firstWithoutTransfer_ = path;
    }

    if (const json* position = findMember(object, "position")) {
      const std::string positionPath = memberPath(path, "position");
      sample.position = check_.vector(*position, positionPath, "metres");
      for (std::size_t a = 0; a < 3; ++a)
        check_.number((*position)[a], elementPath(positionPath, a),
                      rangeText(-kMaxTrackCoordinate, kMaxTrackCoordinate, "metres"), isTrackCoordinate);
    }
    return sample;
  }

  JsonValidator check_;
  TransferValues transferRule_;
  std::size_t channelCount_ = 1;
  std::string transferExpected_;
  std::string firstWithTransfer_;     ///< path of the first sample with `transfer`, if any
  std::string firstWithoutTransfer_;  ///< path of the first sample without it, if any
};

// ---- writing ------------------------------------------------------------------------------------

/// Appends a number as nlohmann-json writes it: the shortest text that reads back to the same
/// double (its Grisu2 conversion, called directly so that no JSON value is built per number);
/// `null` for NaN and infinities, which the reader rejects.
void appendNumber(std::string& out, double value) {
  if (!std::isfinite(value)) {
    out += "null";
    return;
  }
  std::array<char, 64> buffer;
  char* const end = nlohmann::detail::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  out.append(buffer.data(), static_cast<std::size_t>(end - buffer.data()));
}

/// The document text: header fields one per line, one line per bubble and per track sample, so
/// large files stay readable and diff well. Numbers are nlohmann's shortest exact form; the text is
/// the same as dumping each sample as a JSON object (`{"t":…,"depth":…,"transfer":[…],
/// "position":[…]}`), written without building one.
std::string formatTrackSet(const BubbleTrackSet& set) {
  // About 60 characters per bubble line and 70 + 25 per number in a sample line: reserved once.
  std::size_t samples = 0, numbers = 0;
  for (const BubbleTrack& bubble : set.bubbles)
    for (const TrackSample& s : bubble.track) ++samples, numbers += s.transfer.size() + (s.position ? 3 : 0);
  std::string out;
  out.reserve(256 + 60 * set.bubbles.size() + 70 * samples + 25 * numbers);
  out += "{\n  \"format\": " + json(kFormatTag).dump() + ",\n";
  out += "  \"sample_rate\": ";
  appendNumber(out, set.sampleRate);
  out += ",\n";
  if (set.duration) {
    out += "  \"duration\": ";
    appendNumber(out, *set.duration);
    out += ",\n";
  }
  if (!set.listeners.empty()) out += "  \"listeners\": " + json(set.listeners).dump() + ",\n";
  if (!set.heads.empty()) {
    json heads = json::array();
    for (const acoustics::ListenerHead& h : set.heads)
      heads.push_back({{"listener", h.listener}, {"position", h.position}, {"facing", h.facing}, {"up", h.up}});
    out += "  \"heads\": " + heads.dump() + ",\n";
  }
  if (set.hrtf) out += "  \"hrtf\": " + json(*set.hrtf).dump() + ",\n";
  out += "  \"bubbles\": [";
  for (std::size_t i = 0; i < set.bubbles.size(); ++i) {
    const BubbleTrack& bubble = set.bubbles[i];
    out += i == 0 ? "\n    {\"radius\":" : ",\n    {\"radius\":";
    appendNumber(out, bubble.radius);
    out += ",\"birth\":";
    appendNumber(out, bubble.birth);
    if (bubble.amplitude) {
      out += ",\"amplitude\":";
      appendNumber(out, *bubble.amplitude);
    }
    for (std::size_t k = 0; k < bubble.rings.size(); ++k) {
      const acoustics::ResonatorRing& r = bubble.rings[k];
      out += k == 0 ? ",\"rings\":[{\"frequency\":" : ",{\"frequency\":";
      appendNumber(out, r.frequency);
      out += ",\"decay_rate\":";
      appendNumber(out, r.decayRate);
      for (const auto& [key, values] : {std::pair{",\"gain\":[", &r.gain}, std::pair{",\"phase\":[", &r.phase}}) {
        out += key;
        for (std::size_t k = 0; k < values->size(); ++k) {
          if (k > 0) out += ',';
          appendNumber(out, (*values)[k]);
        }
        out += ']';
      }
      out += k + 1 == bubble.rings.size() ? "}]" : "}";
    }
    if (!bubble.track.empty()) {
      out += ",\"track\":[";
      for (std::size_t j = 0; j < bubble.track.size(); ++j) {
        const TrackSample& s = bubble.track[j];
        out += j == 0 ? "\n      {\"t\":" : ",\n      {\"t\":";
        appendNumber(out, s.time);
        out += ",\"depth\":";
        appendNumber(out, s.depth);
        if (!s.transfer.empty()) {
          out += ",\"transfer\":[";
          for (std::size_t k = 0; k < s.transfer.size(); ++k) {
            if (k > 0) out += ',';
            appendNumber(out, s.transfer[k]);
          }
          out += ']';
        }
        if (s.position) {
          out += ",\"position\":[";
          for (std::size_t a = 0; a < 3; ++a) {
            if (a > 0) out += ',';
            appendNumber(out, (*s.position)[a]);
          }
          out += ']';
        }
        out += '}';
      }
      out += "\n    ]";
    }
    out += "}";
  }
  out += set.bubbles.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

}  // namespace

acoustics::BubbleTrackSet parseBubbleTracks(std::string_view text, const std::string& fileName) {
  return parseBubbleTracks(text, fileName, TransferValues::Required);
}

acoustics::BubbleTrackSet parseBubbleTracks(std::string_view text, const std::string& fileName,
                                            TransferValues transfer) {
  // The documents fluidsound writes are read in one pass; anything else (and every invalid
  // document, for its error message) goes through the JSON tree and the validator.
  if (std::optional<BubbleTrackSet> plain = parsePlainBubbleTracks(text, transfer)) return std::move(*plain);
  const json root = parseJson(text, fileName, DuplicateKeys::Rejected);
  return TrackSetReader(fileName, transfer).read(root);
}

acoustics::BubbleTrackSet readBubbleTracks(const std::filesystem::path& path) {
  return readBubbleTracks(path, TransferValues::Required);
}

acoustics::BubbleTrackSet readBubbleTracks(const std::filesystem::path& path,
                                           TransferValues transfer) {
  if (path == kStandardInput) return parseBubbleTracks(readStandardInput("standard input"), "standard input", transfer);
  return parseBubbleTracks(readInputFile(path), path.string(), transfer);
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
    if (!parsePlainBubbleTracks(text, TransferValues::Optional))
      parseBubbleTracks(text, path.string(), TransferValues::Optional);
  } catch (const InputError& error) {
    throw std::invalid_argument("cannot write invalid bubble tracks: " + std::string(error.what()));
  }

  writeOutputFile(path, text);  // the output rule (output_file.h)
}

}  // namespace fluidsound::io
