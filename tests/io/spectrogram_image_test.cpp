// tests/io/spectrogram_image_test.cpp — the spectrogram PNG puts a tone where the axes say it is,
// at the requested size, with an ordered colour map; failures leave no file behind; power of
// another grid than the picture's is refused.
#include "io/spectrogram_image.h"

#include <cairo.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "acoustics/analysis/spectrogram.h"
#include "io/input_error.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

constexpr double sampleRate = 48000.0;  // Hz

/// The spectrogram PNG of `audio` at `path`, as the CLI makes it (tools/spectrogram_picture.h):
/// the picture's signal and grid from io, the pooled power from acoustics, drawn and written by io.
void writePicture(const fs::path& path, const AudioBuffer& audio, const SpectrogramSettings& settings) {
  const std::vector<float> signal = spectrogramSignal(audio, settings);
  writeSpectrogramPng(path, audio, settings, {},
                      acoustics::pooledSpectrogramPower(signal, audio.sampleRate, spectrogramLayout(settings)));
}

/// CIE L* (0 black … 100 white) of an sRGB colour.
double lightness(double r8, double g8, double b8) {
  const auto linear = [](double c8) {
    const double c = c8 / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const double y = 0.2126 * linear(r8) + 0.7152 * linear(g8) + 0.0722 * linear(b8);
  return y > 216.0 / 24389.0 ? 116.0 * std::cbrt(y) - 16.0 : y * 24389.0 / 27.0;
}

double lightness(const std::array<std::uint8_t, 3>& rgb) {
  return lightness(rgb[0], rgb[1], rgb[2]);
}

/// A PNG read back with cairo: size and the L* of every pixel.
struct Picture {
  int width = 0, height = 0;
  std::vector<double> lightness;  // row-major
  double at(int x, int y) const { return lightness[static_cast<std::size_t>(y) * width + x]; }
};

Picture readPicture(const fs::path& path) {
  const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create_from_png(path.c_str()), &cairo_surface_destroy);
  Picture picture;
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) return picture;
  picture.width = cairo_image_surface_get_width(surface.get());
  picture.height = cairo_image_surface_get_height(surface.get());
  const unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  for (int y = 0; y < picture.height; ++y) {
    const auto* row =
        reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < picture.width; ++x)
      picture.lightness.push_back(
          lightness((row[x] >> 16) & 0xff, (row[x] >> 8) & 0xff, row[x] & 0xff));
  }
  return picture;
}

/// Mono audio: a sine of `frequency` [Hz] and amplitude 0.5, on during [on, off) seconds.
AudioBuffer toneBurst(double frequency, double duration, double on, double off) {
  AudioBuffer audio;
  audio.sampleRate = sampleRate;
  audio.channels.emplace_back(static_cast<std::size_t>(std::llround(duration * sampleRate)), 0.0f);
  for (std::size_t i = 0; i < audio.channels[0].size(); ++i) {
    const double t = static_cast<double>(i) / sampleRate;
    if (t >= on && t < off)
      audio.channels[0][i] =
          static_cast<float>(0.5 * std::sin(2.0 * std::numbers::pi * frequency * t));
  }
  return audio;
}

/// Row (image y) of the plot area whose mean lightness over the plot's columns is largest.
int brightestRow(const Picture& picture, const SpectrogramPlotArea& area) {
  int best = -1;
  double bestMean = -1.0;
  for (int y = area.top; y < area.top + area.height; ++y) {
    double sum = 0.0;
    for (int x = area.left; x < area.left + area.width; ++x) sum += picture.at(x, y);
    if (sum / area.width > bestMean) {
      bestMean = sum / area.width;
      best = y;
    }
  }
  return best;
}

std::vector<fs::path> filesIn(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) files.push_back(entry.path().filename());
  return files;
}

/// A fresh folder per test, removed afterwards.
class SpectrogramImage : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::temp_directory_path() / ("fluidsound-spectrogram-" + std::string(info->name()) +
                                           "-" + std::to_string(::getpid()));
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::permissions(folder_, fs::perms::owner_all, fs::perm_options::add, ignored);
    fs::remove_all(folder_, ignored);
  }
  fs::path folder_;
};

