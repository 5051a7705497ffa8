// io/spectrogram_image.cpp — the spectrogram PNG: the pooled STFT power of
// acoustics/analysis/spectrogram.h on the plot's pixel grid, coloured in dB relative to the peak
// and drawn with axes, ticks and a colour bar by cairo; written atomically. What the picture
// shows: docs/spectrogram.md.
#include "io/spectrogram_image.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "io/output_file.h"

namespace fluidsound::io {
namespace {

// Margins around the plot [px]: left = frequency tick labels and the rotated axis label; right =
// gap, colour bar, its tick labels and rotated label; top = title line; bottom = time ticks, label.
constexpr int marginLeftPx = 76;
constexpr int marginRightPx = 112;
constexpr int marginTopPx = 40;
constexpr int marginBottomPx = 50;
constexpr int minPlotSizePx = 64;
constexpr int maxImageSizePx = 16384;  // cairo's own limit is 32767; larger is surely a typo
constexpr int minWindowSamples = 16;
constexpr int maxWindowSamples = 1 << 20;
constexpr int tickLengthPx = 5;
constexpr int colourBarGapPx = 16;
constexpr int colourBarWidthPx = 16;
constexpr double tickFontPx = 12.0;
constexpr double labelFontPx = 13.0;
constexpr double titleFontPx = 15.0;
// Target tick spacing [px]: far enough apart that labels of ~5 characters never touch.
constexpr double timeTickSpacingPx = 90.0;
constexpr double frequencyTickSpacingPx = 50.0;
constexpr double colourBarTickSpacingPx = 45.0;
// A log axis labels 1-2-5 in each decade when a decade is at least this tall, else only 1s:
// 2 sits 0.30 decade above 1, so 50 px/decade keeps 12 px labels 15 px apart.
constexpr double minPxPerDecadeFor125 = 50.0;

struct CairoSurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct CairoDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, CairoSurfaceDeleter>;
using CairoPtr = std::unique_ptr<cairo_t, CairoDeleter>;

void validate(const AudioBuffer& audio, const SpectrogramSettings& s) {
  if (audio.channels.empty() || audio.frameCount() == 0)
    throw std::invalid_argument("spectrogram: the audio is empty (no channels or no samples)");
  for (const auto& c : audio.channels)
    if (c.size() != audio.frameCount())
      throw std::invalid_argument("spectrogram: the audio's channels differ in length");
  if (!std::isfinite(audio.sampleRate) || audio.sampleRate <= 0.0)
    throw std::invalid_argument("spectrogram: expected a sample rate > 0 Hz, found " +
                                std::to_string(audio.sampleRate));
  if (s.windowSamples < minWindowSamples || s.windowSamples > maxWindowSamples)
    throw std::invalid_argument("spectrogram: expected windowSamples in 16…1048576, found " +
                                std::to_string(s.windowSamples));
  if (s.hopSamples < 1)
    throw std::invalid_argument("spectrogram: expected hopSamples ≥ 1, found " +
                                std::to_string(s.hopSamples));
  if (!(s.dynamicRangeDb > 0.0) || !std::isfinite(s.dynamicRangeDb))
    throw std::invalid_argument("spectrogram: expected dynamicRangeDb > 0, found " +
                                std::to_string(s.dynamicRangeDb));
  const int channelCount = static_cast<int>(audio.channels.size());
  if (s.channel < -1 || s.channel >= channelCount)
    throw std::invalid_argument("spectrogram: expected channel −1 (mean) or 0…" +
                                std::to_string(channelCount - 1) + ", found " +
                                std::to_string(s.channel));
  const auto [minWidth, minHeight] = spectrogramMinimumSize();
  if (s.width < minWidth || s.height < minHeight || s.width > maxImageSizePx ||
      s.height > maxImageSizePx)
    throw std::invalid_argument("spectrogram: expected an image of " + std::to_string(minWidth) +
                                "…16384 × " + std::to_string(minHeight) + "…16384 px, found " +
                                std::to_string(s.width) + " × " + std::to_string(s.height));
  const double nyquist = audio.sampleRate / 2.0;
  if (s.logFrequency && !(s.minFrequency > 0.0 && s.minFrequency < nyquist))
    throw std::invalid_argument("spectrogram: a log axis needs 0 < minFrequency < " +
                                std::to_string(nyquist) + " Hz (Nyquist), found " +
                                std::to_string(s.minFrequency));
}

/// The signal to analyse: one channel, or the sample-wise mean of all of them.
std::vector<float> selectSignal(const AudioBuffer& audio, int channel) {
  std::vector<float> signal;
  if (channel >= 0) {
    signal = audio.channels[static_cast<std::size_t>(channel)];
  } else {
    signal.assign(audio.frameCount(), 0.0f);
    const float scale = 1.0f / static_cast<float>(audio.channels.size());
    for (const auto& c : audio.channels)
      for (std::size_t i = 0; i < c.size(); ++i) signal[i] += scale * c[i];
  }
  for (float x : signal)
    if (!std::isfinite(x))
      throw std::invalid_argument("spectrogram: the audio contains a non-finite sample");
  return signal;
}

/// The STFT and pooling grid of the picture: its plot area's pixels.
acoustics::SpectrogramLayout layoutOf(const SpectrogramSettings& s) {
  const SpectrogramPlotArea a = spectrogramPlotArea(s);
  acoustics::SpectrogramLayout layout;
  layout.windowSamples = s.windowSamples;
  layout.hopSamples = s.hopSamples;
  layout.logFrequency = s.logFrequency;
  layout.minFrequency = s.minFrequency;
  layout.columns = a.width;
  layout.rows = a.height;
  layout.left = a.left;
  layout.top = a.top;
  return layout;
}

/// A 1-2-5 step giving about `count` intervals over `span`.
double niceStep(double span, double count) {
  const double raw = span / std::max(count, 1.0);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double r = raw / magnitude;
  return (r < 1.5 ? 1.0 : r < 3.5 ? 2.0 : r < 7.5 ? 5.0 : 10.0) * magnitude;
}

/// Decimals needed to print multiples of `step` exactly (0.5 → 1, 0.05 → 2, 20 → 0).
int decimalsFor(double step) {
  return std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
}

std::string formatNumber(double value, int decimals) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, std::abs(value) < 1e-12 ? 0.0 : value);
  std::string text = buffer;
  if (text.front() == '-') text = "\u2212" + text.substr(1);  // typographic minus
  return text;
}

