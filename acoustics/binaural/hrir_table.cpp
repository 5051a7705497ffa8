// acoustics/binaural/hrir_table.cpp — see hrir_table.h.
#include "acoustics/binaural/hrir_table.h"

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace fluidsound::acoustics {

namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double correlation(const std::vector<float>& a, const std::vector<float>& b, long lag) {
  double sum = 0.0;
  for (long n = 0; n < static_cast<long>(a.size()); ++n) {
    const long m = n - lag;
    if (m >= 0 && m < static_cast<long>(b.size())) sum += static_cast<double>(a[n]) * b[m];
  }
  return sum;
}

}  // namespace

std::size_t nearestDirection(const HrirTable& table, const Vec3& direction) {
  const double length = norm(direction);
  if (!(length > 0.0) || table.directions.empty())
    throw std::invalid_argument("nearestDirection: a direction of length 0 or an empty table");
  std::size_t best = 0;
  double closest = -2.0;
  for (std::size_t i = 0; i < table.directions.size(); ++i) {
    const double c = dot(table.directions[i], direction) / length;
    if (c > closest) closest = c, best = i;
  }
  return best;
}

double interauralTimeDifference(const HrirTable& table, std::size_t index) {
  const std::vector<float>& l = table.left.at(index);
  const std::vector<float>& r = table.right.at(index);
  const long span = static_cast<long>(l.size());
  long bestLag = 0;
  double best = -std::numeric_limits<double>::infinity();
  for (long lag = -span + 1; lag < span; ++lag) {
    const double c = correlation(r, l, lag);  // r[n] ≈ l[n − lag]: the right ear lags by `lag`
    if (c > best) best = c, bestLag = lag;
  }
  const double before = correlation(r, l, bestLag - 1), after = correlation(r, l, bestLag + 1);
  const double curvature = before - 2.0 * best + after;
  const double offset = curvature < 0.0 ? 0.5 * (before - after) / curvature : 0.0;
  return (bestLag + offset) / table.sampleRate + (table.delayRight.at(index) - table.delayLeft.at(index));
}

double responseMagnitude(const std::vector<float>& response, double frequency, double sampleRate) {
  std::complex<double> sum(0.0);
  for (std::size_t n = 0; n < response.size(); ++n)
    sum += static_cast<double>(response[n]) *
           std::polar(1.0, -2.0 * std::numbers::pi * frequency * static_cast<double>(n) / sampleRate);
  return std::abs(sum);
}

double interauralLevelDifference(const HrirTable& table, std::size_t index, double frequency) {
  return 20.0 * std::log10(responseMagnitude(table.left.at(index), frequency, table.sampleRate) /
                           responseMagnitude(table.right.at(index), frequency, table.sampleRate));
}

double freeFieldGain(const HrirTable& table) {
  const std::size_t ahead = nearestDirection(table, {1.0, 0.0, 0.0});
  double sum = 0.0;
  int count = 0;
  for (double f = 200.0; f <= 500.0; f += 50.0, count += 2)
    sum += responseMagnitude(table.left[ahead], f, table.sampleRate) +
           responseMagnitude(table.right[ahead], f, table.sampleRate);
  if (!(sum > 0.0)) throw std::invalid_argument("freeFieldGain: the frontal responses are silent below 500 Hz");
  return count / sum;
}

Vec3 headDirection(const Vec3& world, const Vec3& facing, const Vec3& up) {
  const double f = norm(facing);
  if (!(f > 0.0)) throw std::invalid_argument("headDirection: facing is zero");
  const Vec3 x{facing[0] / f, facing[1] / f, facing[2] / f};
  const double along = dot(up, x);
  Vec3 z{up[0] - along * x[0], up[1] - along * x[1], up[2] - along * x[2]};
  const double u = norm(z);
  if (!(u > 1e-9 * (norm(up) + 1e-300))) throw std::invalid_argument("headDirection: up is zero or along facing");
  for (double& c : z) c /= u;
  const Vec3 y = cross(z, x);  // left = up × facing
  return {dot(world, x), dot(world, y), dot(world, z)};
}

}  // namespace fluidsound::acoustics
