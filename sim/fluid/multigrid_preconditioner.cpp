// sim/fluid/multigrid_preconditioner.cpp — see multigrid_preconditioner.h. Coarsening, red-black
// Gauss–Seidel smoothing and trilinear transfers of McAdams, Sifakis & Teran (2010), on the
// compact unknown numbering of SevenPointMatrix so that level 0 runs on the assembled matrix.
#include "sim/fluid/multigrid_preconditioner.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "sim/fluid/block_parallel.h"

namespace fluidsound::sim {
namespace {

/// θ across an open face of the domain on a coarse level: p = 0 on the face, half a cell from
/// the centre (as kOpenBoundarySurfaceFraction on the solver grid).
constexpr double kDomainFaceFraction = 0.5;

/// Weights of the two coarse parents of a fine cell along one axis (trilinear, cell centred):
/// the fine centre is ¼ coarse cell from its own parent's centre, ¾ from the other's.
constexpr double kNearParentWeight = 0.75;
constexpr double kFarParentWeight = 0.25;

/// Coarse parents of fine index i along one axis: {own parent, other parent}.
std::array<int, 2> parents(int i) {
  const int own = i >> 1;
  return {own, (i & 1) ? own + 1 : own - 1};
}

constexpr std::array<double, 2> kParentWeights{kNearParentWeight, kFarParentWeight};

/// Σ of the off-diagonal terms A(n, m)·x(m) of row n.
double offDiagonalProduct(const SevenPointMatrix& M, std::size_t n, std::span<const double> x) {
  double sum = 0.0;
  for (int a = 0; a < 3; ++a) {
    const std::int32_t p = M.plusNeighbour[a][n];
    const std::int32_t m = M.minusNeighbour[a][n];
    if (p >= 0) sum += M.plus[a][n] * x[p];
    if (m >= 0) sum += M.plus[a][m] * x[m];
  }
  return sum;
}

/// One Gauss–Seidel half-sweep over one colour: x(n) = (b(n) − Σ A(n, m)·x(m)) / A(n, n). The
/// 7-point neighbours of a colour all have the other colour, so the updates are independent.
void relaxColour(const SevenPointMatrix& M, std::span<const std::int32_t> colour,
                 std::span<const double> b, std::span<double> x) {
  forEachBlock(colour.size(), kUnknownBlock, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t c = begin; c < end; ++c) {
      const std::size_t n = static_cast<std::size_t>(colour[c]);
      x[n] = (b[n] - offDiagonalProduct(M, n, x)) / M.diagonal[n];
    }
  });
}

}  // namespace

void MultigridPreconditioner::build(const Array3<std::int32_t>& unknownOfCell,
                                    const std::array<Array3f, 3>& faceWeights,
                                    double coefficientScale) {
  levels_.clear();
  levels_.emplace_back();
  buildFineLevel(unknownOfCell, faceWeights, coefficientScale, levels_[0]);
  markBoundaryBand(faceWeights, levels_[0]);
  while (*std::max_element(levels_.back().cells.begin(), levels_.back().cells.end()) >
         kMultigridCoarsestCells) {
    Level coarse;
    buildCoarseLevel(levels_.back(), coarse);
    levels_.push_back(std::move(coarse));
  }
  for (std::size_t l = 0; l < levels_.size(); ++l) prepareLevel(l);
}

void MultigridPreconditioner::buildFineLevel(const Array3<std::int32_t>& unknownOfCell,
                                             const std::array<Array3f, 3>& faceWeights,
                                             double coefficientScale, Level& fine) {
  fine.cells = unknownOfCell.size();
  fine.unknownOfCell = unknownOfCell;
  fine.type = Array3<Cell>(fine.cells, Cell::Solid);
  for (int a = 0; a < 3; ++a) {
    fine.faceCoefficient[a] = Array3d(faceWeights[a].size());
    for (std::size_t f = 0; f < faceWeights[a].elementCount(); ++f)
      fine.faceCoefficient[a].values()[f] = coefficientScale * faceWeights[a].values()[f];
  }
  std::int32_t count = 0;
  for (int k = 0; k < fine.cells[2]; ++k)
    for (int j = 0; j < fine.cells[1]; ++j)
      for (int i = 0; i < fine.cells[0]; ++i) {
        if (unknownOfCell(i, j, k) >= 0) {
          fine.type(i, j, k) = Cell::Liquid;
          count = std::max(count, unknownOfCell(i, j, k) + 1);
          continue;
        }
        // Not an unknown but with an open face: air (a liquid cell with one would be one).
        for (int a = 0; a < 3; ++a) {
          Index3 upper{i, j, k};
          ++upper[a];
          if (faceWeights[a](i, j, k) > 0.0f || faceWeights[a](upper[0], upper[1], upper[2]) > 0.0f)
            fine.type(i, j, k) = Cell::Air;
        }
      }
  fine.cellOfUnknown.assign(static_cast<std::size_t>(count), Index3{0, 0, 0});
  for (int k = 0; k < fine.cells[2]; ++k)
    for (int j = 0; j < fine.cells[1]; ++j)
      for (int i = 0; i < fine.cells[0]; ++i)
        if (const std::int32_t n = unknownOfCell(i, j, k); n >= 0)
          fine.cellOfUnknown[static_cast<std::size_t>(n)] = {i, j, k};
}