/// Where a text goes: its anchor at (x, y) [px]; ax, ay in [0, 1] pick the anchor inside the
/// text's ink box (0, 0 = top left; 0.5, 0.5 = centre). rotated: reads bottom to top.
struct TextPlacement {
  double x = 0.0, y = 0.0;
  double ax = 0.0, ay = 0.0;
  bool rotated = false;
};

void drawText(cairo_t* cr, const std::string& text, const TextPlacement& at) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_save(cr);
  cairo_translate(cr, at.x, at.y);
  if (at.rotated) cairo_rotate(cr, -std::numbers::pi / 2.0);
  cairo_move_to(cr, -e.x_bearing - at.ax * e.width, -e.y_bearing - at.ay * e.height);
  cairo_show_text(cr, text.c_str());
  cairo_restore(cr);
}

void drawTick(cairo_t* cr, double x0, double y0, double x1, double y1) {
  cairo_move_to(cr, x0, y0);
  cairo_line_to(cr, x1, y1);
  cairo_stroke(cr);
}

/// An RGB24 surface of `width` × `height` whose pixel (x, y) has colour level(x, y) ∈ [0, 1].
template <typename Level>
SurfacePtr colourSurface(int width, int height, Level level) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    throw std::invalid_argument("spectrogram: cannot allocate a " + std::to_string(width) + " × " +
                                std::to_string(height) + " px image");
  cairo_surface_flush(surface.get());
  unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  for (int y = 0; y < height; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < width; ++x) {
      const auto [r, g, b] = spectrogramColour(level(x, y));
      row[x] = 0xff000000u | (std::uint32_t{r} << 16) | (std::uint32_t{g} << 8) | b;
    }
  }
  cairo_surface_mark_dirty(surface.get());
  return surface;
}