TEST(SpectrogramColour, LightnessRisesMonotonically) {
  // Claim: the colour map is perceptually ordered — CIE L* never falls from level 0 to level 1,
  // and rises by a visible amount over every 1/32 of the range. Reference: its anchors were chosen
  // at L* = 0, 12.25, …, 98. Tolerance: neighbours 1/1024 apart differ by < 1 unit per channel,
  // and rounding each channel to 8 bits separately can lower L* by up to ~0.1 (half a step in
  // green is ≤ 0.2 L*); 0.25 allows that and is a quarter of the ~1 L* just-noticeable
  // difference. Over 1/32 of the range L* should rise by ≈ 3, so > 1 separates "ordered" from
  // "flat".
  double previous = lightness(spectrogramColour(0.0));
  EXPECT_LT(previous, 1.0);
  for (int i = 1; i <= 1024; ++i) {
    const double current = lightness(spectrogramColour(i / 1024.0));
    EXPECT_GE(current, previous - 0.25) << "level " << i / 1024.0;
    previous = current;
  }
  EXPECT_GT(previous, 95.0);
  for (int i = 1; i <= 32; ++i)
    EXPECT_GT(lightness(spectrogramColour(i / 32.0)) - lightness(spectrogramColour((i - 1) / 32.0)),
              1.0)
        << "level " << i / 32.0;
}

TEST(SpectrogramAxes, MapFrequencyAndTimeOntoThePlotEdges) {
  // Claim: the axes span the plot area exactly — 0 Hz (linear) or minFrequency (log) on its bottom
  // edge, Nyquist on its top edge, 3 kHz at the closed-form fraction of the height between; 0 s on
  // its left edge, the duration on its right. Reference: u = f/f_N (linear), u = ln(f/f_min) /
  // ln(f_N/f_min) (log), y = top + height·(1 − u). Tolerance 1e-9 px: the same arithmetic in
  // double precision, so only rounding (~1e-13 px) separates them. This pins the mapping that the
  // tone tests below take as their reference.
  SpectrogramSettings settings;
  const SpectrogramPlotArea a = spectrogramPlotArea(settings);
  ASSERT_GT(a.width, 0);
  ASSERT_GT(a.height, 0);
  const double bottom = a.top + a.height, nyquist = sampleRate / 2.0;
  EXPECT_NEAR(frequencyToPixelRow(0.0, sampleRate, settings), bottom, 1e-9);
  EXPECT_NEAR(frequencyToPixelRow(nyquist, sampleRate, settings), a.top, 1e-9);
  EXPECT_NEAR(frequencyToPixelRow(3000.0, sampleRate, settings),
              a.top + a.height * (1.0 - 3000.0 / nyquist), 1e-9);
  settings.logFrequency = true;
  EXPECT_NEAR(frequencyToPixelRow(settings.minFrequency, sampleRate, settings), bottom, 1e-9);
  EXPECT_NEAR(frequencyToPixelRow(nyquist, sampleRate, settings), a.top, 1e-9);
  EXPECT_NEAR(frequencyToPixelRow(3000.0, sampleRate, settings),
              a.top + a.height * (1.0 - std::log(3000.0 / 20.0) / std::log(nyquist / 20.0)), 1e-9);
  EXPECT_NEAR(timeToPixelColumn(0.0, 3.0, settings), a.left, 1e-9);
  EXPECT_NEAR(timeToPixelColumn(3.0, 3.0, settings), a.left + a.width, 1e-9);
  // The plot leaves room for labels on every side.
  EXPECT_GE(a.left, 40);
  EXPECT_GE(a.top, 20);
  EXPECT_GE(settings.width - a.left - a.width, 80);
  EXPECT_GE(settings.height - a.top - a.height, 30);
}