void MultigridPreconditioner::markBoundaryBand(const std::array<Array3f, 3>& faceWeights,
                                               Level& fine) {
  // Cells with a face cut by a solid (0 < w < 1), then every unknown within
  // kMultigridBoundaryBand cells of one (McAdams et al. 2010, §5 "boundary smoothing").
  constexpr int band = kMultigridBoundaryBand;
  Array3<std::uint8_t> cut(fine.cells, 0);
  for (int k = 0; k < fine.cells[2]; ++k)
    for (int j = 0; j < fine.cells[1]; ++j)
      for (int i = 0; i < fine.cells[0]; ++i)
        for (int a = 0; a < 3; ++a) {
          Index3 upper{i, j, k};
          ++upper[a];
          const float w0 = faceWeights[a](i, j, k);
          const float w1 = faceWeights[a](upper[0], upper[1], upper[2]);
          if ((w0 > 0.0f && w0 < 1.0f) || (w1 > 0.0f && w1 < 1.0f)) cut(i, j, k) = 1;
        }
  for (std::size_t u = 0; u < fine.cellOfUnknown.size(); ++u) {
    const Index3 c = fine.cellOfUnknown[u];
    bool near = false;
    for (int dk = -band; dk <= band && !near; ++dk)
      for (int dj = -band; dj <= band && !near; ++dj)
        for (int di = -band; di <= band && !near; ++di)
          near =
              cut.contains(c[0] + di, c[1] + dj, c[2] + dk) && cut(c[0] + di, c[1] + dj, c[2] + dk);
    if (near) fine.boundaryColour[(c[0] + c[1] + c[2]) & 1].push_back(std::int32_t(u));
  }
}

void MultigridPreconditioner::prepareLevel(std::size_t l) {
  Level& level = levels_[l];
  const std::size_t n = level.cellOfUnknown.size();
  for (auto& c : level.colour) c.clear();
  for (std::size_t u = 0; u < n; ++u) {
    const Index3& c = level.cellOfUnknown[u];
    level.colour[(c[0] + c[1] + c[2]) & 1].push_back(static_cast<std::int32_t>(u));
  }
  level.rhs.assign(n, 0.0);
  level.solution.assign(n, 0.0);
  level.residual.assign(n, 0.0);
  level.prolongationScale.assign(n, 1.0);
  if (l + 1 == levels_.size()) return;
  const Level& coarse = levels_[l + 1];
  for (std::size_t u = 0; u < n; ++u) {
    const Index3& c = level.cellOfUnknown[u];
    const std::array<std::array<int, 2>, 3> p{parents(c[0]), parents(c[1]), parents(c[2])};
    double total = 0.0;
    for (int pk = 0; pk < 2; ++pk)
      for (int pj = 0; pj < 2; ++pj)
        for (int pi = 0; pi < 2; ++pi) {
          const int i = p[0][pi], j = p[1][pj], k = p[2][pk];
          if (!coarse.type.contains(i, j, k) || coarse.type(i, j, k) == Cell::Solid) continue;
          total += kParentWeights[pi] * kParentWeights[pj] * kParentWeights[pk];
        }
    // The own parent is liquid (a parent of a liquid child), so total ≥ (¾)³.
    level.prolongationScale[u] = 1.0 / total;
  }
}