void drawTimeAxis(cairo_t* cr, const SpectrogramPlotArea& a, double duration,
                  const SpectrogramSettings& s) {
  const double step = niceStep(duration, a.width / timeTickSpacingPx);
  const int decimals = decimalsFor(step);
  const double bottom = a.top + a.height;
  cairo_set_font_size(cr, tickFontPx);
  for (int k = 0; k * step <= duration * (1.0 + 1e-9); ++k) {
    const double x = std::round(timeToPixelColumn(k * step, duration, s)) + 0.5;
    drawTick(cr, x, bottom, x, bottom + tickLengthPx);
    drawText(cr, formatNumber(k * step, decimals), {x, bottom + tickLengthPx + 4, 0.5, 0.0});
  }
  cairo_set_font_size(cr, labelFontPx);
  drawText(cr, "time (s)", {a.left + a.width / 2.0, bottom + tickLengthPx + 22, 0.5, 0.0});
}

void drawFrequencyAxis(cairo_t* cr, const SpectrogramPlotArea& a, double sampleRate,
                       const SpectrogramSettings& s) {
  const double nyquist = sampleRate / 2.0;
  struct Tick {
    double frequency;
    std::string label;
  };
  std::vector<Tick> ticks;
  std::vector<double> minorTicks;
  std::string axisLabel = "frequency (Hz)";
  if (s.logFrequency) {
    const double pxPerDecade = a.height / std::log10(nyquist / s.minFrequency);
    const bool labels125 = pxPerDecade >= minPxPerDecadeFor125;
    for (int d = static_cast<int>(std::floor(std::log10(s.minFrequency))); d <= 5; ++d) {
      for (int m = 1; m <= 9; ++m) {
        const double f = m * std::pow(10.0, d);
        if (f < s.minFrequency * (1.0 - 1e-9) || f > nyquist * (1.0 + 1e-9)) continue;
        if (m == 1 || (labels125 && (m == 2 || m == 5))) {
          char buffer[32];
          if (f >= 1000.0)
            std::snprintf(buffer, sizeof buffer, "%gk", f / 1000.0);
          else
            std::snprintf(buffer, sizeof buffer, "%g", f);
          ticks.push_back({f, buffer});
        } else {
          minorTicks.push_back(f);
        }
      }
    }
  } else {
    const bool kilohertz = nyquist >= 2000.0;
    const double unit = kilohertz ? 1000.0 : 1.0;
    if (kilohertz) axisLabel = "frequency (kHz)";
    const double step = niceStep(nyquist / unit, a.height / frequencyTickSpacingPx);
    const int decimals = decimalsFor(step);
    for (int k = 0; k * step * unit <= nyquist * (1.0 + 1e-9); ++k)
      ticks.push_back({k * step * unit, formatNumber(k * step, decimals)});
  }
  cairo_set_font_size(cr, tickFontPx);
  for (const Tick& t : ticks) {
    const double y = std::round(frequencyToPixelRow(t.frequency, sampleRate, s)) + 0.5;
    drawTick(cr, a.left - tickLengthPx, y, a.left, y);
    drawText(cr, t.label, {a.left - tickLengthPx - 4.0, y, 1.0, 0.5});
  }
  for (double f : minorTicks) {
    const double y = std::round(frequencyToPixelRow(f, sampleRate, s)) + 0.5;
    drawTick(cr, a.left - tickLengthPx / 2.0, y, a.left, y);
  }
  cairo_set_font_size(cr, labelFontPx);
  drawText(cr, axisLabel, {18, a.top + a.height / 2.0, 0.5, 0.5, true});
}

