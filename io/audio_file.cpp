// io/audio_file.cpp — WAV/FLAC through libsndfile (docs/audio.md): float or TPDF-dithered PCM,
// optional peak or loudness normalisation, clipping counted, loudness of what was written,
// channels named and unpositioned, encoded in memory and written by the output rule
// (output_file.h); reading back as floats.
#include "io/audio_file.h"

#include <sndfile.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "io/loudness.h"
#include "io/channel_layout.h"
#include "io/input_error.h"
#include "io/json_validation.h"
#include "io/output_file.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

/// Frames converted and handed to libsndfile per call: bounds the interleaved scratch buffer.
constexpr std::size_t kBlockFrames = 8192;

[[noreturn]] void badSettings(const fs::path& path, const std::string& reason) {
  throw std::invalid_argument(path.string() + ": cannot write audio: " + reason);
}

/// The sample layout actually written: FLAC has no float samples, so 32 bits become 24.
struct SampleLayout {
  int format = 0;  ///< libsndfile SF_FORMAT_* major | subtype
  int bits = 32;   ///< 32 = float; 24 or 16 = PCM
};

SampleLayout sampleLayout(const fs::path& path, const AudioWriteSettings& settings,
                          std::size_t channels) {
  if (settings.bitsPerSample != 16 && settings.bitsPerSample != 24 &&
      settings.bitsPerSample != 32) {
    badSettings(
        path, "bitsPerSample must be 16, 24 or 32, not " + std::to_string(settings.bitsPerSample));
  }
  SampleLayout layout;
  if (settings.format == AudioFormat::Flac) {
    layout.bits = settings.bitsPerSample == 16 ? 16 : 24;
    layout.format = SF_FORMAT_FLAC | (layout.bits == 16 ? SF_FORMAT_PCM_16 : SF_FORMAT_PCM_24);
  } else {
    layout.bits = settings.bitsPerSample;
    // WAVE_FORMAT_EXTENSIBLE can say "no speaker positions" (channel_layout.h); plain WAVE
    // cannot, and players guess a surround layout from the channel count.
    const int container =
        channels >= kFirstUnpositionedChannelCount ? SF_FORMAT_WAVEX : SF_FORMAT_WAV;
    layout.format = container | (layout.bits == 32   ? SF_FORMAT_FLOAT
                                 : layout.bits == 24 ? SF_FORMAT_PCM_24
                                                     : SF_FORMAT_PCM_16);
  }
  return layout;
}

/// Largest |sample|; also checks that every sample is finite and the channels agree in length.
double checkedPeak(const fs::path& path, const AudioBuffer& audio) {
  if (audio.channels.empty()) badSettings(path, "no channels");
  const std::size_t frames = audio.frameCount();
  double peak = 0.0;
  for (std::size_t c = 0; c < audio.channels.size(); ++c) {
    const std::vector<float>& channel = audio.channels[c];
    if (channel.size() != frames) {
      badSettings(path, "channel " + std::to_string(c) + " has " + std::to_string(channel.size()) +
                            " samples, channel 0 has " + std::to_string(frames));
    }
    for (std::size_t i = 0; i < frames; ++i) {
      if (!std::isfinite(channel[i])) {
        badSettings(path, "channel " + std::to_string(c) + ", frame " + std::to_string(i) +
                              " is not a finite number");
      }
      peak = std::max(peak, static_cast<double>(std::abs(channel[i])));
    }
  }
  return peak;
}

/// The gain of a peak or loudness normalisation (1 without either); sets the report's flags.
double normalisationGain(const fs::path& path, const AudioBuffer& audio,
                         const AudioWriteSettings& settings, AudioWriteReport& report) {
  if (settings.normalizePeakDbfs && settings.loudness)
    badSettings(path, "normalise either to a peak or to a loudness, not both");
  if (settings.normalizePeakDbfs) {
    if (!std::isfinite(*settings.normalizePeakDbfs))
      badSettings(path, "the normalisation peak must be a finite level in dBFS");
    return report.inputPeak > 0
               ? std::pow(10.0, *settings.normalizePeakDbfs / 20.0) / report.inputPeak
               : 1.0;
  }
  if (!settings.loudness) return 1.0;
  if (!std::isfinite(settings.loudness->integratedLufs) ||
      !std::isfinite(settings.loudness->truePeakCeilingDbtp))
    badSettings(path, "the loudness target and true-peak ceiling must be finite levels");
  // Measured with the peak at full scale, so that BS.1770's one absolute gate (−70 LUFS) drops
  // only what is 70 dB below the loudest sound, whatever the render's level in pascals.
  const double probe = report.inputPeak > 0 ? 1.0 / report.inputPeak : 1.0;
  const io::LoudnessMeasurement m =
      io::measureLoudness(audio.channels, audio.sampleRate, probe);
  const std::optional<io::LoudnessGain> gain =
      io::loudnessNormalisationGain(m, *settings.loudness);
  if (!gain) {
    report.loudnessUnmeasured = true;
    return 1.0;
  }
  report.truePeakLimited = gain->limitedByTruePeak;
  return probe * std::pow(10.0, gain->gainDecibels / 20.0);
}

