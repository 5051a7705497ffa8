// tools/synth_report.cpp — see synth_report.h.
#include "tools/synth_report.h"

#include <string>

#include "tools/audio_options.h"

namespace fluidsound::tools {

void addSynthResults(RunReport& report, const SynthOptions& o, const SynthRender& render) {
  const acoustics::SynthesisSettings& settings = render.stage.settings;
  const acoustics::SynthesisReport& r = render.stage.report;
  const io::AudioWriteReport& w = render.written;
  report.setting("input", o.input);
  report.setting("output", o.output);
  report.setting("sample_rate", settings.sampleRate);
  report.setOscillatorModel(settings.model);
  report.result("bubbles_in_file", static_cast<double>(render.bubblesInFile));
  report.result("bubbles_rendered", static_cast<double>(r.bubblesRendered));
  report.result("bubbles_above_nyquist", static_cast<double>(r.bubblesAboveNyquist));
  report.result("bubbles_after_end", static_cast<double>(r.bubblesSilent));
  report.result("depths_clamped", static_cast<double>(r.depthsClamped));
  report.result("oscillator_samples", static_cast<double>(r.oscillatorSamples));
  report.result("duration_seconds", render.stage.durationSeconds());
  report.result("channels", static_cast<double>(render.channels));
  report.result("peak_pascals", r.peakPascals);
  report.result("ring_samples", r.ringSamples);
  // The inner loop that ran (acoustics/synthesis/oscillator_kernel.h): a speed figure says what it
  // measured.
  report.result("oscillator_kernel", std::string(acoustics::oscillatorKernelName(r.kernel)));
  report.result("gain", w.gain);
  report.result("output_peak_dbfs", w.outputPeakDbfs);
  report.result("clipped_samples", static_cast<double>(w.clippedSamples));
  reportAudioOutput(report, render.write,
                    w);  // format, bits, normalisation, scale, loudness, channels
}

}  // namespace fluidsound::tools
