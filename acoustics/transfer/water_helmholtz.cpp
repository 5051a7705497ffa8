// acoustics/transfer/water_helmholtz.cpp — see water_helmholtz.h.
#include "acoustics/transfer/water_helmholtz.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include <Eigen/SparseCholesky>
#include <Eigen/UmfPackSupport>

namespace fluidsound::acoustics {

namespace {

/// Lower clamp of the ghost-fluid fraction θ, the projection's (sim/fluid/pressure_solver.h).
constexpr double kMinimumSurfaceFraction = 0.01;

using ComplexMatrix = Eigen::SparseMatrix<Complex>;

/// What a cell of the grid is to the water side.
enum class CellKind : unsigned char { Liquid, Air, Solid };

/// One ghost-fluid term: the equation of `unknown` gets coefficient·p_L at air point `point`.
struct SurfaceCrossing {
  int unknown = 0;
  int point = 0;
  double coefficient = 0.0;  ///< w_f / θ [-]
};

}  // namespace

struct WaterHelmholtz::Impl {
  WaterGrid grid;
  double soundSpeed = 0.0, lossFactor = 0.0;
  std::vector<CellKind> kind;
  std::vector<int> unknownOfCell;  ///< −1 for a cell that is not a liquid unknown
  std::vector<int> airPointOfCell; ///< −1 unless an air cell next to the liquid
  std::vector<AirPoint> airPoints;
  std::vector<SurfaceCrossing> crossings;
  Eigen::SparseMatrix<double> laplacian;  ///< Σ w_f (u_c − u_n) + ghost terms, ×h² scaled
  /// The fill-reducing (AMD) order of the fast method's LDLᵀ, the same for every frequency of
  /// the frame: found once, on the first factorisation.
  mutable std::once_flag orderOnce;
  mutable Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order, orderInverse;
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>& fillReducingOrder() const {
    std::call_once(orderOnce, [this] {
      Eigen::AMDOrdering<int> amd;
      amd(laplacian, orderInverse);
      order = orderInverse.inverse();
    });
    return order;
  }
  Eigen::VectorXd volume;                 ///< open volume fraction ·h² per unknown
  Vec3 liquidMin{}, liquidMax{};

  double faceOpen(int axis, int i, int j, int k) const {
    const std::vector<float>& f = grid.faceOpen[axis];
    return f.empty() ? 1.0 : f[grid.faceIndex(axis, i, j, k)];
  }
  bool inGrid(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < grid.cells[0] && j < grid.cells[1] &&
           k < grid.cells[2];
  }
  /// The cell's open volume fraction: given, else the mean of its six faces' fractions.
  double cellOpen(int i, int j, int k) const {
    if (!grid.cellOpen.empty()) return grid.cellOpen[grid.cellIndex(i, j, k)];
    double sum = 0.0;
    for (int a = 0; a < 3; ++a) {
      std::array<int, 3> c{i, j, k};
      sum += faceOpen(a, c[0], c[1], c[2]);
      ++c[a];
      sum += faceOpen(a, c[0], c[1], c[2]);
    }
    return sum / 6.0;
  }
  void classifyCells();
  void markEnclosedAir(std::vector<char>& openAir) const;
  void addAirPoints();
  void assemble();
};

void WaterHelmholtz::Impl::classifyCells() {
  const std::size_t n = grid.cellCount();
  kind.assign(n, CellKind::Solid);
  unknownOfCell.assign(n, -1);
  int next = 0;
  for (int k = 0; k < grid.cells[2]; ++k)
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i) {
        const std::size_t c = grid.cellIndex(i, j, k);
        if (cellOpen(i, j, k) <= 0.0) continue;
        if (grid.phi[c] < 0.0f) {
          kind[c] = CellKind::Liquid;
          unknownOfCell[c] = next++;
        } else {
          kind[c] = CellKind::Air;
        }
      }
}

