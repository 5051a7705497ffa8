// tools/simulate_report.cpp — see simulate_report.h.
#include "tools/simulate_report.h"

#include <nlohmann/json.hpp>
#include <vector>

namespace fluidsound::tools {

namespace {

/// report.json's `results.frames`: one object per frame made (docs/cli.md).
nlohmann::ordered_json framesJson(const std::vector<sim::FrameRecord>& records) {
  nlohmann::ordered_json frames = nlohmann::ordered_json::array();
  for (const sim::FrameRecord& r : records) {
    const sim::FrameStats& s = r.fluid;
    frames.push_back({{"frame", r.frame},
                      {"time", r.time},
                      {"substeps", s.substeps},
                      {"cg_iterations", s.pressureIterations},
                      {"cg_residual", s.pressureResidual},
                      {"cg_converged", s.pressureConverged},
                      {"particles", r.particles},
                      {"particles_deleted", s.particlesDeleted},
                      {"particles_emitted", s.particlesEmitted},
                      {"particles_reseeded", s.particlesReseeded},
                      {"particles_thinned", s.particlesThinned},
                      {"density_cg_iterations", s.densityIterations},
                      {"max_density_excess", s.maxDensityExcess},
                      {"liquid_volume", s.liquidVolume},
                      {"max_divergence", s.maxDivergence},
                      {"max_speed", s.maxSpeed},
                      {"bubbles_alive", r.bubblesAlive},
                      {"bubbles_total", r.bubblesTotal},
                      {"seconds", r.simulationSeconds + r.observerSeconds}});
  }
  return frames;
}

}  // namespace

void addSimulationResults(RunReport& report, const SimulateOptions& o, const sim::Scene& scene,
                          const sim::SimulationResult& result) {
  report.setting("scene", o.scene);
  report.setting("output", o.output);
  report.setting("cells", static_cast<double>(result.grid.cells[0]) * result.grid.cells[1] *
                              result.grid.cells[2]);
  report.setting("cell_size", result.grid.cellSize);
  report.setting("fps", scene.time.fps);
  report.setting("cfl", scene.time.cfl);
  report.setting("seed", static_cast<double>(scene.seed));
  report.resultJson("frames", framesJson(result.frames).dump());
  report.result("bubbles", static_cast<double>(result.bubbles.size()));
}

}  // namespace fluidsound::tools