/// Renders tones and checks, for each, that the brightest plot row is where the axis puts it.
void expectTonesOnAxis(const fs::path& folder, bool logFrequency) {
  SpectrogramSettings settings;
  settings.width = 800;
  settings.height = 500;
  settings.logFrequency = logFrequency;
  const SpectrogramPlotArea area = spectrogramPlotArea(settings);
  // 3 kHz is the claim of the brief; 375 Hz and 12 kHz pin the axis scale at two more points
  // (a wrong log base or a linear/log mix-up moves them by tens of pixels). All three are exact
  // FFT bins (16, 128, 512 × 48000/2048 Hz), so no scalloping shifts the peak.
  for (double frequency : {375.0, 3000.0, 12000.0}) {
    const fs::path png = folder / ("tone-" + std::to_string(static_cast<int>(frequency)) + ".png");
    writePicture(png, toneBurst(frequency, 1.0, 0.0, 1.0), settings);
    const Picture picture = readPicture(png);
    ASSERT_EQ(picture.width, settings.width) << png;
    ASSERT_EQ(picture.height, settings.height) << png;

    // Claim: the brightest row of the plot is the row that frequencyToPixelRow assigns to the
    // tone's frequency. Reference: that same mapping, floor(y). Tolerance 2 px: a row is
    // 48 Hz (linear) or 1.4 % of f (log) tall while the Hann main lobe is ±47 Hz wide, so the
    // ±1-bin neighbours (−6 dB) can share or adjoin the peak row; 2 px allows that and a
    // pixel-centre convention off by one, while a mis-scaled axis misses by far more.
    const int expected =
        static_cast<int>(std::floor(frequencyToPixelRow(frequency, sampleRate, settings)));
    EXPECT_NEAR(brightestRow(picture, area), expected, 2.0)
        << frequency << " Hz, " << (logFrequency ? "log" : "linear") << " axis";
  }
  EXPECT_EQ(filesIn(folder).size(), 3u) << "a temporary file was left behind";
}

TEST_F(SpectrogramImage, PureToneBrightestRowMatchesLinearAxis) {
  expectTonesOnAxis(folder_, false);
}

TEST_F(SpectrogramImage, PureToneBrightestRowMatchesLogAxis) { expectTonesOnAxis(folder_, true); }

TEST_F(SpectrogramImage, ToneBurstStartsAndEndsAtItsTimesOnAxis) {
  SpectrogramSettings settings;
  settings.width = 1000;
  settings.height = 400;
  const SpectrogramPlotArea area = spectrogramPlotArea(settings);
  const double duration = 3.0, on = 1.0, off = 2.0;  // s
  const fs::path png = folder_ / "burst.png";
  writePicture(png, toneBurst(3000.0, duration, on, off), settings);
  const Picture picture = readPicture(png);
  ASSERT_EQ(picture.width, settings.width);

  // First and last plot columns in the tone's row brighter than the middle of the colour map.
  const int row = static_cast<int>(std::floor(frequencyToPixelRow(3000.0, sampleRate, settings)));
  const double threshold = lightness(spectrogramColour(0.5));
  int first = -1, last = -1;
  for (int x = area.left; x < area.left + area.width; ++x) {
    if (picture.at(x, row) <= threshold) continue;
    if (first < 0) first = x;
    last = x;
  }
  // Claim: the burst is drawn from the column of `on` to the column of `off`. Reference:
  // timeToPixelColumn. Tolerance: a frame centred up to half a window (1024 samples = 21.3 ms,
  // 7.1 px at 333 px/s) outside the burst still overlaps it, and max-pooling shows that frame;
  // plus 1 px for the pixel convention.
  const double halfWindowPx = settings.windowSamples / 2.0 / sampleRate * area.width / duration;
  EXPECT_NEAR(first, std::floor(timeToPixelColumn(on, duration, settings)), halfWindowPx + 1.0);
  EXPECT_NEAR(last, std::floor(timeToPixelColumn(off, duration, settings)), halfWindowPx + 1.0);
}

TEST_F(SpectrogramImage, MissingFolderThrowsOutputError) {
  const fs::path png = folder_ / "no-such-folder" / "out.png";
  EXPECT_THROW(writePicture(png, toneBurst(3000.0, 0.2, 0.0, 0.2), {}), OutputError);
  EXPECT_FALSE(fs::exists(png.parent_path()));
}

TEST_F(SpectrogramImage, ReadOnlyFolderThrowsOutputErrorAndLeavesNoFile) {
  fs::permissions(folder_, fs::perms::owner_read | fs::perms::owner_exec);
  if (::access(folder_.c_str(), W_OK) == 0)
    GTEST_SKIP() << "running with rights that ignore permissions (root)";
  EXPECT_THROW(writePicture(folder_ / "out.png", toneBurst(3000.0, 0.2, 0.0, 0.2), {}),
               OutputError);
  EXPECT_TRUE(filesIn(folder_).empty());
}

