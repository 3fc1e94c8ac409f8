// Chapter 8's options and what each level is measured against: the manufactured scene's exact
// solution (energy and L2 errors, both multipliers in L2, the stick-slip point), and
// Cattaneo-Mindlin (the stick half-width and the shear, at every load step; on cattaneo-exact
// also u and both multipliers against the exact field).
#pragma once

#include <string>
#include <vector>

#include "cattaneo_mindlin.hpp"
#include "common/study/bilateral_study.hpp"
#include "common/study/convergence_study.hpp"
#include "frictional_level.hpp"

namespace chapter08 {

struct Options : mortar::TwoBodyOptions {
  std::string scene = "manufactured";
  std::string law = "coulomb";
  std::string solver = "newton";
  std::string start = "nested";
  double friction = 0.3;
  double R = 1, delta = 0.02, q_ratio = 0.6;
  int load_steps = 10;
  int n0 = 8, levels = 7;  // cattaneo: 16 and 5 unless given
  int threads = mortar::default_solver_threads();
  bool no_compare = false;
  std::string out = "results/ch08_friction";
  bool quick = false, no_plot = false;
};

void parse_options(mortar::OptionParser& parser, Options& o, int argc, char** argv);

SceneParameters scene_parameters(const Options& o);
LevelSetup level_setup(const Options& o, int level);
mortar::FrictionLaw law_of(const Options& o);
// 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2
double e_star(const Options& o);

// The manufactured scene: a row of convergence.csv.
mortar::Row manufactured_row(const FrictionalLevel& r, const mortar::ManufacturedFriction& exact);
// x_c of the stick zone (0, x_c): the midpoint between its last stick node and the next node.
double stick_slip_point(const FrictionalLevel& r);

// One load step against Cattaneo-Mindlin at the step's own P and Q.
struct CattaneoStep {
  int step = 0;
  double P = 0, Q = 0, q_ratio = 0;       // computed forces, Q / (F P)
  double c = 0, c_h = 0;                  // stick half-widths, exact and computed
  double shear_rel_error_l2 = 0;          // ||lambda_t,h - q|| / ||q||
  double pressure_change_rel_l2 = 0;      // ||p_h(Q) - p_h(0)|| / ||p_h(0)||
  double hertz_pressure_rel_error_l2 = 0;  // ||p_h - p_Hertz|| / ||p_Hertz||
  int newton_steps = 0, lu_steps = 0, stick_nodes = 0, slip_nodes = 0;
  double limit_ratio = 0;                 // the load step's time over the level's physical limit
};
// At each step's computed P and Q (cattaneo), or at the exact field's (cattaneo-exact).
std::vector<CattaneoStep> compare_with_cattaneo(const Options& o, const FrictionalLevel& r, const Scene& scene);
mortar::Row cattaneo_row(const FrictionalLevel& r, const CattaneoStep& last);
// cattaneo-exact: u, lambda_n and lambda_t of the last step against its exact field, and the
// stick half-width.
mortar::Row cattaneo_exact_row(const FrictionalLevel& r, const mortar::CattaneoHalfPlanes& exact, const CattaneoStep& last);
void write_cattaneo_csv(const std::string& path, const std::vector<CattaneoStep>& steps);
// The residual and the stick and slip counts after every Newton step of every load step.
void write_newton_csv(const std::string& path, const FrictionalLevel& r);

}  // namespace chapter08
