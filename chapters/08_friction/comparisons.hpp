// What chapter 8 compares beside its convergence study:
//  - solvers (manufactured scene, Coulomb): the semismooth Newton method on all conditions
//    against the fixed point on Tresca thresholds, over F and over h;
//  - load paths (cattaneo scene): Q in one step instead of N, and P and Q raised together
//    (Mindlin's proportional loading) instead of P first: Coulomb's answer depends on the path.
#pragma once

#include <string>
#include <vector>

#include "study.hpp"

namespace chapter08 {

struct SolverRun {
  double friction = 0, h1 = 0;
  int level = 0, dofs = 0;
  int newton_steps = 0, newton_lu_steps = 0;
  int fixed_point_outer = 0, fixed_point_steps = 0;
  double newton_s = 0, fixed_point_s = 0, limit_s = 0;
  double difference = 0;  // ||u_newton - u_fixed|| / ||u_newton||
};
std::vector<SolverRun> compare_solvers(const Options& o, const std::vector<double>& frictions, int finest_level);
void write_solver_runs(const std::string& path, const std::vector<SolverRun>& runs);

struct PathRun {
  std::string path;  // "P then Q in N steps", ... (no comma: a CSV field)
  int steps = 0, newton_steps = 0;
  double q_ratio = 0, c_h = 0, contact_half_width = 0;
  double shear_difference = 0;  // ||lambda_t - lambda_t of the first path|| / ||lambda_t of the first||
};
// The paths on the level `level` of o; the first is the chapter's own (P, then Q in o.load_steps).
std::vector<PathRun> compare_paths(const Options& o, int level);
void write_path_runs(const std::string& path, const std::vector<PathRun>& runs);

}  // namespace chapter08