/// Air connected through open faces to an air cell on the grid's boundary is open air: the
/// listener's field reaches it. The rest are enclosed pockets (p_L = 0).
void WaterHelmholtz::Impl::markEnclosedAir(std::vector<char>& openAir) const {
  openAir.assign(grid.cellCount(), 0);
  std::vector<std::array<int, 3>> stack;
  const auto& n = grid.cells;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const bool boundary = i == 0 || j == 0 || k == 0 || i == n[0] - 1 || j == n[1] - 1 ||
                              k == n[2] - 1;
        const std::size_t c = grid.cellIndex(i, j, k);
        if (boundary && kind[c] == CellKind::Air && !openAir[c]) {
          openAir[c] = 1;
          stack.push_back({i, j, k});
        }
      }
  while (!stack.empty()) {
    const std::array<int, 3> c = stack.back();
    stack.pop_back();
    for (int a = 0; a < 3; ++a)
      for (int s = -1; s <= 1; s += 2) {
        std::array<int, 3> m = c;
        m[a] += s;
        if (!inGrid(m[0], m[1], m[2])) continue;
        std::array<int, 3> face = c;
        if (s > 0) ++face[a];
        if (faceOpen(a, face[0], face[1], face[2]) <= 0.0) continue;
        const std::size_t mc = grid.cellIndex(m[0], m[1], m[2]);
        if (kind[mc] != CellKind::Air || openAir[mc]) continue;
        openAir[mc] = 1;
        stack.push_back(m);
      }
  }
}

void WaterHelmholtz::Impl::assemble() {
  std::vector<char> openAir;
  markEnclosedAir(openAir);
  const double h = grid.cellSize;
  std::vector<Eigen::Triplet<double>> entries;
  const int unknowns = static_cast<int>(
      std::count_if(unknownOfCell.begin(), unknownOfCell.end(), [](int u) { return u >= 0; }));
  volume.setZero(unknowns);
  liquidMin = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
               std::numeric_limits<double>::max()};
  liquidMax = {-liquidMin[0], -liquidMin[1], -liquidMin[2]};
  for (int k = 0; k < grid.cells[2]; ++k)
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i) {
        const std::size_t c = grid.cellIndex(i, j, k);
        const int row = unknownOfCell[c];
        if (row < 0) continue;
        const Vec3 centre = grid.cellCentre(i, j, k);
        for (int a = 0; a < 3; ++a) {
          liquidMin[a] = std::min(liquidMin[a], centre[a] - 0.5 * h);
          liquidMax[a] = std::max(liquidMax[a], centre[a] + 0.5 * h);
        }
        volume[row] = cellOpen(i, j, k) * h * h;
        double diagonal = 0.0;
        for (int a = 0; a < 3; ++a)
          for (int s = -1; s <= 1; s += 2) {
            std::array<int, 3> m{i, j, k}, face{i, j, k};
            m[a] += s;
            if (s > 0) ++face[a];
            const double w = faceOpen(a, face[0], face[1], face[2]);
            if (w <= 0.0) continue;
            Vec3 direction{0.0, 0.0, 0.0};
            direction[a] = s;
            double theta = 0.0;
            bool enclosed = false;
            if (!inGrid(m[0], m[1], m[2])) {
              const int side = 2 * a + (s > 0 ? 1 : 0);
              if (!grid.openSides[side]) continue;  // a rigid grid side: ∂u/∂n = 0
              theta = 0.5;                          // air begins at the side itself
            } else {
              const std::size_t mc = grid.cellIndex(m[0], m[1], m[2]);
              if (kind[mc] == CellKind::Liquid) {
                diagonal += w;
                entries.emplace_back(row, unknownOfCell[mc], -w);
                continue;
              }
              if (kind[mc] == CellKind::Solid) continue;  // closed cell: ∂u/∂n = 0
              const double phiLiquid = grid.phi[c], phiAir = grid.phi[mc];
              theta = std::max(phiLiquid / (phiLiquid - phiAir), kMinimumSurfaceFraction);
              enclosed = !openAir[mc];
            }
            // Ghost fluid (Gibou et al. 2002): u at the crossing x_c + θh·e is p_L there.
            diagonal += w / theta;
            AirPoint point;
            for (int b = 0; b < 3; ++b) point.position[b] = centre[b] + theta * h * direction[b];
            point.enclosed = enclosed;
            crossings.push_back({row, static_cast<int>(airPoints.size()), w / theta});
            airPoints.push_back(point);
          }
        entries.emplace_back(row, row, diagonal);
      }
  laplacian.resize(unknowns, unknowns);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  addAirPoints();
  for (std::size_t c = 0; c < grid.cellCount(); ++c)
    if (airPointOfCell[c] >= 0) airPoints[airPointOfCell[c]].enclosed = !openAir[c];
}