/// Names the channels in a WAV's iXML chunk (before any audio is written: libsndfile's rule).
void addChannelNames(const fs::path& path, SNDFILE* file, const AudioWriteSettings& settings,
                     int format) {
  if (settings.channelNames.empty() || (format & SF_FORMAT_TYPEMASK) == SF_FORMAT_FLAC) return;
  std::string xml = ixmlTrackList(settings.channelNames);
  // libsndfile copies `datalen` bytes but writes the chunk rounded up to 4: pad it ourselves.
  while (xml.size() % 4 != 0) xml += '\n';
  SF_CHUNK_INFO chunk{};
  std::memcpy(chunk.id, "iXML", 4);
  chunk.id_size = 4;
  chunk.datalen = static_cast<unsigned>(xml.size());
  chunk.data = xml.data();
  if (sf_set_chunk(file, &chunk) != SF_ERR_NO_ERROR)
    throw OutputError(path.string() + ": cannot write: the iXML chunk: " + sf_strerror(file));
}

double decibelsFromAmplitude(double amplitude) {
  return amplitude > 0 ? 20.0 * std::log10(amplitude) : -std::numeric_limits<double>::infinity();
}

/// Uniform on [0, 1) from the top 53 bits of one draw: exactly specified, unlike
/// std::uniform_real_distribution, so the dither is the same with every standard library.
double uniform01(std::mt19937_64& generator) {
  return static_cast<double>(generator() >> 11) * 0x1.0p-53;
}

/// Owns an open SNDFILE; close() reports errors (a destructor cannot).
class SoundFile {
 public:
  explicit SoundFile(SNDFILE* file) : file_(file) {}
  ~SoundFile() {
    if (file_ != nullptr) sf_close(file_);
  }
  SoundFile(const SoundFile&) = delete;
  SoundFile& operator=(const SoundFile&) = delete;
  SNDFILE* get() const { return file_; }
  /// @return libsndfile's error code of the close (0 on success)
  int close() {
    const int code = sf_close(file_);
    file_ = nullptr;
    return code;
  }

 private:
  SNDFILE* file_;
};

/// A file in memory for libsndfile (sf_open_virtual): WAV's header is patched after the samples,
/// which needs a seekable file; the bytes are then written by the output rule, so a FIFO, a
/// device or standard output gets the same bytes as a regular file.
struct MemoryFile {
  std::string bytes;
  sf_count_t position = 0;

  static MemoryFile& of(void* user) { return *static_cast<MemoryFile*>(user); }
  static sf_count_t length(void* user) { return static_cast<sf_count_t>(of(user).bytes.size()); }
  static sf_count_t seek(sf_count_t offset, int whence, void* user) {
    MemoryFile& file = of(user);
    const sf_count_t base = whence == SEEK_CUR   ? file.position
                            : whence == SEEK_END ? static_cast<sf_count_t>(file.bytes.size())
                                                 : 0;
    if (base + offset < 0) return -1;
    file.position = base + offset;
    return file.position;
  }
  static sf_count_t read(void* out, sf_count_t count, void* user) {
    MemoryFile& file = of(user);
    const auto size = static_cast<sf_count_t>(file.bytes.size());
    const sf_count_t available = std::max<sf_count_t>(0, std::min(count, size - file.position));
    if (available > 0)
      std::memcpy(out, file.bytes.data() + file.position, static_cast<std::size_t>(available));
    file.position += available;
    return available;
  }
  static sf_count_t write(const void* in, sf_count_t count, void* user) {
    MemoryFile& file = of(user);
    const auto end = static_cast<std::size_t>(file.position + count);
    if (end > file.bytes.size()) file.bytes.resize(end);
    std::memcpy(file.bytes.data() + file.position, in, static_cast<std::size_t>(count));
    file.position += count;
    return count;
  }
  static sf_count_t tell(void* user) { return of(user).position; }
};

/// Marks 3 or more channels of encoded bytes as having no speaker positions (channel_layout.h).
void removeSpeakerPositions(std::string& bytes, const fs::path& path, int format,
                            std::size_t channels) {
  if (channels < kFirstUnpositionedChannelCount) return;
  if ((format & SF_FORMAT_TYPEMASK) == SF_FORMAT_FLAC)
    clearFlacSpeakerMask(bytes, path);
  else
    clearWaveSpeakerMask(bytes, path);
}

}  // namespace