void MultigridPreconditioner::buildCoarseLevel(const Level& fine, Level& coarse) const {
  for (int a = 0; a < 3; ++a) coarse.cells[a] = (fine.cells[a] + 1) / 2;
  const Index3 n = coarse.cells;
  coarse.type = Array3<Cell>(n, Cell::Solid);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        Cell type = Cell::Solid;
        for (int dk = 0; dk < 2; ++dk)
          for (int dj = 0; dj < 2; ++dj)
            for (int di = 0; di < 2; ++di)
              if (fine.type.contains(2 * i + di, 2 * j + dj, 2 * k + dk))
                type = std::max(type, fine.type(2 * i + di, 2 * j + dj, 2 * k + dk));
        coarse.type(i, j, k) = type;  // Liquid > Air > Solid
      }
  // Coarse face = mean of its 2×2 child faces, divided by 4 for the doubled spacing (1/h²).
  constexpr double kFaceAverageAndSpacing = 1.0 / 16.0;
  for (int a = 0; a < 3; ++a) {
    Index3 faces = n;
    ++faces[a];
    coarse.faceCoefficient[a] = Array3d(faces, 0.0);
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int k = 0; k < faces[2]; ++k)
      for (int j = 0; j < faces[1]; ++j)
        for (int i = 0; i < faces[0]; ++i) {
          const Index3 coarseFace{i, j, k};
          double sum = 0.0;
          for (int db = 0; db < 2; ++db)
            for (int dc = 0; dc < 2; ++dc) {
              Index3 f;
              f[a] = 2 * coarseFace[a];
              f[b] = 2 * coarseFace[b] + db;
              f[c] = 2 * coarseFace[c] + dc;
              if (fine.faceCoefficient[a].contains(f[0], f[1], f[2]))
                sum += fine.faceCoefficient[a](f[0], f[1], f[2]);
            }
          coarse.faceCoefficient[a](i, j, k) = kFaceAverageAndSpacing * sum;
        }
  }
  coarse.unknownOfCell = Array3<std::int32_t>(n, -1);
  std::int32_t count = 0;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        if (coarse.type(i, j, k) == Cell::Liquid) {
          coarse.unknownOfCell(i, j, k) = count++;
          coarse.cellOfUnknown.push_back({i, j, k});
        }
  assembleCoarseMatrix(coarse);
}

void MultigridPreconditioner::assembleCoarseMatrix(Level& coarse) {
  SevenPointMatrix& M = coarse.matrix;
  M.reset(coarse.cellOfUnknown.size());
  for (std::size_t row = 0; row < coarse.cellOfUnknown.size(); ++row) {
    const Index3 cell = coarse.cellOfUnknown[row];
    for (int a = 0; a < 3; ++a)
      for (int side : {-1, 1}) {
        Index3 face = cell, neighbour = cell;
        if (side > 0) ++face[a];
        neighbour[a] += side;
        const double coefficient = coarse.faceCoefficient[a](face[0], face[1], face[2]);
        if (coefficient <= 0.0) continue;
        if (!coarse.type.contains(neighbour[0], neighbour[1], neighbour[2])) {
          M.diagonal[row] += coefficient / kDomainFaceFraction;
        } else if (coarse.type(neighbour[0], neighbour[1], neighbour[2]) == Cell::Liquid) {
          M.diagonal[row] += coefficient;
          const std::int32_t column =
              coarse.unknownOfCell(neighbour[0], neighbour[1], neighbour[2]);
          if (side > 0) {
            M.plus[a][row] = -coefficient;
            M.plusNeighbour[a][row] = column;
          } else {
            M.minusNeighbour[a][row] = column;
          }
        } else {
          M.diagonal[row] += coefficient;  // air: p = 0 at its centre (θ = 1 on coarse levels)
        }
      }
    // A coarse cell whose liquid children are open only to each other has no coupling: give it
    // the equation x = b so that the operator stays positive definite.
    if (M.diagonal[row] <= 0.0) M.diagonal[row] = 1.0;
  }
}

double MultigridPreconditioner::fineSweepsPerApply() const {
  double work = 2 * kMultigridSmoothingSweeps + 1;
  if (levels_.empty() || levels_[0].cellOfUnknown.empty()) return work;
  const Level& fine = levels_[0];
  const double band = double(fine.boundaryColour[0].size() + fine.boundaryColour[1].size());
  return work + 2.0 * kMultigridBoundarySweeps * band / double(fine.cellOfUnknown.size());
}

PcgPreconditioner MultigridPreconditioner::forSolve(const SevenPointMatrix& fineMatrix) {
  return {[this, &fineMatrix](std::span<const double> r, std::span<double> z) {
            apply(fineMatrix, r, z);
          },
          fineSweepsPerApply()};
}

void MultigridPreconditioner::apply(const SevenPointMatrix& fineMatrix, std::span<const double> r,
                                    std::span<double> z) {
  std::fill(z.begin(), z.end(), 0.0);
  if (levels_.empty() || fineMatrix.size() == 0) return;
  levels_[0].residual.resize(fineMatrix.size());
  vCycle(0, fineMatrix, r, z);
}

