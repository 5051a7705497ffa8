// acoustics/modal/modal_analysis.cpp — see modal_analysis.h.
#include "acoustics/modal/modal_analysis.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "acoustics/modal/elastic_matrices.h"
#include "acoustics/modal/modal_solve.h"

namespace fluidsound::acoustics {
namespace {

/// Rigid motions of a free body: three translations and three rotations.
constexpr int kRigidModesOfFreeBody = 6;

/// The shift σ = −(2π·20 Hz)² [rad²/s²]: below the spectrum, so the modes nearest it are the
/// lowest and K − σM is positive definite for a free body too; at the bottom of hearing, so it
/// is small beside every audible ω² (good Lanczos separation) yet ~10⁵ times the rounding noise
/// ε·λ_max of the rigid modes for voxels down to 0.1 mm, so the Cholesky factor stays accurate.
constexpr double kShiftFrequency = 20.0;  // [Hz]

/// Elastic pairs asked for first, and the margin on the next request's prediction (analyseModes).
constexpr int kFirstRequest = 24;
constexpr double kModeCountMargin = 1.25;

double frequencyOf(double eigenvalue) {
  return std::copysign(std::sqrt(std::abs(eigenvalue)), eigenvalue) / (2.0 * std::numbers::pi);
}

std::vector<int> clampedNodes(const HexMesh& mesh, const ModalSettings& settings) {
  std::vector<int> nodes;
  if (!settings.clamped) return nodes;
  for (std::size_t n = 0; n < mesh.positions.size(); ++n)
    if (settings.clamped(mesh.positions[n])) nodes.push_back(static_cast<int>(n));
  return nodes;
}

}  // namespace

ModalModel analyseModes(const VoxelSolid& solid, const SolidMaterial& material,
                        const ModalSettings& settings) {
  if (solid.cells.empty()) throw std::invalid_argument("analyseModes: the solid has no cells");
  if (const auto problem = solidMaterialProblem(material))
    throw std::invalid_argument("analyseModes: material: " + std::string(*problem));
  if (!(solid.voxelSize > 0.0))
    throw std::invalid_argument("analyseModes: voxelSize must be > 0 (metres)");
  if (settings.maxModes < 1) throw std::invalid_argument("analyseModes: maxModes must be >= 1");
  if (!(settings.rigidFrequency >= 0.0 && settings.rigidFrequency < settings.maxFrequency))
    throw std::invalid_argument("analyseModes: need 0 <= rigidFrequency < maxFrequency (Hz)");

  const HexMesh mesh = hexMesh(solid);
  const std::vector<int> clamped = clampedNodes(mesh, settings);
  const ElasticMatrices matrices = assembleElasticMatrices(mesh, material, clamped);
  const int dofs = static_cast<int>(matrices.nodeDofs.size());
  const double shift = -std::pow(2.0 * std::numbers::pi * kShiftFrequency, 2);
  const double rigidEigenvalue = std::pow(2.0 * std::numbers::pi * settings.rigidFrequency, 2);

  // A few pairs first, then as many as the modes found so far predict below maxFrequency, until
  // the highest passes it or there are maxModes elastic ones: a compact body has few audible
  // modes, and every pair asked for costs Lanczos vectors (measured: a 10 k-unknown steel block
  // has 23 below 20 kHz; asking for 206 took 11.7 s, 1.8 s this way). The prediction is a thin
  // plate's mode count, N(f) ∝ f (its bending modes have a constant density; Cremer & Heckl):
  // more than a bar's (∝ √f), fewer than a solid's at high frequency (∝ f³), for which the
  // requests at least double. The rigid modes come on top (6 for a free body; more for parts
  // joined only along an edge or at a corner, or separate pieces).
  const LowestEigenpairsSolver solver(matrices.stiffness, matrices.mass, shift);
  const int rigidExpected = clamped.empty() ? kRigidModesOfFreeBody : 0;
  int requested = std::min({dofs, settings.maxModes + rigidExpected, kFirstRequest + rigidExpected});
  GeneralisedEigenpairs pairs;
  for (;;) {
    pairs = solver.lowest(requested);
    const auto rigid = std::count_if(pairs.eigenvalues.begin(), pairs.eigenvalues.end(),
                                     [&](double value) { return value < rigidEigenvalue; });
    const int enough = std::min<int>(dofs, settings.maxModes + static_cast<int>(rigid));
    const bool pastCut = pairs.eigenvalues.size() > 0 &&
                         frequencyOf(pairs.eigenvalues.maxCoeff()) > settings.maxFrequency;
    if (enough <= requested || pastCut || requested >= dofs) break;
    const double elastic = static_cast<double>(pairs.eigenvalues.size() - rigid);
    const double highest = frequencyOf(pairs.eigenvalues.maxCoeff());
    const double predicted =
        highest > 0.0 ? kModeCountMargin * elastic * (settings.maxFrequency / highest) + static_cast<double>(rigid)
                      : 0.0;
    requested = std::min<int>(enough, std::max<double>(2.0 * requested, std::ceil(std::min(predicted, 1e9))));
  }

  ModalModel model;
  model.dofCount = dofs;
  model.operations = pairs.operations;
  std::vector<Eigen::Index> kept;
  for (Eigen::Index j = 0; j < pairs.eigenvalues.size(); ++j) {
    const double eigenvalue = pairs.eigenvalues[j];
    if (eigenvalue < rigidEigenvalue) {
      model.rigidFrequencies.push_back(frequencyOf(eigenvalue));
      continue;
    }
    if (frequencyOf(eigenvalue) > settings.maxFrequency ||
        static_cast<int>(kept.size()) == settings.maxModes)
      break;
    kept.push_back(j);
  }
  model.rigidModesDropped = static_cast<int>(model.rigidFrequencies.size());
  for (const Eigen::Index j : kept) {
    const double angularFrequency = std::sqrt(pairs.eigenvalues[j]);
    const double decay = modalDecayRate(material, angularFrequency);
    model.frequency.push_back(angularFrequency / (2.0 * std::numbers::pi));
    model.decayRate.push_back(decay);
    model.dampedFrequency.push_back(
        decay < angularFrequency ? std::sqrt(angularFrequency * angularFrequency - decay * decay) /
                                       (2.0 * std::numbers::pi)
                                 : 0.0);
  }

  setModelSurface(model, solid, mesh);
  std::vector<int> keptDof(3 * mesh.positions.size(), -1);
  for (int d = 0; d < dofs; ++d) keptDof[static_cast<std::size_t>(matrices.nodeDofs[d])] = d;
  model.surfaceShapes.setZero(3 * static_cast<Eigen::Index>(model.surfaceNodes.size()),
                              static_cast<Eigen::Index>(kept.size()));
  for (std::size_t s = 0; s < model.surfaceNodes.size(); ++s)
    for (int c = 0; c < 3; ++c) {
      const int dof = keptDof[3 * static_cast<std::size_t>(model.surfaceNodes[s]) + c];
      if (dof < 0) continue;  // clamped: stays zero
      for (std::size_t m = 0; m < kept.size(); ++m)
        model.surfaceShapes(3 * static_cast<Eigen::Index>(s) + c, static_cast<Eigen::Index>(m)) =
            static_cast<float>(pairs.eigenvectors(dof, kept[m]));
    }
  return model;
}

void setModelSurface(ModalModel& model, const VoxelSolid& solid, const HexMesh& mesh) {
  // The faces once; the nodes are their corners (as surfaceNodes gives them).
  model.surfaceFaces = surfaceFaces(solid, mesh);
  model.surfaceNodes.clear();
  for (const SurfaceFace& face : model.surfaceFaces)
    model.surfaceNodes.insert(model.surfaceNodes.end(), face.nodes.begin(), face.nodes.end());
  std::sort(model.surfaceNodes.begin(), model.surfaceNodes.end());
  model.surfaceNodes.erase(std::unique(model.surfaceNodes.begin(), model.surfaceNodes.end()), model.surfaceNodes.end());
  model.surfacePositions.clear();
  for (const int node : model.surfaceNodes) model.surfacePositions.push_back(mesh.positions[node]);
  model.voxelSize = solid.voxelSize;
  for (SurfaceFace& face : model.surfaceFaces)
    for (int& node : face.nodes)
      node = static_cast<int>(std::lower_bound(model.surfaceNodes.begin(), model.surfaceNodes.end(), node) -
                              model.surfaceNodes.begin());
}

std::array<double, 3> surfaceMotionShares(const ModalModel& model, std::size_t mode) {
  std::array<double, 3> sum{};
  const auto column = static_cast<Eigen::Index>(mode);
  for (Eigen::Index row = 0; row < model.surfaceShapes.rows(); ++row) {
    const double value = model.surfaceShapes(row, column);
    sum[static_cast<std::size_t>(row % 3)] += value * value;
  }
  const double total = sum[0] + sum[1] + sum[2];
  if (total > 0.0)
    for (double& share : sum) share /= total;
  return sum;
}

}  // namespace fluidsound::acoustics