std::optional<AudioFormat> audioFormatFromPath(const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".flac") return AudioFormat::Flac;
  if (extension == ".wav") return AudioFormat::Wav;
  return std::nullopt;
}

AudioWriteReport writeAudio(const fs::path& path, const AudioBuffer& audio,
                            const AudioWriteSettings& settings) {
  EncodedAudio encoded = encodeAudio(path, audio, settings);
  writeOutputFile(path, encoded.bytes);
  return encoded.report;
}

namespace {

/// The sample rate and channel names must fit the audio and the format.
void checkRateAndNames(const fs::path& path, const AudioBuffer& audio,
                       const AudioWriteSettings& settings) {
  const double rate = audio.sampleRate;
  if (!(rate >= 1 && rate <= INT_MAX) || rate != std::floor(rate)) {
    badSettings(
        path, "the sample rate must be a positive whole number of Hz, not " + std::to_string(rate));
  }
  if (!settings.channelNames.empty() && settings.channelNames.size() != audio.channels.size()) {
    badSettings(path, std::to_string(settings.channelNames.size()) + " channel names for " +
                          std::to_string(audio.channels.size()) + " channels");
  }
}

/// libsndfile's description of the file, checked.
SF_INFO soundFileInfo(const fs::path& path, const AudioBuffer& audio, const SampleLayout& layout) {
  SF_INFO info{};
  info.samplerate = static_cast<int>(audio.sampleRate);
  info.channels = static_cast<int>(audio.channels.size());
  info.format = layout.format;
  if (audio.channels.size() > INT_MAX || !sf_format_check(&info)) {
    badSettings(path, "libsndfile cannot write this format with " +
                          std::to_string(audio.channels.size()) + " channels at " +
                          std::to_string(info.samplerate) + " Hz");
  }
  return info;
}

/// Where the interleaved blocks go: the loudness meter of the samples as written, then the file.
struct SampleSink {
  const fs::path& path;
  SNDFILE* file;
  io::LoudnessMeter& meter;

  OutputError failed() const {
    return OutputError(path.string() + ": cannot write: " + sf_strerror(file));
  }
  void writeFloats(const std::vector<float>& block, std::size_t count) const {
    meter.addInterleaved(block);
    const auto want = static_cast<sf_count_t>(count);
    if (sf_writef_float(file, block.data(), want) != want) throw failed();
  }
  void writeInts(const std::vector<int>& block, const std::vector<float>& levels,
                 std::size_t count) const {
    meter.addInterleaved(levels);
    const auto want = static_cast<sf_count_t>(count);
    if (sf_writef_int(file, block.data(), want) != want) throw failed();
  }
};

/// 32-bit float samples: each sample times `gain`, rounded to float. Returns the peak written
/// (full scale 1.0).
double writeFloatSamples(const AudioBuffer& audio, double gain, const SampleSink& sink) {
  const std::size_t channels = audio.channels.size();
  const std::size_t frames = audio.frameCount();
  double outputPeak = 0.0;
  std::vector<float> block;
  for (std::size_t start = 0; start < frames; start += kBlockFrames) {
    const std::size_t count = std::min(kBlockFrames, frames - start);
    block.resize(count * channels);
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t c = 0; c < channels; ++c) {
        const float value = static_cast<float>(audio.channels[c][start + i] * gain);
        outputPeak = std::max(outputPeak, static_cast<double>(std::abs(value)));
        block[i * channels + c] = value;
      }
    }
    sink.writeFloats(block, count);
  }
  return outputPeak;
}

/// Integer samples of `bits` bits with TPDF dither from `ditherSeed`, clipped to the codes
/// (counted in report.clippedSamples). Returns the peak written (full scale 1.0).
double writeDitheredSamples(const AudioBuffer& audio, int bits, std::uint64_t ditherSeed,
                            const SampleSink& sink, AudioWriteReport& report) {
  const std::size_t channels = audio.channels.size();
  const std::size_t frames = audio.frameCount();
  // Codes q in [-2^(bits-1), 2^(bits-1) - 1]; full scale 1.0 is 2^(bits-1), as libsndfile reads.
  const double fullScale = std::ldexp(1.0, bits - 1);
  const std::int64_t lowest = -static_cast<std::int64_t>(fullScale);
  const std::int64_t highest = static_cast<std::int64_t>(fullScale) - 1;
  // libsndfile keeps the top `bits` bits of the 32-bit ints it is given.
  const std::int64_t toInt32 = std::int64_t{1} << (32 - bits);
  std::mt19937_64 dither(ditherSeed);
  std::int64_t largestCode = 0;
  std::vector<int> block;
  std::vector<float> levels;  // the codes at full scale 1.0, for the loudness meter
  for (std::size_t start = 0; start < frames; start += kBlockFrames) {
    const std::size_t count = std::min(kBlockFrames, frames - start);
    block.resize(count * channels);
    levels.resize(count * channels);
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t c = 0; c < channels; ++c) {
        // TPDF dither: the sum of two independent uniform ±0.5 LSB values (Lipshitz,
        // Wannamaker & Vanderkooy 1992), drawn frame by frame, channel by channel.
        const double noise = uniform01(dither) + uniform01(dither) - 1.0;
        const double scaled = audio.channels[c][start + i] * report.gain * fullScale;
        auto code = static_cast<std::int64_t>(std::floor(scaled + noise + 0.5));
        if (code > highest || code < lowest) {
          code = std::clamp(code, lowest, highest);
          ++report.clippedSamples;
        }
        largestCode = std::max(largestCode, code < 0 ? -code : code);
        block[i * channels + c] = static_cast<int>(code * toInt32);
        levels[i * channels + c] = static_cast<float>(static_cast<double>(code) / fullScale);
      }
    }
    sink.writeInts(block, levels, count);
  }
  return static_cast<double>(largestCode) / fullScale;
}

}  // namespace