void MultigridPreconditioner::vCycle(std::size_t l, const SevenPointMatrix& A,
                                     std::span<const double> b, std::span<double> x) {
  Level& level = levels_[l];
  const SevenPointMatrix& M = l == 0 ? A : level.matrix;
  std::fill(x.begin(), x.end(), 0.0);
  if (l + 1 == levels_.size()) {
    // Palindromic red, black, …, red: a symmetric approximation of A_c⁻¹.
    for (int s = 0; s < kMultigridCoarsestSweeps; ++s) {
      relaxColour(M, level.colour[0], b, x);
      relaxColour(M, level.colour[1], b, x);
    }
    relaxColour(M, level.colour[0], b, x);
    return;
  }
  for (int s = 0; s < kMultigridSmoothingSweeps; ++s) {
    relaxColour(M, level.colour[0], b, x);
    relaxColour(M, level.colour[1], b, x);
  }
  // Extra sweeps on the cut-cell band (empty above level 0): red, black after pre-smoothing,
  // black, red before post-smoothing, so the V-cycle stays palindromic.
  const int extra = kMultigridBoundarySweeps;
  for (int s = 0; s < extra; ++s) {
    relaxColour(M, level.boundaryColour[0], b, x);
    relaxColour(M, level.boundaryColour[1], b, x);
  }
  restrictResidual(l, M, b, x);
  vCycle(l + 1, A, levels_[l + 1].rhs, levels_[l + 1].solution);
  prolongCorrection(l, M, x);
  for (int s = 0; s < extra; ++s) {
    relaxColour(M, level.boundaryColour[1], b, x);
    relaxColour(M, level.boundaryColour[0], b, x);
  }
  for (int s = 0; s < kMultigridSmoothingSweeps; ++s) {
    relaxColour(M, level.colour[1], b, x);
    relaxColour(M, level.colour[0], b, x);
  }
}

void MultigridPreconditioner::restrictResidual(std::size_t l, const SevenPointMatrix& M,
                                               std::span<const double> b,
                                               std::span<const double> x) {
  Level& level = levels_[l];
  std::vector<double>& residual = level.residual;
  forEachBlock(M.size(), kUnknownBlock, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n)
      residual[n] = b[n] - M.diagonal[n] * x[n] - offDiagonalProduct(M, n, x);
  });

  // Restriction Pᵀ/8: each coarse unknown gathers the 4³ fine cells whose parent it is.
  Level& coarse = levels_[l + 1];
  constexpr double kRestrictionScale = 1.0 / 8.0;
  constexpr std::array<double, 4> kGatherWeights{kFarParentWeight, kNearParentWeight,
                                                 kNearParentWeight, kFarParentWeight};
  forEachBlock(coarse.cellOfUnknown.size(), kUnknownBlock,
               [&](std::size_t, std::size_t begin, std::size_t end) {
                 for (std::size_t u = begin; u < end; ++u) {
                   const Index3 c = coarse.cellOfUnknown[u];
                   double sum = 0.0;
                   for (int dk = 0; dk < 4; ++dk)
                     for (int dj = 0; dj < 4; ++dj)
                       for (int di = 0; di < 4; ++di) {
                         const int i = 2 * c[0] - 1 + di, j = 2 * c[1] - 1 + dj,
                                   k = 2 * c[2] - 1 + dk;
                         if (!level.unknownOfCell.contains(i, j, k)) continue;
                         const std::int32_t f = level.unknownOfCell(i, j, k);
                         if (f < 0) continue;
                         sum += kGatherWeights[di] * kGatherWeights[dj] * kGatherWeights[dk] *
                                level.prolongationScale[f] * residual[f];
                       }
                   coarse.rhs[u] = kRestrictionScale * sum;
                 }
               });
}

void MultigridPreconditioner::prolongCorrection(std::size_t l, const SevenPointMatrix& M,
                                                std::span<double> x) {
  const Level& level = levels_[l];
  const Level& coarse = levels_[l + 1];
  // Prolongation P: trilinear from the 8 nearest coarse cells (0 in air and solid cells),
  // renormalised over the non-solid ones.
  forEachBlock(M.size(), kUnknownBlock, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t u = begin; u < end; ++u) {
      const Index3 c = level.cellOfUnknown[u];
      const std::array<std::array<int, 2>, 3> p{parents(c[0]), parents(c[1]), parents(c[2])};
      double sum = 0.0;
      for (int pk = 0; pk < 2; ++pk)
        for (int pj = 0; pj < 2; ++pj)
          for (int pi = 0; pi < 2; ++pi) {
            const int i = p[0][pi], j = p[1][pj], k = p[2][pk];
            if (!coarse.unknownOfCell.contains(i, j, k)) continue;
            const std::int32_t e = coarse.unknownOfCell(i, j, k);
            if (e < 0) continue;
            sum +=
                kParentWeights[pi] * kParentWeights[pj] * kParentWeights[pk] * coarse.solution[e];
          }
      x[u] += level.prolongationScale[u] * sum;
    }
  });
}

}  // namespace fluidsound::sim
