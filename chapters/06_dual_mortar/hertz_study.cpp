#include "hertz_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>

#include "common/contact/constraints.hpp"
#include "common/contact/contact_solvers.hpp"
#include "common/contact/dual_condensation.hpp"
#include "common/contact/bilateral_contact.hpp"

namespace chapter06 {

std::vector<mortar::MemoryPart> hertz_memory_parts(const mortar::BilateralStudyOptions& o) {
  const double n1 = std::ldexp(static_cast<double>(o.n0), o.levels - 1);
  const double n2 = std::max(2.0, std::round(n1 / o.h_ratio));
  const double dofs = 2 * (n1 + 1) * (n1 + 1) + 2 * (n2 + 1) * (n2 + 1);
  const double m = (o.nonmortar == 1 ? n1 : n2) - 1, t = (o.nonmortar == 1 ? n2 : n1) + 1;
  char sparse[96], dense[128];
  std::snprintf(sparse, sizeof sparse, "the Hertz part's finest level (%.3g dofs, square blocks)", dofs);
  std::snprintf(dense, sizeof dense, "the Hertz part's S = B K^-1 B^T on Gamma_c (%.0f multipliers, %.0f mortar nodes)",
                m, t);
  return {{sparse, dofs * mortar::bytes_per_dof_single_solve}, {dense, mortar::schur_dense_bytes(m, t)}};
}

std::string basis_name(Basis basis) { return basis == Basis::dual ? "dual" : "standard"; }

// The Hertz part is driven by the plates' displacement delta: u does not depend on the unit of
// E, and the multipliers are proportional to it. The solvers work on S = B K^-1 B^T, of order
// 1/E, whose squares leave the range of double beyond E ~ 1e+-150; so each level is solved with
// the moduli divided by the power of two nearest the larger one (an exact division), and the
// multipliers are multiplied back.
double modulus_unit(const mortar::TwoBodyOptions& b) {
  return std::exp2(std::round(std::log2(std::max(b.E1, b.E2))));
}

HertzLevel solve_hertz_level(const HertzOptions& o, int level, Basis basis, const HertzLevel* coarser) {
  const mortar::TwoBodyGeometry geometry = mortar::two_body_geometry(o.bodies, o.n0 << level, 1.0);
  const double unit = modulus_unit(o.bodies);
  const mortar::TwoBodies bodies = mortar::make_two_bodies(geometry, mortar::Material(o.bodies.E1 / unit, o.bodies.nu1),
                                                           mortar::Material(o.bodies.E2 / unit, o.bodies.nu2));
  const double L = o.bodies.L, R = o.R;
  const auto gap = [L, R](double x) { return (x - 0.5 * L) * (x - 0.5 * L) / (2 * R); };
  HertzLevel r;
  r.basis = basis;
  r.level = level;
  r.dofs = bodies.num_dofs();
  std::optional<mortar::SceneData> scene;
  mortar::ContactInterface gamma;
  mortar::Constraints constraints;
  Eigen::VectorXd lambda;
  const auto solve = [&] {
    // 1. The scene and K, as in chapter 5.
    scene = mortar::pressed_between_plates(bodies, o.delta);
    mortar::SparseMatrix K = bodies.stiffness();
    // 2. Gamma_c with the chosen basis: the hats of M_h^1 or their dual functions.
    gamma = mortar::contact_traces(bodies, o.bodies.nonmortar - 1);
    gamma.grid = mortar::merge_traces(gamma.nonmortar_trace, gamma.mortar_trace);
    gamma.space = basis == Basis::dual ? mortar::dual_end_modified_p1(gamma.nonmortar_trace)
                                       : mortar::end_modified_p1(gamma.nonmortar_trace);
    gamma.matrices = mortar::mortar_matrices(gamma.nonmortar_trace, gamma.mortar_trace, gamma.grid, gamma.space);
    // 3. B u <= G: int psi_i [u_h.n] <= int psi_i g. With the dual psi_i this is the weighted
    //    gap of Hueber and Wohlmuth: psi_i changes sign, so it tests a weighted mean of the
    //    penetration, not its value at a point or its mean against a positive weight.
    constraints = mortar::constraint_rows(bodies, gamma, mortar::integral_matching_rows(gamma),
                                          scene->prescribed_mask(bodies.num_dofs()));
    const Eigen::VectorXd G = mortar::tested_gap(gamma, constraints, gap);
    // 4. Dirichlet elimination; one stiffness matrix at a time from here on.
    mortar::ReducedSystem system = mortar::eliminate_dirichlet(K, scene->F, scene->dirichlet);
    mortar::SparseMatrix().swap(K);
    mortar::SaddlePointProblem reduced = mortar::reduce_to_free_dofs(system, constraints, G);
    mortar::SparseMatrix().swap(system.K);
    Eigen::VectorXd u;
    if (basis == Basis::dual) {
      // 5. Dual: condense (u_s from the weighted gap w), then the semismooth Newton method.
      mortar::CondensedContact condensed = mortar::condense_contact(reduced);
      mortar::SparseMatrix().swap(reduced.K);
      mortar::DualContactOptions options;
      if (coarser != nullptr && o.nested_start && !coarser->zone.empty) {
        // between the coarser level's outermost active nodes (their halfway points to the
        // inactive neighbours were tried too: 2, 2, 2, 1, 2 steps on levels 1-5 against 1, 2, 1,
        // 2, 1 from the active nodes)
        const double left = coarser->zone.left_active, right = coarser->zone.right_active;
        for (int node : constraints.row_node) {
          const double x = gamma.nonmortar_trace.x[node];
          options.initial_active.push_back(x >= left && x <= right);
        }
      }
      const mortar::DualContactSolution x = mortar::solve_dual_contact(condensed, options);
      lambda = x.lambda;
      r.iterations = x.iterations;
      r.active_sizes = x.active_sizes;
      r.active_sets.steps = x.active_history;
      r.residual = x.residual;
    } else {
      // 5. Standard: chapter 5's primal-dual active set on the multipliers, through S.
      mortar::ContactProblem problem{{}, std::move(reduced.f), {}, std::move(reduced.G)};
      problem.K.swap(reduced.K);
      problem.B.swap(reduced.B);
      const mortar::ContactSolution x = mortar::solve_contact(problem, mortar::ContactSolverOptions{});
      lambda = x.lambda;
      r.iterations = x.iterations;
      r.residual = x.residual;
      r.active_sets.steps = x.active_history;
    }
  };
  // The finest level is timed with repetitions (physical_limit.hpp); the others once each, as
  // chapter 5's comparison does: their ratios are read as a trend, not quoted.
  const mortar::Repetitions once{1, 1, 0.0};
  r.timing = mortar::time_against_limit(solve, [&] { return mortar::two_body_limit_matrix(bodies, *scene); },
                                        level + 1 == o.levels ? mortar::Repetitions{} : once);

  // 6. What the multipliers say: the coefficients at their nodes, the function they make, the
  //    total force int lambda_h = sum_i lambda_i int psi_i (the same int psi_i for both bases).
  lambda *= unit;  // back to the moduli given
  r.multipliers = static_cast<int>(lambda.size());
  r.active_sets.label = basis == Basis::dual ? "dual basis, semismooth Newton" : "standard basis, active set on S";
  for (int node : constraints.row_node) r.active_sets.x.push_back(gamma.nonmortar_trace.x[node]);
  r.h1 = gamma.nonmortar_trace.max_element_length();
  r.pressure = mortar::contact_pressure(gamma, constraints, lambda);
  r.total_force = mortar::total_contact_force(gamma, constraints, lambda);
  r.max_pressure = *std::max_element(r.pressure.value.begin(), r.pressure.value.end());
  r.zone = mortar::contact_zone(r.pressure);
  r.half_width = r.zone.half_width();
  r.function = mortar::multiplier_function(gamma, constraints, lambda);
  r.min_function = std::min(*std::min_element(r.function.left.begin(), r.function.left.end()),
                            *std::min_element(r.function.right.begin(), r.function.right.end()));
  return r;
}


HertzStudy run_hertz_study(const HertzOptions& o) {
  HertzStudy study;
  for (int level = 0; level < o.levels; ++level) {
    for (Basis basis : {Basis::standard, Basis::dual}) {
      auto& list = basis == Basis::dual ? study.dual : study.standard;
      list.push_back(solve_hertz_level(o, level, basis, list.empty() ? nullptr : &list.back()));
      HertzLevel& r = list.back();
      if (basis == Basis::dual) r.pressure_difference = mortar::relative_l2_difference(r.pressure, study.standard.back().pressure);
      std::printf("hertz level %d, %-8s  dofs=%d  total_force=%.10g  iterations=%d  time_s=%.4g  limit_s=%.4g  "
                  "ratio=%.2f\n",
                  level, basis_name(basis).c_str(), r.dofs, r.total_force, r.iterations, r.timing.time_s,
                  r.timing.limit_s, r.timing.ratio());
    }
  }
  return study;
}

void write_hertz_csv(const std::string& path, const HertzStudy& study) {
  std::ofstream out(path);
  out << "basis,level,h1,dofs,multipliers,total_force,max_pressure,half_width,iterations,residual,"
         "min_function,pressure_difference,time_s,limit_s,limit_ratio\n";
  char line[512];
  for (const auto* list : {&study.standard, &study.dual})
    for (const HertzLevel& r : *list) {
      std::snprintf(line, sizeof line, "%s,%d,%.10g,%d,%d,%.12g,%.10g,%.10g,%d,%.3g,%.6g,%.6g,%.6g,%.6g,%.4f\n",
                    basis_name(r.basis).c_str(), r.level, r.h1, r.dofs, r.multipliers, r.total_force, r.max_pressure,
                    r.half_width, r.iterations, r.residual, r.min_function, r.pressure_difference, r.timing.time_s,
                    r.timing.limit_s, r.timing.ratio());
      out << line;
    }
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace chapter06
