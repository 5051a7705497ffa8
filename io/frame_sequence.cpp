// io/frame_sequence.cpp — see frame_sequence.h.
#include "io/frame_sequence.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <system_error>

#include "io/input_error.h"

namespace fluidsound::io {
namespace fs = std::filesystem;

namespace {

/// A file name split at its frame token: prefix, the token's zero padding (0: none), suffix.
struct NamePattern {
  std::string prefix, suffix;
  int padding = 0;

  std::string name(int frame) const {
    std::string digits = std::to_string(frame);
    if (static_cast<int>(digits.size()) < padding) digits.insert(0, padding - digits.size(), '0');
    return prefix + digits + suffix;
  }
  /// The frame number a file name holds, if it is this pattern's name for it.
  std::optional<int> frameOf(const std::string& file) const {
    if (file.size() <= prefix.size() + suffix.size() || !file.starts_with(prefix) || !file.ends_with(suffix))
      return std::nullopt;
    const std::string digits = file.substr(prefix.size(), file.size() - prefix.size() - suffix.size());
    if (digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      return std::nullopt;
    const int frame = std::stoi(digits);
    if (name(frame) != file) return std::nullopt;  // 07.vdb is not frame 7 of %04d
    return frame;
  }
};

/// The frame tokens in `text`: each as (position, length, padding).
struct Token {
  std::size_t at, length;
  int padding;
};
std::vector<Token> frameTokens(const std::string& text) {
  std::vector<Token> tokens;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%') {  // %d or %0Nd / %Nd
      std::size_t j = i + 1;
      while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) ++j;
      if (j < text.size() && text[j] == 'd') {
        const int width = j > i + 1 ? std::stoi(text.substr(i + 1, j - i - 1)) : 0;
        tokens.push_back({i, j + 1 - i, width});
        i = j;
      }
    } else if (text[i] == '$' && i + 1 < text.size() && text[i + 1] == 'F') {  // $F or $FN
      std::size_t j = i + 2;
      while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) ++j;
      tokens.push_back({i, j - i, j > i + 2 ? std::stoi(text.substr(i + 2, j - i - 2)) : 0});
      i = j - 1;
    } else if (text[i] == '#') {  // a run of #: that many digits
      std::size_t j = i;
      while (j < text.size() && text[j] == '#') ++j;
      tokens.push_back({i, j - i, static_cast<int>(j - i)});
      i = j - 1;
    }
  }
  return tokens;
}

}  // namespace

std::vector<SequenceFrame> frameSequence(const std::string& pattern, const fs::path& folder,
                                         const std::string& sourceFile, const std::string& field) {
  const std::string expected =
      "a file pattern with one frame number (%04d, $F4 or ####, as in frames/%04d.vdb) or a folder of "
      "NNNN.vdb files";
  fs::path full = fs::path(pattern).is_absolute() ? fs::path(pattern) : folder / pattern;
  std::error_code ec;
  if (frameTokens(pattern).empty() && fs::is_directory(full, ec)) full /= "%04d.vdb";  // simulate's frames
  const std::string name = full.filename().string();
  const std::vector<Token> tokens = frameTokens(name);
  if (tokens.size() != 1 || frameTokens(full.parent_path().string()).size() != 0)
    throw InputError(sourceFile, field, expected,
                     "\"" + pattern + "\" (" + std::to_string(frameTokens(full.string()).size()) + " frame tokens" +
                         (tokens.size() == 1 ? ", one in a folder name)" : ")"));
  const Token& t = tokens.front();
  const NamePattern names{name.substr(0, t.at), name.substr(t.at + t.length), t.padding};
  const fs::path dir = full.parent_path().empty() ? fs::path(".") : full.parent_path();
  if (!fs::is_directory(dir, ec))
    throw InputError(sourceFile, field, expected + " in an existing folder", dir.string() + ": no such folder");
  std::vector<SequenceFrame> frames;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    if (!entry.is_regular_file(ec)) continue;
    if (const auto frame = names.frameOf(entry.path().filename().string())) frames.push_back({*frame, entry.path()});
  }
  if (frames.empty())
    throw InputError(sourceFile, field, "at least one frame file", "none matching " + (dir / names.name(0)).string() +
                                                                      " (\"" + pattern + "\")");
  std::sort(frames.begin(), frames.end(), [](const SequenceFrame& a, const SequenceFrame& b) { return a.frame < b.frame; });
  for (std::size_t i = 1; i < frames.size(); ++i)
    if (frames[i].frame != frames[i - 1].frame + 1)
      throw InputError(sourceFile, field,
                       "every frame from " + std::to_string(frames.front().frame) + " to " +
                           std::to_string(frames.back().frame),
                       "no " + (dir / names.name(frames[i - 1].frame + 1)).string());
  return frames;
}

}  // namespace fluidsound::io