/// Every air cell in the 26-neighbourhood of a liquid unknown gets an air point at its centre.
void WaterHelmholtz::Impl::addAirPoints() {
  airPointOfCell.assign(grid.cellCount(), -1);
  for (int k = 0; k < grid.cells[2]; ++k)
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i) {
        const std::size_t c = grid.cellIndex(i, j, k);
        if (kind[c] != CellKind::Air) continue;
        bool nearLiquid = false;
        for (int dk = -1; dk <= 1 && !nearLiquid; ++dk)
          for (int dj = -1; dj <= 1 && !nearLiquid; ++dj)
            for (int di = -1; di <= 1 && !nearLiquid; ++di)
              nearLiquid = inGrid(i + di, j + dj, k + dk) &&
                           unknownOfCell[grid.cellIndex(i + di, j + dj, k + dk)] >= 0;
        if (!nearLiquid) continue;
        airPointOfCell[c] = static_cast<int>(airPoints.size());
        airPoints.push_back({grid.cellCentre(i, j, k), false});
      }
}

WaterHelmholtz::WaterHelmholtz(const WaterGrid& grid, double soundSpeed, double lossFactor)
    : impl_(std::make_unique<Impl>()) {
  if (grid.cells[0] < 1 || grid.cells[1] < 1 || grid.cells[2] < 1 || !(grid.cellSize > 0.0) ||
      grid.phi.size() != grid.cellCount())
    throw std::invalid_argument("water grid: phi has " + std::to_string(grid.phi.size()) +
                                " values for " + std::to_string(grid.cellCount()) + " cells");
  for (int a = 0; a < 3; ++a) {
    std::size_t faces = grid.cellCount() / grid.cells[a] * (grid.cells[a] + 1);
    if (!grid.faceOpen[a].empty() && grid.faceOpen[a].size() != faces)
      throw std::invalid_argument("water grid: faceOpen[" + std::to_string(a) + "] has " +
                                  std::to_string(grid.faceOpen[a].size()) + " values for " +
                                  std::to_string(faces) + " faces");
  }
  if (!grid.cellOpen.empty() && grid.cellOpen.size() != grid.cellCount())
    throw std::invalid_argument("water grid: cellOpen has " + std::to_string(grid.cellOpen.size()) +
                                " values for " + std::to_string(grid.cellCount()) + " cells");
  if (!(soundSpeed > 0.0) || !(lossFactor >= 0.0))
    throw std::invalid_argument("water grid: sound speed and loss factor must be positive");
  impl_->grid = grid;
  impl_->soundSpeed = soundSpeed;
  impl_->lossFactor = lossFactor;
  impl_->classifyCells();
  impl_->assemble();
}

WaterHelmholtz::~WaterHelmholtz() = default;
WaterHelmholtz::WaterHelmholtz(WaterHelmholtz&&) noexcept = default;
WaterHelmholtz& WaterHelmholtz::operator=(WaterHelmholtz&&) noexcept = default;

double WaterHelmholtz::cellSize() const { return impl_->grid.cellSize; }
std::size_t WaterHelmholtz::unknowns() const { return impl_->volume.size(); }
const std::vector<AirPoint>& WaterHelmholtz::airPoints() const { return impl_->airPoints; }

