// io/bubble_track_fast_reader.cpp — see bubble_track_fast_reader.h.
#include "io/bubble_track_fast_reader.h"

#include "io/bubble_track_limits.h"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <system_error>
#include <utility>

namespace fluidsound::io {
namespace {

using acoustics::BubbleTrack;
using acoustics::BubbleTrackSet;
using acoustics::TrackSample;

constexpr std::string_view kFormatTag = "fluidsound.bubbles/1";

/// A forward-only reader of JSON tokens. Every method returns false on anything outside the plain
/// subset; the caller gives up at the first false.
class Cursor {
 public:
  explicit Cursor(std::string_view text) : at_(text.data()), end_(text.data() + text.size()) {}

  void skipSpace() {
    while (at_ != end_ && (*at_ == ' ' || *at_ == '\n' || *at_ == '\r' || *at_ == '\t')) ++at_;
  }
  /// Consumes `c` after optional whitespace.
  bool take(char c) {
    skipSpace();
    if (at_ == end_ || *at_ != c) return false;
    ++at_;
    return true;
  }
  /// The next non-space character (0 at the end), not consumed.
  char peek() {
    skipSpace();
    return at_ == end_ ? '\0' : *at_;
  }
  bool atEnd() {
    skipSpace();
    return at_ == end_;
  }
  /// A string of printable ASCII without escapes (what nlohmann-json reads as the same bytes).
  bool string(std::string_view& out) {
    if (!take('"')) return false;
    const char* const first = at_;
    while (at_ != end_ && *at_ != '"') {
      const unsigned char c = static_cast<unsigned char>(*at_);
      if (c < 0x20 || c >= 0x7F || c == '\\') return false;
      ++at_;
    }
    if (at_ == end_) return false;
    out = std::string_view(first, static_cast<std::size_t>(at_ - first));
    ++at_;
    return true;
  }
  /// A finite JSON number (RFC 8259 grammar), as a double correctly rounded.
  bool number(double& out) {
    skipSpace();
    const char* p = at_;
    const char* const first = p;
    if (p != end_ && *p == '-') ++p;
    if (p == end_ || !isDigit(*p)) return false;
    if (*p == '0') ++p;
    else
      while (p != end_ && isDigit(*p)) ++p;
    bool integer = true;
    if (p != end_ && *p == '.') {
      ++p;
      if (p == end_ || !isDigit(*p)) return false;
      while (p != end_ && isDigit(*p)) ++p;
      integer = false;
    }
    if (p != end_ && (*p == 'e' || *p == 'E')) {
      ++p;
      if (p != end_ && (*p == '+' || *p == '-')) ++p;
      if (p == end_ || !isDigit(*p)) return false;
      while (p != end_ && isDigit(*p)) ++p;
      integer = false;
    }
    // nlohmann-json reads "-0" as the integer 0, which becomes +0.0, where from_chars gives −0.0.
    if (integer && *first == '-' && p - first == 2 && first[1] == '0') return false;
    const auto [last, error] = std::from_chars(first, p, out);
    if (error != std::errc() || last != p || !std::isfinite(out)) return false;
    at_ = p;
    return true;
  }

 private:
  static bool isDigit(char c) { return c >= '0' && c <= '9'; }
  const char* at_;
  const char* end_;
};

/// Reads the members of an object (the opening brace already taken): for each key, `member(key)`
/// reads its value and returns false to give up. Keys outside `known` (bit per index) or repeated
/// give up too.
template <std::size_t N, class Member>
bool members(Cursor& in, const std::string_view (&known)[N], Member member) {
  unsigned seen = 0;
  if (in.take('}')) return true;
  do {
    std::string_view key;
    if (!in.string(key) || !in.take(':')) return false;
    std::size_t index = N;
    for (std::size_t k = 0; k < N; ++k)
      if (key == known[k]) index = k;
    if (index == N || (seen >> index) & 1u) return false;
    seen |= 1u << index;
    if (!member(index)) return false;
  } while (in.take(','));
  return in.take('}');
}

/// Reads an array (opening bracket not yet taken), calling element() for each element.
template <class Element>
bool elements(Cursor& in, Element element) {
  if (!in.take('[')) return false;
  if (in.take(']')) return true;
  do
    if (!element()) return false;
  while (in.take(','));
  return in.take(']');
}

class PlainReader {
 public:
  explicit PlainReader(TransferValues rule) : rule_(rule) {}

