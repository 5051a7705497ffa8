// Tests of tools/progress_display.h on an injected stream: on a terminal, log lines and the
// redrawn progress line never share a line of the screen; in a log, every line is plain.
#include "tools/progress_display.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace fluidsound::tools {
namespace {

/// Everything written to a temporary stream, read back.
std::string contents(std::FILE* stream) {
  std::fflush(stream);
  std::rewind(stream);
  std::string text;
  char buffer[512];
  std::size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof buffer, stream)) > 0) text.append(buffer, count);
  return text;
}

/// The lines a terminal shows after printing `text`: '\r' returns to column 0 (later characters
/// overwrite), "ESC [ K" erases to the end of the line, '\n' starts the next line (ECMA-48).
std::vector<std::string> screenLines(const std::string& text) {
  std::vector<std::string> lines(1);
  std::size_t column = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    std::string& line = lines.back();
    if (text[i] == '\r') {
      column = 0;
    } else if (text[i] == '\n') {
      lines.emplace_back();
      column = 0;
    } else if (text.compare(i, 3, "\x1b[K") == 0) {
      line.resize(std::min(line.size(), column));
      i += 2;
    } else {
      if (column < line.size())
        line[column] = text[i];
      else
        line.push_back(text[i]);
      ++column;
    }
  }
  if (lines.back().empty()) lines.pop_back();
  return lines;
}

// Claim: on a terminal, a log line printed while the progress line is up appears on a line of its
// own, whole, and the progress line is drawn again below it (progress_display.h). Reference: the
// screen a terminal shows (screenLines), which would read "simulate  50.0% … frame 1 …" on one
// line if the log line were printed straight after the progress line's text, as before.
TEST(ProgressDisplay, LogLinesNeverRunIntoTheProgressLineOnATerminal) {
  std::FILE* stream = std::tmpfile();
  ASSERT_NE(stream, nullptr);
  {
    ProgressDisplay progress("simulate", 4, "frames", false, {stream, true, 0.0});
    progress.update(0.25);
    progress.log("frame    1/3  t 0.033 s");
    progress.update(0.5);
    progress.log("frame    2/3  t 0.067 s");
    progress.update(0.75);
  }  // the destructor ends the progress line
  const std::vector<std::string> lines = screenLines(contents(stream));
  std::fclose(stream);
  ASSERT_EQ(lines.size(), 3u) << ::testing::PrintToString(lines);
  EXPECT_EQ(lines[0], "frame    1/3  t 0.033 s");
  EXPECT_EQ(lines[1], "frame    2/3  t 0.067 s");
  EXPECT_EQ(lines[2].rfind("simulate  75.0%", 0), 0u) << lines[2];
}

// Claim: in a log (not a terminal) nothing is redrawn: no carriage returns or escape sequences,
// one plain line per log line. Quiet shows nothing at all.
TEST(ProgressDisplay, WritesPlainLinesToALogAndNothingWhenQuiet) {
  std::FILE* stream = std::tmpfile();
  ASSERT_NE(stream, nullptr);
  {
    ProgressDisplay progress("transfer", 2, "frames", false, {stream, false, 0.0});
    progress.update(0.5);  // within the log interval after the start: not printed
    progress.log("a log line");
    progress.update(1.0);  // the last one always is
  }
  const std::string text = contents(stream);
  std::fclose(stream);
  EXPECT_EQ(text.find('\r'), std::string::npos) << text;
  EXPECT_EQ(text.find('\x1b'), std::string::npos) << text;
  EXPECT_EQ(text.rfind("a log line\ntransfer 100.0%", 0), 0u) << text;

  std::FILE* quietStream = std::tmpfile();
  ASSERT_NE(quietStream, nullptr);
  {
    ProgressDisplay quiet("transfer", 2, "frames", true, {quietStream, true, 0.0});
    quiet.update(0.5);
    quiet.log("a log line");
  }
  EXPECT_EQ(contents(quietStream), "");
  std::fclose(quietStream);
}

}  // namespace
}  // namespace fluidsound::tools