void drawColourBar(cairo_t* cr, const SpectrogramPlotArea& a, const SpectrogramSettings& s) {
  const int left = a.left + a.width + colourBarGapPx;
  const SurfacePtr bar = colourSurface(
      colourBarWidthPx, a.height, [&](int, int y) { return (a.height - 1 - y + 0.5) / a.height; });
  cairo_set_source_surface(cr, bar.get(), left, a.top);
  cairo_rectangle(cr, left, a.top, colourBarWidthPx, a.height);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_rectangle(cr, left - 0.5, a.top - 0.5, colourBarWidthPx + 1, a.height + 1);
  cairo_stroke(cr);

  const double range = s.dynamicRangeDb;
  const double step = niceStep(range, a.height / colourBarTickSpacingPx);
  const int decimals = decimalsFor(step);
  const double right = left + colourBarWidthPx;
  double labelWidth = 0.0;
  cairo_set_font_size(cr, tickFontPx);
  for (int k = 0; k * step <= range * (1.0 + 1e-9); ++k) {
    const double y = std::round(a.top + a.height * (k * step / range)) + 0.5;
    drawTick(cr, right, y, right + tickLengthPx, y);
    const std::string label = formatNumber(-k * step, decimals);
    cairo_text_extents_t e;
    cairo_text_extents(cr, label.c_str(), &e);
    labelWidth = std::max(labelWidth, e.width);
    drawText(cr, label, {right + tickLengthPx + 3, y, 0.0, 0.5});
  }
  cairo_set_font_size(cr, labelFontPx);
  drawText(cr, "level (dB re peak)",
           {right + tickLengthPx + 3 + labelWidth + 10, a.top + a.height / 2.0, 0.5, 0.5, true});
}

void drawTitle(cairo_t* cr, const SpectrogramPlotArea& a, const std::string& title,
               const std::string& details, int imageWidth) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, titleFontPx);
  cairo_text_extents_t titleExtents;
  cairo_text_extents(cr, title.c_str(), &titleExtents);
  drawText(cr, title, {static_cast<double>(a.left), 14, 0.0, 0.0});
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, tickFontPx);
  cairo_text_extents_t e;
  cairo_text_extents(cr, details.c_str(), &e);
  const double right = imageWidth - 10.0;
  if (right - e.width > a.left + titleExtents.width + 20.0) {  // only when it fits beside the title
    cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
    drawText(cr, details, {right, 16, 1.0, 0.0});
    cairo_set_source_rgb(cr, 0, 0, 0);
  }
}

}  // namespace

std::array<int, 2> spectrogramMinimumSize() {
  return {marginLeftPx + minPlotSizePx + marginRightPx,
          marginTopPx + minPlotSizePx + marginBottomPx};
}

SpectrogramPlotArea spectrogramPlotArea(const SpectrogramSettings& settings) {
  return {marginLeftPx, marginTopPx, settings.width - marginLeftPx - marginRightPx,
          settings.height - marginTopPx - marginBottomPx};
}

double frequencyToPixelRow(double frequency, double sampleRate,
                           const SpectrogramSettings& settings) {
  const SpectrogramPlotArea a = spectrogramPlotArea(settings);
  return a.top + a.height * (1.0 - acoustics::spectrogramAxisFraction(frequency, sampleRate / 2.0,
                                                                      layoutOf(settings)));
}

double timeToPixelColumn(double time, double duration, const SpectrogramSettings& settings) {
  const SpectrogramPlotArea a = spectrogramPlotArea(settings);
  return a.left + a.width * (time / duration);
}

std::array<std::uint8_t, 3> spectrogramColour(double level) {
  // Anchors on an inferno-like hue path (black → violet → magenta → red → orange → yellow → pale
  // yellow), each scaled in linear light so that CIE L* rises in equal steps of 12.25 from 0 to 98:
  // L* = 0.1, 12.2, 24.6, 36.8, 49.0, 61.3, 73.4, 85.8, 98.0. Linear sRGB interpolation between
  // anchors keeps L* monotonic (checked in tests/io/spectrogram_image_test.cpp).
  // clang-format off
  static constexpr std::array<std::array<std::uint8_t, 3>, 9> anchors{{
      {0, 0, 4}, {38, 16, 85}, {95, 19, 121}, {152, 39, 118}, {208, 61, 96},
      {250, 99, 59}, {255, 158, 27}, {255, 210, 56}, {252, 255, 164}}};
  // clang-format on
  const double v = std::isfinite(level) ? std::clamp(level, 0.0, 1.0) : 0.0;
  const double position = v * (anchors.size() - 1);
  const std::size_t k = std::min(static_cast<std::size_t>(position), anchors.size() - 2);
  const double f = position - static_cast<double>(k);
  std::array<std::uint8_t, 3> rgb{};
  for (int i = 0; i < 3; ++i)
    rgb[i] = static_cast<std::uint8_t>(
        std::lround(anchors[k][i] + f * (anchors[k + 1][i] - anchors[k][i])));
  return rgb;
}

