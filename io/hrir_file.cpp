// io/hrir_file.cpp — see hrir_file.h.
#include "io/hrir_file.h"

#include <mysofa.h>

#include <cmath>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "io/input_error.h"

namespace fluidsound::io {

std::filesystem::path defaultHrirFile() {
  return "/usr/share/libmysofa/MIT_KEMAR_normal_pinna.sofa";
}

acoustics::HrirTable readHrirTable(const std::filesystem::path& sofa, std::optional<double> sampleRate) {
  const std::string file = sofa.string();
  // libmysofa would block on a FIFO and read a device: only regular files are opened.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(sofa, ec))
    throw InputError(file, "", "a readable SOFA file of head-related impulse responses",
                     std::filesystem::exists(sofa, ec) ? "not a regular file" : "no such file");
  int err = MYSOFA_OK;
  std::unique_ptr<MYSOFA_HRTF, decltype(&mysofa_free)> hrtf(mysofa_load(file.c_str(), &err),
                                                           &mysofa_free);
  if (!hrtf || err != MYSOFA_OK)
    throw InputError(file, "", "a readable SOFA file of head-related impulse responses",
                     "libmysofa error " + std::to_string(err));
  if (mysofa_check(hrtf.get()) != MYSOFA_OK)
    throw InputError(file, "", "a SOFA SimpleFreeFieldHRIR set libmysofa accepts", "another convention");
  if (hrtf->R != 2 || hrtf->M < 1 || hrtf->N < 1 || hrtf->DataSamplingRate.elements < 1)
    throw InputError(file, "Data.IR", "two receivers (the ears) and at least one measurement",
                     std::to_string(hrtf->R) + " receivers, " + std::to_string(hrtf->M) + " measurements");
  mysofa_tocartesian(hrtf.get());
  const double fileRate = hrtf->DataSamplingRate.values[0];
  // Data.Delay is per receiver, either once for all measurements or per measurement [samples at
  // the file's rate]: taken in seconds before any resampling.
  const auto delaySeconds = [&](unsigned m, unsigned receiver) {
    const MYSOFA_ARRAY& d = hrtf->DataDelay;
    if (d.elements == 2) return d.values[receiver] / fileRate;
    if (d.elements == 2 * hrtf->M) return d.values[2 * m + receiver] / fileRate;
    return 0.0;
  };
  std::vector<double> delays(2 * hrtf->M);
  for (unsigned m = 0; m < hrtf->M; ++m) delays[2 * m] = delaySeconds(m, 0), delays[2 * m + 1] = delaySeconds(m, 1);
  if (sampleRate && *sampleRate != fileRate &&
      mysofa_resample(hrtf.get(), static_cast<float>(*sampleRate)) != MYSOFA_OK)
    throw InputError(file, "Data.SamplingRate", "responses libmysofa can resample to " +
                     std::to_string(std::lround(*sampleRate)) + " Hz", std::to_string(std::lround(fileRate)) + " Hz");
  acoustics::HrirTable table;
  table.sampleRate = hrtf->DataSamplingRate.values[0];
  const unsigned n = hrtf->N;
  for (unsigned m = 0; m < hrtf->M; ++m) {
    const float* p = hrtf->SourcePosition.values + 3 * m;
    const double length = std::hypot(p[0], p[1], p[2]);
    if (!(length > 0.0)) continue;  // a source at the head's centre has no direction
    table.directions.push_back({p[0] / length, p[1] / length, p[2] / length});
    const float* left = hrtf->DataIR.values + (2 * m) * n;
    const float* right = hrtf->DataIR.values + (2 * m + 1) * n;
    table.left.emplace_back(left, left + n);
    table.right.emplace_back(right, right + n);
    table.delayLeft.push_back(delays[2 * m]);
    table.delayRight.push_back(delays[2 * m + 1]);
  }
  if (table.directions.empty())
    throw InputError(file, "SourcePosition", "at least one source away from the head's centre", "none");
  return table;
}

}  // namespace fluidsound::io