/// Death-test body: with a 1 KiB limit on file size, writing must throw OutputError and leave the
/// folder empty. Exits 0 if so, 1 otherwise.
[[noreturn]] void writeWithFileSizeLimit(const fs::path& folder) {
  std::signal(SIGXFSZ, SIG_IGN);  // get EFBIG from write() instead of being killed
  rlimit limit{};
  limit.rlim_cur = limit.rlim_max = 1024;  // bytes
  ::setrlimit(RLIMIT_FSIZE, &limit);
  bool threw = false;
  try {
    writePicture(folder / "out.png", toneBurst(3000.0, 0.5, 0.0, 0.5), {});
  } catch (const OutputError&) {
    threw = true;
  }
  std::exit(threw && filesIn(folder).empty() ? 0 : 1);
}

TEST_F(SpectrogramImage, FullDiskThrowsOutputErrorAndLeavesNoFile) {
  // A full disk, simulated in a child process (a death test) by a limit on file size: the
  // temporary file is created, then writing the PNG into it fails. Works as root too.
  // "threadsafe": the child re-executes the test binary instead of forking a process that may
  // hold other tests' worker threads (TBB), which can deadlock a forked child.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(writeWithFileSizeLimit(folder_), ::testing::ExitedWithCode(0), "");
}

TEST_F(SpectrogramImage, EmptyAudioThrowsInvalidArgument) {
  const fs::path png = folder_ / "out.png";
  AudioBuffer noChannels;
  EXPECT_THROW(writePicture(png, noChannels, {}), std::invalid_argument);
  AudioBuffer noSamples;
  noSamples.channels.assign(2, {});
  EXPECT_THROW(writePicture(png, noSamples, {}), std::invalid_argument);
  EXPECT_TRUE(filesIn(folder_).empty());
}

// Claim: the picture draws power pooled on its own plot area only; power of another grid (here
// one column short) is refused before anything is written.
TEST_F(SpectrogramImage, PowerOfAnotherGridIsRefused) {
  const AudioBuffer audio = toneBurst(3000.0, 0.2, 0.0, 0.2);
  const SpectrogramSettings settings;
  acoustics::SpectrogramLayout layout = spectrogramLayout(settings);
  const acoustics::SpectrogramPower right =
      acoustics::pooledSpectrogramPower(spectrogramSignal(audio, settings), audio.sampleRate, layout);
  EXPECT_FALSE(encodeSpectrogramPng(audio, settings, "t", right).empty());
  layout.columns -= 1;
  const acoustics::SpectrogramPower narrow =
      acoustics::pooledSpectrogramPower(spectrogramSignal(audio, settings), audio.sampleRate, layout);
  EXPECT_THROW(writeSpectrogramPng(folder_ / "out.png", audio, settings, {}, narrow), std::invalid_argument);
  EXPECT_TRUE(filesIn(folder_).empty());
}

TEST_F(SpectrogramImage, BadSettingsThrowInvalidArgument) {
  const fs::path png = folder_ / "out.png";
  const AudioBuffer audio = toneBurst(3000.0, 0.2, 0.0, 0.2);
  const auto expectRejected = [&](auto change, const char* what) {
    SpectrogramSettings settings;
    change(settings);
    EXPECT_THROW(writePicture(png, audio, settings), std::invalid_argument) << what;
  };
  expectRejected([](SpectrogramSettings& s) { s.hopSamples = 0; }, "hop 0");
  expectRejected([](SpectrogramSettings& s) { s.windowSamples = 8; }, "window 8");
  expectRejected([](SpectrogramSettings& s) { s.dynamicRangeDb = 0.0; }, "range 0 dB");
  expectRejected([](SpectrogramSettings& s) { s.channel = 1; }, "channel 1 of 1");
  expectRejected([](SpectrogramSettings& s) { s.width = 100; }, "width 100 px");
  expectRejected([](SpectrogramSettings& s) { s.height = 100000; }, "height 100000 px");
  expectRejected(
      [](SpectrogramSettings& s) {
        s.logFrequency = true;
        s.minFrequency = 24000.0;
      },
      "log axis from Nyquist");
  expectRejected(
      [](SpectrogramSettings& s) {
        s.logFrequency = true;
        s.minFrequency = 0.0;
      },
      "log axis from 0 Hz");
  EXPECT_TRUE(filesIn(folder_).empty());
}

}  // namespace
}  // namespace fluidsound::io
