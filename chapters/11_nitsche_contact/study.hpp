// Chapter 11's studies: the head-to-head table (every method on every level) and the sweep of
// Nitsche's gamma0 for theta = 1, 0, -1 on one level.
#pragma once

#include <string>
#include <vector>

#include "common/study/convergence_study.hpp"
#include "level.hpp"

namespace chapter11 {

// The methods in the table's order: Nitsche, penalty with gamma = gamma0 E / h, penalty with
// gamma fixed, the standard mortar basis, the dual one.
const std::vector<std::string>& method_names();

// Every method on one level, and its row of convergence.csv: h, h1, h2, dofs, time_s (Nitsche's),
// limit_s, then one column group per method (err_energy_<m>, err_l2_<m>, err_pressure_<m>,
// half_width_error_m_<m>, newton_steps_<m>, time_s_<m>).
// coarser: the level below, already solved (the nested start of Nitsche and penalty), or null.
void solve_level(const Options& o, const Scene& scene, Level& level, const Level* coarser);
mortar::Row level_row(const Level& level);

// One line of gamma_sweep.csv.
struct SweepPoint {
  double theta = 0, gamma0 = 0;
  MethodResult result;
};
// gamma0 = 1e-3 .. 1e3 (three values a decade) and theta = 1, 0, -1, plus penalty, on one level.
std::vector<SweepPoint> gamma_sweep(const Options& o, const Scene& scene, const Level& level);
void write_sweep(const std::string& path, const std::vector<SweepPoint>& points);

// One line of stiffness_sweep.csv: E1 / E2 and whose traction Nitsche reads (or a mortar
// reference, traction "-"), on level o.sweep_level.
struct StiffnessPoint {
  double ratio = 1;
  std::string traction;
  MethodResult result;
};
// E1 / E2 = 1e-6, 1e-4, ..., 1e6 (E2 as given), Nitsche with body 1's, body 2's and the harmonic
// traction, and both mortar references (the softer body non-mortar).
std::vector<StiffnessPoint> stiffness_sweep(const Options& o);
void write_stiffness_sweep(const std::string& path, const std::vector<StiffnessPoint>& points);

}  // namespace chapter11
