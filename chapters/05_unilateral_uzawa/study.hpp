// The convergence study of chapter 5: one table row per level for the chosen matching and
// solver, and a comparison of every solver on both matchings at every level.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/study/bilateral_study.hpp"
#include "common/study/convergence_study.hpp"
#include "common/study/options.hpp"
#include "hertz.hpp"
#include "unilateral_level.hpp"

namespace chapter05 {

struct Options : mortar::TwoBodyOptions {
  Options() {  // chapter 5's bodies: one material, square blocks
    E2 = 1;
    nu2 = 0.3;
    H1 = H2 = 1;
  }
  std::string scene = "hertz";
  std::string matching = "integral";
  std::string solver = "pdas";
  std::string acceleration = "nesterov";
  std::string uzawa_step = "both-ends";
  double rho = 0, tol = 1e-8;
  int n0 = 12, levels = 5;  // signorini: 8 and 6, hertz-exact: 4 and 7 unless given (parse_options)
  int threads = mortar::default_solver_threads();
  double R = 1, delta = 0.02;
  bool no_compare = false, compare = true;
  std::string out = "results/ch05_unilateral_uzawa";
  bool quick = false, no_plot = false;
  bool profile = false;  // print where the finest level's time goes
};

void parse_options(mortar::OptionParser& parser, Options& o, int argc, char** argv);

UnilateralSetup level_setup(const Options& o, int level, mortar::Matching matching,
                            const mortar::ContactSolverOptions& solver);
mortar::ContactSolverOptions solver_options(const Options& o, const std::string& solver,
                                            bool accelerate);

struct HertzReference;  // hertz_reference.hpp

// What a level is measured against: (hertz) a finite-body reference on graded meshes, with
// half-space Hertz compared with that reference for the model error; the exact solution of
// the bilateral scene; or (partial) a reference solution two levels finer, stated as such.
struct Reference {
  std::string kind;  // "hertz", "exact" or "finer mesh"
  std::unique_ptr<UnilateralLevel> finer;
  std::shared_ptr<const HertzReference> hertz;
};
Reference make_reference(const Options& o, const mortar::ExactContact& exact);

mortar::Row level_row(const Options& o, const UnilateralLevel& r, const Reference& ref,
                      const mortar::ExactContact& exact);
Hertz hertz_for(const Options& o, const UnilateralLevel& r);
// Signorini scene: x*_h, the right edge of the discrete contact zone (the midpoint between its
// last active node and the next node), and |x*_h - x*|; NaN when nothing touches.
double computed_contact_point(const UnilateralLevel& r);
double contact_point_error(const UnilateralLevel& r, double L);
// hertz-exact scene: |a_h - a| in metres, a_h = ContactZone::half_width (0 when nothing touches)
double half_width_error(const UnilateralLevel& r, double L);

// One line of solvers.csv: a (matching, solver) pair on one level.
struct SolverRun {
  std::string matching, solver;
  int level = 0;
  double h = 0, time_s = 0, limit_s = 0, error = 0, total_force = 0;
  int iterations = 0, columns = 0;
};
std::vector<SolverRun> compare_solvers(const Options& o, const mortar::ExactContact& exact,
                                       const Reference& ref,
                                       std::vector<std::unique_ptr<UnilateralLevel>>& finest_by_matching);
void write_solver_runs(const std::string& path, const std::vector<SolverRun>& runs);

}  // namespace chapter05