EncodedAudio encodeAudio(const fs::path& path, const AudioBuffer& audio,
                         const AudioWriteSettings& settings) {
  // Validate everything before touching the disk.
  const SampleLayout layout = sampleLayout(path, settings, audio.channels.size());
  checkRateAndNames(path, audio, settings);
  AudioWriteReport report;
  report.inputPeak = checkedPeak(path, audio);
  report.gain = normalisationGain(path, audio, settings, report);
  SF_INFO info = soundFileInfo(path, audio, layout);

  MemoryFile memory;
  SF_VIRTUAL_IO io{MemoryFile::length, MemoryFile::seek, MemoryFile::read, MemoryFile::write,
                   MemoryFile::tell};
  SoundFile file(sf_open_virtual(&io, SFM_WRITE, &info, &memory));
  if (file.get() == nullptr) {
    throw OutputError(path.string() + ": cannot write: " + sf_strerror(nullptr));
  }
  // No PEAK chunk: libsndfile stamps it with the time of writing, so two renders of the same
  // input would differ in those bytes (the peak is in report.json).
  sf_command(file.get(), SFC_SET_ADD_PEAK_CHUNK, nullptr, SF_FALSE);
  addChannelNames(path, file.get(), settings, layout.format);
  io::LoudnessMeter meter(audio.channels.size(),
                                 audio.sampleRate);  // of the samples as written
  const SampleSink sink{path, file.get(), meter};
  const double outputPeak =
      layout.bits == 32
          ? writeFloatSamples(audio, report.gain, sink)
          : writeDitheredSamples(audio, layout.bits, settings.ditherSeed, sink, report);
  if (const int code = file.close(); code != 0) {
    throw OutputError(path.string() + ": cannot write: " + sf_error_number(code));
  }
  removeSpeakerPositions(memory.bytes, path, layout.format, audio.channels.size());
  report.outputPeakDbfs = decibelsFromAmplitude(outputPeak);
  report.written = meter.measurement();
  return {std::move(memory.bytes), report};
}

AudioBuffer readAudio(const fs::path& path) {
  // `-` is standard input, which libsndfile itself opens for the name "-" (as sox does).
  const bool standardInput = path == "-";
  const std::string name = standardInput ? "standard input" : path.string();
  if (!standardInput) {
    if (const std::string kind = nonRegularInput(path); !kind.empty())
      throw InputError(name, "", "a readable file", kind);
  }
  SF_INFO info{};
  SoundFile file(sf_open(path.c_str(), SFM_READ, &info));
  if (file.get() == nullptr) {
    throw InputError(name, "", "an audio file that libsndfile can read (WAV, FLAC, ...)",
                     sf_strerror(nullptr));
  }
  AudioBuffer audio;
  audio.sampleRate = info.samplerate;
  const auto channels = static_cast<std::size_t>(info.channels);
  audio.channels.resize(channels);
  if (info.frames > 0 && info.frames != SF_COUNT_MAX) {  // SF_COUNT_MAX: length unknown
    for (auto& channel : audio.channels) channel.reserve(static_cast<std::size_t>(info.frames));
  }
  std::vector<float> block(kBlockFrames * channels);
  sf_count_t count = 0;
  while ((count = sf_readf_float(file.get(), block.data(), static_cast<sf_count_t>(kBlockFrames))) >
         0) {
    for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
      for (std::size_t c = 0; c < channels; ++c)
        audio.channels[c].push_back(block[i * channels + c]);
    }
  }
  if (sf_error(file.get()) != SF_ERR_NO_ERROR) {
    throw InputError(name, "", "a readable audio file", sf_strerror(file.get()));
  }
  return audio;
}

}  // namespace fluidsound::io