  bool document(std::string_view text, BubbleTrackSet& set) {
    Cursor in(text);
    static constexpr std::string_view keys[] = {"format", "sample_rate", "duration", "listeners", "bubbles"};
    bool format = false, bubbles = false;
    if (!in.take('{')) return false;
    const bool ok = members(in, keys, [&](std::size_t key) {
      switch (key) {
        case 0: {
          std::string_view tag;
          format = in.string(tag) && tag == kFormatTag;
          return format;
        }
        case 1: return in.number(set.sampleRate) && isTrackSampleRate(set.sampleRate);
        case 2: {
          double duration = 0.0;
          if (!in.number(duration) || !isTrackDuration(duration)) return false;
          set.duration = duration;
          return true;
        }
        case 3:
          return elements(in, [&] {
            std::string_view name;
            if (!in.string(name)) return false;
            set.listeners.emplace_back(name);
            return true;
          });
        default:
          bubbles = true;
          return elements(in, [&] { return bubble(in, set); });
      }
    });
    if (!ok || !format || !bubbles || !in.atEnd()) return false;
    // Transfer lists are checked once the listeners are known (they may follow the bubbles).
    const std::size_t channels = set.channelCount();
    for (const BubbleTrack& b : set.bubbles)
      for (const TrackSample& s : b.track)
        if (!s.transfer.empty() && s.transfer.size() != channels) return false;
    if (rule_ == TransferValues::Required && withoutTransfer_) return false;
    return !(withTransfer_ && withoutTransfer_);
  }

 private:
  bool bubble(Cursor& in, BubbleTrackSet& set) {
    static constexpr std::string_view keys[] = {"radius", "birth", "amplitude", "track"};
    BubbleTrack b;
    bool radius = false, birth = false;
    if (!in.take('{')) return false;
    const bool ok = members(in, keys, [&](std::size_t key) {
      switch (key) {
        case 0: return radius = in.number(b.radius) && isBubbleRadius(b.radius);
        case 1: return birth = in.number(b.birth) && isTrackTime(b.birth);
        case 2: {
          double amplitude = 0.0;
          if (!in.number(amplitude) || !isBubbleAmplitude(amplitude)) return false;
          b.amplitude = amplitude;
          return true;
        }
        default: return elements(in, [&] { return sample(in, b); });
      }
    });
    if (!ok || !radius || !birth) return false;
    // Depth against the radius and the time order, once the radius is known.
    for (std::size_t j = 0; j < b.track.size(); ++j) {
      if (!isBubbleDepth(b.track[j].depth, b.radius)) return false;
      if (j > 0 && !(b.track[j].time > b.track[j - 1].time)) return false;
    }
    set.bubbles.push_back(std::move(b));
    return true;
  }

  bool sample(Cursor& in, BubbleTrack& b) {
    static constexpr std::string_view keys[] = {"t", "depth", "transfer", "position"};
    TrackSample s;
    bool time = false, depth = false, transfer = false;
    if (!in.take('{')) return false;
    const bool ok = members(in, keys, [&](std::size_t key) {
      switch (key) {
        case 0: return time = in.number(s.time) && isTrackTime(s.time);
        case 1: return depth = in.number(s.depth);
        case 2:
          transfer = true;
          // An empty list is valid JSON but not a valid transfer; the caller rejects it by count.
          return elements(in, [&] {
            double v = 0.0;
            if (!in.number(v) || !isTransfer(v)) return false;
            s.transfer.push_back(v);
            return true;
          }) && !s.transfer.empty();
        default: {
          std::array<double, 3> p{};
          std::size_t count = 0;
          const bool read =
              elements(in, [&] { return count < 3 && in.number(p[count]) && isTrackCoordinate(p[count++]); });
          if (!read || count != 3) return false;
          s.position = p;
          return true;
        }
      }
    });
    if (!ok || !time || !depth) return false;
    (transfer ? withTransfer_ : withoutTransfer_) = true;
    b.track.push_back(std::move(s));
    return true;
  }

  TransferValues rule_;
  bool withTransfer_ = false, withoutTransfer_ = false;
};

}  // namespace

std::optional<acoustics::BubbleTrackSet> parsePlainBubbleTracks(std::string_view text, TransferValues transfer) {
  BubbleTrackSet set;
  if (!PlainReader(transfer).document(text, set)) return std::nullopt;
  return set;
}

}  // namespace fluidsound::io
