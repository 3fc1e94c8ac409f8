#include "adaptive_loop.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "marking.hpp"
#include "common/fem/bisection.hpp"
#include "common/fem/errors.hpp"
#include "common/linalg/memory_estimate.hpp"
#include "common/timing/stopwatch.hpp"

namespace chapter10 {

namespace {

void measure_meshes(StepRecord& r, const mortar::TwoBodies& bodies) {
  r.h_min = std::numeric_limits<double>::infinity();
  double area = 0;
  for (int l = 0; l < 2; ++l) {
    const mortar::Mesh& m = bodies.body(l).mesh;
    r.triangles[l] = static_cast<int>(m.triangles.size());
    for (int t = 0; t < r.triangles[l]; ++t) area += m.area(t);
    for (const auto& t : m.triangles)
      for (int k = 0; k < 3; ++k) {
        const double e = (m.nodes[t[k]] - m.nodes[t[(k + 1) % 3]]).norm();
        r.h_min = std::min(r.h_min, e);
      }
  }
  r.h_mean = std::sqrt(area / (r.triangles[0] + r.triangles[1]));
}

// The error against the exact solution (not timed: a measurement, not part of the method).
void measure_error(StepRecord& r, const Scene& scene, const ContactStep& s) {
  const mortar::ExactContact* exact = scene.exact();
  if (exact == nullptr) {
    r.err_energy = r.rel_err_energy = r.effectivity = r.rel_err_by_energy = std::nan("");
    return;
  }
  mortar::ErrorNorms norms;
  for (int l = 0; l < 2; ++l)
    norms += mortar::error_norms(s.bodies.body(l).mesh, s.bodies.body(l).material, s.bodies.part(s.u, l),
                                 exact->exact(l));
  r.err_energy = std::sqrt(norms.error.energy);
  r.rel_err_energy = norms.relative_energy();
  const double W = 0.5 * norms.exact.energy;
  r.rel_err_by_energy = std::sqrt(std::fabs(r.strain_energy - W) / W);
  r.effectivity = r.estimator / r.err_energy;
}

// SOLVE and ESTIMATE on the meshes as they are: the record's solve and estimate columns.
StepRecord solve_and_estimate(const Scene& scene, const mortar::Mesh& m1, const mortar::Mesh& m2,
                              const LoopOptions& o, const NestedStart* start, std::unique_ptr<ContactStep>& solved,
                              mortar::ContactEstimate& estimate) {
  StepRecord r;
  solved = std::make_unique<ContactStep>(solve_contact_step(scene, m1, m2, o.nonmortar, start));
  const ContactStep& s = *solved;
  r.solve_s = s.solve_s;
  const mortar::Stopwatch clock;
  estimate = mortar::estimate_contact_error(s.bodies, s.u, s.gamma, s.constraints, s.lambda, scene.estimator_data());
  r.strain_energy = strain_energy(s);  // ||u_h||, which the stopping test divides by
  r.estimate_s = clock.seconds();
  r.dofs = s.bodies.num_dofs();
  r.newton_steps = s.newton_steps;
  r.active_rows = s.active_rows;
  r.estimator = estimate.total();
  r.term2 = estimate.term2;
  r.rel_estimator = r.estimator / std::sqrt(2 * r.strain_energy);
  r.total_force = mortar::total_contact_force(s.gamma, s.constraints, s.lambda);
  measure_meshes(r, s.bodies);
  measure_error(r, scene, s);
  return r;
}

void print_step(const char* kind, const StepRecord& r) {
  char error[96] = "err_energy: later, against the reference";
  if (std::isfinite(r.err_energy))
    std::snprintf(error, sizeof error, "err_energy=%.4e (%.3f%%)  effectivity=%.3f", r.err_energy,
                  100 * r.rel_err_energy, r.effectivity);
  std::printf("%s %2d  dofs=%8d  estimator=%.4e  %s  newton=%d  time_s=%.3f\n", kind, r.step, r.dofs, r.estimator,
              error, r.newton_steps, r.time_s);
  std::fflush(stdout);
}

// The memory of a solve of `dofs` unknowns must fit before it starts (status 2 otherwise).
void check_memory(double dofs) {
  char part[96];
  std::snprintf(part, sizeof part, "the next solve (%.3g dofs)", dofs);
  const std::string shortfall =
      mortar::memory_shortfall({{part, dofs * mortar::bytes_per_dof_single_solve}}, mortar::machine_memory(),
                               "raise --target or lower --max-dofs");
  if (!shortfall.empty()) throw MemoryGuard("the next refinement is refused before its solve: " + shortfall);
}

// MARK over both bodies together; a body that is not to be refined gets no marks.
std::array<std::vector<bool>, 2> mark(const mortar::ContactEstimate& e, const LoopOptions& o) {
  std::vector<double> all;
  for (int l = 0; l < 2; ++l)
    for (double v : e.indicator2[l]) all.push_back(o.refine_body[l] ? v : 0.0);
  const std::vector<bool> marked = doerfler_marking(all, o.theta);
  std::array<std::vector<bool>, 2> split;
  split[0].assign(marked.begin(), marked.begin() + e.indicator2[0].size());
  split[1].assign(marked.begin() + e.indicator2[0].size(), marked.end());
  return split;
}

}  // namespace

LoopResult run_adaptive_loop(const Scene& scene, const LoopOptions& o) {
  LoopResult result;
  std::array<mortar::BisectionMesh, 2> meshes{mortar::BisectionMesh(scene.first_mesh(0)),
                                              mortar::BisectionMesh(scene.first_mesh(1))};
  std::optional<NestedStart> start;
  double elapsed = 0;
  for (int step = 0;; ++step) {
    // SOLVE, ESTIMATE
    mortar::ContactEstimate estimate;
    StepRecord r = solve_and_estimate(scene, meshes[0].mesh(), meshes[1].mesh(), o,
                                      start && o.nested ? &*start : nullptr, result.last, estimate);
    r.step = step;
    r.min_angle_deg = std::min(meshes[0].min_angle_degrees(), meshes[1].min_angle_degrees());
    elapsed += r.solve_s + r.estimate_s;
    if (std::find(o.snapshot_steps.begin(), o.snapshot_steps.end(), step) != o.snapshot_steps.end())
      result.snapshots.push_back({step, {meshes[0].mesh(), meshes[1].mesh()}, estimate.indicator2});
    const bool last = r.rel_estimator <= o.target || step + 1 >= o.max_steps;
    if (last) {
      r.time_s = elapsed;
      result.steps.push_back(r);
      print_step("adaptive step", r);
      result.stopped_because = r.rel_estimator <= o.target ? "the estimated error reached the target" : "the step limit";
      break;
    }
    // MARK, REFINE, and the displacement carried to the new meshes
    const mortar::Stopwatch clock;
    const auto marked = mark(estimate, o);
    r.marked = static_cast<int>(std::count(marked[0].begin(), marked[0].end(), true) +
                                std::count(marked[1].begin(), marked[1].end(), true));
    for (int l = 0; l < 2; ++l) meshes[l].refine(marked[l]);
    Eigen::VectorXd u_next(meshes[0].mesh().num_dofs() + meshes[1].mesh().num_dofs());
    const ContactStep& solved = *result.last;
    u_next << meshes[0].prolong(solved.bodies.part(solved.u, 0), 2), meshes[1].prolong(solved.bodies.part(solved.u, 1), 2);
    start = nested_start(solved, std::move(u_next));
    r.refine_s = clock.seconds();
    elapsed += r.refine_s;
    r.time_s = elapsed;
    result.steps.push_back(r);
    print_step("adaptive step", r);
    const double next_dofs = static_cast<double>(start->u.size());
    if (next_dofs > o.max_dofs) {
      result.stopped_because = "the next step would pass --max-dofs";
      break;
    }
    check_memory(next_dofs);
  }
  return result;
}

LoopResult run_uniform_levels(const Scene& scene, const LoopOptions& o, double target) {
  LoopResult result;
  std::optional<NestedStart> start;
  std::array<mortar::Mesh, 2> mesh{mortar::rectangle_mesh(scene.first_mesh(0)), mortar::rectangle_mesh(scene.first_mesh(1))};
  for (int level = 0;; ++level) {
    mortar::ContactEstimate estimate;
    StepRecord r =
        solve_and_estimate(scene, mesh[0], mesh[1], o, start && o.nested ? &*start : nullptr, result.last, estimate);
    r.step = level;
    r.min_angle_deg = std::min(mortar::min_angle_degrees(mesh[0]), mortar::min_angle_degrees(mesh[1]));
    r.time_s = r.solve_s;  // the level alone: uniform refinement needs no coarser level
    result.steps.push_back(r);
    print_step("uniform level", r);
    const double error = scene.exact() != nullptr ? r.rel_err_energy : r.rel_estimator;
    if (error <= target) {
      result.stopped_because = "the target error";
      break;
    }
    const double next_dofs = 4.0 * r.dofs;
    if (next_dofs > o.max_dofs) {
      result.stopped_because = "the next level would pass --max-dofs";
      break;
    }
    check_memory(next_dofs);
    // the next level, started from this one interpolated (without jitter: cells are found by
    // their coordinates), or from its multipliers alone
    const std::array<mortar::RectangleSpec, 2> coarse{scene.first_mesh(0, level), scene.first_mesh(1, level)};
    mesh = {mortar::rectangle_mesh(scene.first_mesh(0, level + 1)), mortar::rectangle_mesh(scene.first_mesh(1, level + 1))};
    const ContactStep& solved = *result.last;
    if (coarse[0].jitter == 0 && coarse[1].jitter == 0) {
      Eigen::VectorXd u_next(mesh[0].num_dofs() + mesh[1].num_dofs());
      u_next << mortar::interpolate_from_rectangle(coarse[0], solved.bodies.part(solved.u, 0), mesh[0]),
          mortar::interpolate_from_rectangle(coarse[1], solved.bodies.part(solved.u, 1), mesh[1]);
      start = nested_start(solved, std::move(u_next));
    } else {
      start = nested_start(solved, {});
    }
  }
  return result;
}

}  // namespace chapter10