std::vector<float> spectrogramSignal(const AudioBuffer& audio, const SpectrogramSettings& settings) {
  validate(audio, settings);
  return selectSignal(audio, settings.channel);
}

acoustics::SpectrogramLayout spectrogramLayout(const SpectrogramSettings& settings) {
  return layoutOf(settings);
}

void writeSpectrogramPng(const std::filesystem::path& path, const AudioBuffer& audio,
                         const SpectrogramSettings& settings, const std::string& title,
                         const acoustics::SpectrogramPower& power) {
  // Encoded in memory, then written by the output rule (output_file.h).
  writeOutputFile(path, encodeSpectrogramPng(audio, settings,
                                             title.empty() ? path.filename().string() : title, power));
}

std::string encodeSpectrogramPng(const AudioBuffer& audio, const SpectrogramSettings& settings,
                                 const std::string& title, const acoustics::SpectrogramPower& pooled) {
  validate(audio, settings);
  const SpectrogramPlotArea area = spectrogramPlotArea(settings);
  const double duration = static_cast<double>(audio.frameCount()) / audio.sampleRate;
  if (pooled.columns != area.width || pooled.rows != area.height ||
      pooled.power.size() != static_cast<std::size_t>(area.width) * area.height)
    throw std::invalid_argument("spectrogram: the power's grid (" + std::to_string(pooled.columns) +
                                " x " + std::to_string(pooled.rows) + ") is not the plot area's (" +
                                std::to_string(area.width) + " x " + std::to_string(area.height) + ")");

  // Colour level of each plot pixel: 0 dB = the largest value in the picture.
  const std::vector<float>& power = pooled.power;
  const float peak = *std::max_element(power.begin(), power.end());
  const auto level = [&](int x, int y) {
    const float p = power[static_cast<std::size_t>(y) * area.width + x];
    if (peak <= 0.0f || p <= 0.0f) return 0.0;
    const double db = 10.0 * std::log10(static_cast<double>(p) / peak);
    return (db + settings.dynamicRangeDb) / settings.dynamicRangeDb;
  };

  SurfacePtr image(cairo_image_surface_create(CAIRO_FORMAT_RGB24, settings.width, settings.height));
  if (cairo_surface_status(image.get()) != CAIRO_STATUS_SUCCESS)
    throw std::invalid_argument("spectrogram: cannot allocate the image");
  const CairoPtr cr(cairo_create(image.get()));
  cairo_set_source_rgb(cr.get(), 1, 1, 1);
  cairo_paint(cr.get());

  const SurfacePtr plot = colourSurface(area.width, area.height, level);
  cairo_set_source_surface(cr.get(), plot.get(), area.left, area.top);
  cairo_rectangle(cr.get(), area.left, area.top, area.width, area.height);
  cairo_fill(cr.get());

  cairo_set_source_rgb(cr.get(), 0, 0, 0);
  cairo_set_line_width(cr.get(), 1.0);
  cairo_rectangle(cr.get(), area.left - 0.5, area.top - 0.5, area.width + 1, area.height + 1);
  cairo_stroke(cr.get());

  const std::string channelText =
      settings.channel >= 0 ? "channel " + std::to_string(settings.channel)
      : audio.channels.size() == 1
          ? "mono"
          : "mean of " + std::to_string(audio.channels.size()) + " channels";
  const std::string details = formatNumber(audio.sampleRate, 0) + " Hz, " + channelText +
                              ", Hann " + std::to_string(settings.windowSamples) + ", hop " +
                              std::to_string(settings.hopSamples);
  drawTitle(cr.get(), area, title, details, settings.width);
  cairo_select_font_face(cr.get(), "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  drawTimeAxis(cr.get(), area, duration, settings);
  drawFrequencyAxis(cr.get(), area, audio.sampleRate, settings);
  drawColourBar(cr.get(), area, settings);
  cairo_surface_flush(image.get());

  std::string png;
  const auto append = [](void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
  };
  const cairo_status_t status = cairo_surface_write_to_png_stream(image.get(), append, &png);
  if (status != CAIRO_STATUS_SUCCESS)
    throw OutputError(std::string("spectrogram: cannot encode the PNG (") +
                      cairo_status_to_string(status) + ")");
  return png;
}

}  // namespace fluidsound::io