double WaterHelmholtz::liquidSize() const {
  if (unknowns() == 0) return 0.0;
  const Vec3 &lo = impl_->liquidMin, &hi = impl_->liquidMax;
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

Vec3 WaterHelmholtz::liquidCentre() const {
  if (unknowns() == 0) return impl_->grid.origin;
  const Vec3 &lo = impl_->liquidMin, &hi = impl_->liquidMax;
  return {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
}

bool WaterHelmholtz::inLiquid(const Vec3& x) const {
  const WaterGrid& g = impl_->grid;
  std::array<int, 3> c{};
  for (int a = 0; a < 3; ++a) c[a] = static_cast<int>(std::floor((x[a] - g.origin[a]) / g.cellSize));
  return impl_->inGrid(c[0], c[1], c[2]) && impl_->unknownOfCell[g.cellIndex(c[0], c[1], c[2])] >= 0;
}

PointSample WaterHelmholtz::sampleAt(const Vec3& x) const {
  const WaterGrid& g = impl_->grid;
  std::array<int, 3> base{};
  std::array<double, 3> t{};
  for (int a = 0; a < 3; ++a) {
    const double u = (x[a] - g.origin[a]) / g.cellSize - 0.5;
    base[a] = static_cast<int>(std::floor(u));
    t[a] = u - base[a];
  }
  PointSample sample;
  double kept = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    std::array<int, 3> c = base;
    double weight = 1.0;
    for (int a = 0; a < 3; ++a) {
      const bool upper = (corner >> a) & 1;
      c[a] += upper ? 1 : 0;
      weight *= upper ? t[a] : 1.0 - t[a];
    }
    if (weight <= 0.0 || !impl_->inGrid(c[0], c[1], c[2])) continue;
    const std::size_t cell = g.cellIndex(c[0], c[1], c[2]);
    if (impl_->unknownOfCell[cell] >= 0)
      sample.cells.emplace_back(impl_->unknownOfCell[cell], weight);
    else if (impl_->airPointOfCell[cell] >= 0)
      sample.air.emplace_back(impl_->airPointOfCell[cell], weight);
    else
      continue;
    kept += weight;
  }
  if (sample.cells.empty()) return {};
  for (auto& [index, weight] : sample.cells) weight /= kept;
  for (auto& [index, weight] : sample.air) weight /= kept;
  return sample;
}

Eigen::VectorXcd WaterHelmholtz::rightHandSide(std::span<const Complex> airPressure) const {
  if (airPressure.size() != impl_->airPoints.size())
    throw std::invalid_argument("water side: p_L has " + std::to_string(airPressure.size()) +
                                " values for " + std::to_string(impl_->airPoints.size()) +
                                " air points");
  Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(static_cast<Eigen::Index>(unknowns()));
  for (const SurfaceCrossing& x : impl_->crossings)
    if (!impl_->airPoints[x.point].enclosed) rhs[x.unknown] += x.coefficient * airPressure[x.point];
  return rhs;
}

std::vector<Complex> WaterHelmholtz::airWeights(const PointSample& sample,
                                                const Eigen::VectorXcd& adjoint) const {
  std::vector<Complex> weights(impl_->airPoints.size(), Complex(0.0));
  for (const SurfaceCrossing& x : impl_->crossings) weights[x.point] += x.coefficient * adjoint[x.unknown];
  for (const auto& [point, weight] : sample.air) weights[point] += weight;
  for (std::size_t p = 0; p < weights.size(); ++p)
    if (impl_->airPoints[p].enclosed) weights[p] = 0.0;
  return weights;
}

const Eigen::SparseMatrix<double>& WaterHelmholtz::stiffness() const { return impl_->laplacian; }
const Eigen::VectorXd& WaterHelmholtz::mass() const { return impl_->volume; }

Complex WaterHelmholtz::evaluate(const PointSample& sample, const Eigen::VectorXcd& u,
                                 std::span<const Complex> airPressure) const {
  Complex value(0.0);
  for (const auto& [cell, weight] : sample.cells) value += weight * u[cell];
  for (const auto& [point, weight] : sample.air)
    if (!impl_->airPoints[point].enclosed) value += weight * airPressure[point];
  return value;
}

struct HelmholtzFactor::Impl {
  HelmholtzMethod method = HelmholtzMethod::Fast;
  std::size_t unknowns = 0;
  // UMFPACK (SuiteSparse): 20–700× faster here than Eigen's SparseLU on these 3-D grids.
  // UMFPACK's solve reads the matrix again (iterative refinement), and Eigen keeps pointers to
  // it: the factor owns its matrix.
  ComplexMatrix matrix;
  Eigen::UmfPackLU<ComplexMatrix> lu;
  bool luReady = false;
  // The fast method: a real LDLᵀ of the lossless operator L − Re(k²)M in the frame's
  // fill-reducing order P (P L Pᵀ is factorised), the loss −i·Im(k²)M added back by iterative
  // refinement.
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> ldlt;
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>* order = nullptr;
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>* orderInverse = nullptr;
  bool ldltReady = false;

  void factoriseLu() {
    lu.compute(matrix);
    if (lu.info() != Eigen::Success)
      throw std::runtime_error("the water-side factorisation failed (a singular operator)");
    luReady = true;
  }
  Eigen::VectorXcd solveReal(const Eigen::VectorXcd& rhs) const {
    const Eigen::VectorXd re = *orderInverse * ldlt.solve((*order * rhs.real()).eval()),
                          im = *orderInverse * ldlt.solve((*order * rhs.imag()).eval());
    Eigen::VectorXcd x(rhs.size());
    x.real() = re;
    x.imag() = im;
    return x;
  }
  /// The fast solve, or nothing when its refinement does not converge (within ~η of a
  /// resonance, or a broken-down pivot). `modes`, when given, are kept out of every iterate.
  std::optional<Eigen::VectorXcd> solveRefined(const Eigen::VectorXcd& rhs,
                                               const ExcludedModes* modes = nullptr) const {
    if (!ldltReady) return std::nullopt;
    const double target = kRefinementTolerance * rhs.norm();
    Eigen::VectorXcd x = solveReal(rhs);
    if (modes) modes->project(x);
    for (int iteration = 0; iteration < kMaxRefinements; ++iteration) {
      if (!x.allFinite()) return std::nullopt;
      const Eigen::VectorXcd residual = rhs - matrix * x;
      if (residual.norm() <= target) return x;
      Eigen::VectorXcd step = solveReal(residual);
      if (modes) modes->project(step);
      x += step;
    }
    return std::nullopt;
  }
};

HelmholtzFactor::HelmholtzFactor(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
HelmholtzFactor::~HelmholtzFactor() = default;

std::unique_ptr<HelmholtzFactor> WaterHelmholtz::factorise(double angularFrequency,
                                                           HelmholtzMethod method,
                                                           double extraLoss) const {
  const Complex k2 =
      lossyWavenumberSquared(angularFrequency, impl_->soundSpeed, impl_->lossFactor + extraLoss);
  auto factor = std::make_unique<HelmholtzFactor::Impl>();
  factor->method = method;
  ComplexMatrix& matrix = factor->matrix;
  matrix = impl_->laplacian.cast<Complex>();
  for (Eigen::Index i = 0; i < impl_->volume.size(); ++i)
    matrix.coeffRef(i, i) -= k2 * impl_->volume[i];
  factor->unknowns = unknowns();
  if (unknowns() == 0) return std::unique_ptr<HelmholtzFactor>(new HelmholtzFactor(std::move(factor)));
  if (method == HelmholtzMethod::Fast) {
    factor->order = &impl_->fillReducingOrder();
    factor->orderInverse = &impl_->orderInverse;
    const Eigen::SparseMatrix<double> real = matrix.real();
    Eigen::SparseMatrix<double> permuted(real.rows(), real.cols());
    permuted.selfadjointView<Eigen::Lower>() =
        real.selfadjointView<Eigen::Lower>().twistedBy(*factor->order);
    factor->ldlt.compute(permuted);
    factor->ldltReady = factor->ldlt.info() == Eigen::Success;
  }
  if (!factor->ldltReady) factor->factoriseLu();
  return std::unique_ptr<HelmholtzFactor>(new HelmholtzFactor(std::move(factor)));
}

Eigen::VectorXcd HelmholtzFactor::solve(const Eigen::VectorXcd& rhs) const {
  if (impl_->unknowns == 0) return Eigen::VectorXcd();
  if (std::optional<Eigen::VectorXcd> fast = impl_->solveRefined(rhs)) return *std::move(fast);
  if (!impl_->luReady) impl_->factoriseLu();
  Eigen::VectorXcd u = impl_->lu.solve(rhs);
  if (impl_->lu.info() != Eigen::Success || !u.allFinite())
    throw std::runtime_error("the water-side solve gave a non-finite value");
  return u;
}

Eigen::VectorXcd HelmholtzFactor::solveOutside(const Eigen::VectorXcd& rhs,
                                               const ExcludedModes& modes) const {
  if (impl_->unknowns == 0) return Eigen::VectorXcd();
  if (std::optional<Eigen::VectorXcd> fast = impl_->solveRefined(rhs, &modes))
    return *std::move(fast);
  Eigen::VectorXcd u = solve(rhs);
  modes.project(u);
  return u;
}

ExcludedModes::ExcludedModes(const Eigen::MatrixXd& modeShapes, const Eigen::VectorXd& mass)
    : shapes(modeShapes.cast<Complex>()),
      massShapes((mass.asDiagonal() * modeShapes).cast<Complex>()) {}

Eigen::VectorXcd ExcludedModes::deflate(Eigen::VectorXcd& rhs) const {
  Eigen::VectorXcd numerators = shapes.transpose() * rhs;
  if (shapes.cols() > 0) rhs -= massShapes * numerators;
  return numerators;
}

void ExcludedModes::project(Eigen::VectorXcd& field) const {
  if (shapes.cols() > 0) field -= shapes * (massShapes.transpose() * field);
}

Eigen::VectorXcd WaterHelmholtz::pointSource(const PointSample& sample) const {
  Eigen::VectorXcd source = Eigen::VectorXcd::Zero(static_cast<Eigen::Index>(unknowns()));
  for (const auto& [cell, weight] : sample.cells) source[cell] += weight;
  return source;
}

double WaterHelmholtz::lossFactor() const { return impl_->lossFactor; }

Eigen::VectorXcd HelmholtzFactor::adjoint(const PointSample& sample) const {
  Eigen::VectorXcd source = Eigen::VectorXcd::Zero(static_cast<Eigen::Index>(impl_->unknowns));
  for (const auto& [cell, weight] : sample.cells) source[cell] += weight;
  return solve(source);
}

}  // namespace fluidsound::acoustics
