// The adaptive loop SOLVE -> ESTIMATE -> MARK -> REFINE, each body on its own mesh, and the
// uniform refinement it is measured against, with the same solver.
//  - SOLVE: contact_step.hpp (chapter 6's dual mortar and semismooth Newton), started from the
//    previous step's solution (nested iteration);
//  - ESTIMATE: the residual estimator of common/contact/contact_estimator.hpp, one indicator
//    eta_T per triangle of either body;
//  - MARK: Doerfler's bulk criterion over the triangles of both bodies together (marking.hpp);
//  - REFINE: newest-vertex bisection of each body (common/fem/bisection.hpp), and the
//    displacement prolonged to the new meshes for the next start.
// Every step's wall time counts all four; measuring the error against the exact solution is not
// part of the method and is not counted.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "contact_step.hpp"
#include "common/contact/contact_estimator.hpp"

namespace chapter10 {

struct LoopOptions {
  double theta = 0.5;           // Doerfler's share
  int max_steps = 40;
  double target = 0.025;        // stop once the relative estimated error eta / ||u_h|| is below
  double max_dofs = 4e6;        // stop before a step with more unknowns
  int nonmortar = 0;            // body index
  bool nested = true;           // start each solve from the previous step
  std::array<bool, 2> refine_body{true, true};  // false: that body keeps its first mesh
  std::vector<int> snapshot_steps{0, 3, 6, 12};
};

struct StepRecord {
  int step = 0, dofs = 0, marked = 0, newton_steps = 0, active_rows = 0;
  std::array<int, 2> triangles{};
  double min_angle_deg = 0, h_min = 0;
  double h_mean = 0;  // (area / triangles)^(1/2) over both bodies: N^(-1/2) up to a constant
  double err_energy = 0, rel_err_energy = 0;  // against the exact solution (NaN without one)
  // (|W_h - W| / W)^(1/2) with W = 1/2 ||u||^2 the exact strain energy: the punch's measure
  // (study.hpp), checked where the exact error is known
  double rel_err_by_energy = 0;
  double estimator = 0, rel_estimator = 0, effectivity = 0;
  std::array<double, mortar::estimator_terms> term2{};
  double solve_s = 0, estimate_s = 0, refine_s = 0;
  double time_s = 0;        // adaptive: every step so far; uniform: this level's solve alone
  double strain_energy = 0;  // 1/2 u.K u
  double total_force = 0;
};

struct MeshSnapshot {
  int step = 0;
  std::array<mortar::Mesh, 2> mesh;
  std::array<std::vector<double>, 2> eta2;  // the indicators of that step
};

struct LoopResult {
  std::vector<StepRecord> steps;
  std::vector<MeshSnapshot> snapshots;
  std::unique_ptr<ContactStep> last;          // the last solve, for its pressure and pictures
  std::string stopped_because;
};

// Thrown before a step the machine's memory cannot hold (main turns it into status 2).
struct MemoryGuard : std::runtime_error {
  using std::runtime_error::runtime_error;
};

LoopResult run_adaptive_loop(const Scene& scene, const LoopOptions& o);
// Uniform refinement: the first meshes with n0 2^k cells along Gamma_c, k = 0, 1, ..., until the
// relative energy error (or, without an exact solution, the relative estimator) is below
// `target` or the next level would pass max_dofs.
LoopResult run_uniform_levels(const Scene& scene, const LoopOptions& o, double target);

}  // namespace chapter10
