#include "options.hpp"

#include <algorithm>
#include <cmath>

#include "common/contact/nitsche_contact.hpp"
#include "common/linalg/memory_estimate.hpp"
#include "common/linalg/spd_solver.hpp"

namespace chapter11 {

void parse_options(mortar::OptionParser& parser, Options& o, int argc, char** argv) {
  using mortar::Range;
  parser.add_choice("scene", o.scene, {"hertz-exact"}, "contact scene (chapter 5's exact Hertz solution)");
  parser.add_double("theta", o.theta, "Nitsche's variant: 1 symmetric, 0, -1 skew-symmetric (any value in [-1, 1])",
                    Range::closed(-1, 1));
  // beyond 1e4 generalized Newton needs 30 steps and more, and fails from about 1e7 on
  parser.add_double("gamma0", o.gamma0, "Nitsche's parameter: gamma = gamma0 E / h", Range::closed(1e-6, 1e4));
  parser.add_double("penalty-gamma0", o.penalty_gamma0,
                    "penalty: gamma = gamma0 E / h, the fixed-gamma run keeping the coarsest level's value (default: --gamma0)",
                    Range::closed(1e-6, 1e4));
  parser.add_choice("traction", o.traction, {"body1", "body2", "mean", "harmonic"},
                    "whose traction p(u) Nitsche reads: body 1, body 2, their mean, or weighted by h / E (the softer body's)");
  parser.add_int("n0", o.n0, "body-1 elements along Gamma_c on the coarsest level", Range::closed(2, 1 << 14));
  parser.add_int("levels", o.levels, "refinement levels, h halving each time (rates need 3)", Range::closed(3, 10));
  mortar::add_two_body_options(parser, o);
  parser.add_double("R", o.R, "radius of the gap (x - L/2)^2 / (2R) [m] (sets p0 = a E* / (2R))", Range::closed(1e-6, 1e12));
  parser.add_choice("gap", o.gap, {"exact", "interpolated"},
                    "the gap every method reads: g, or its linear interpolant on the merged grid (a P1 jump can match it)");
  parser.add_choice("linear-solver", o.linear_solver, {"condensed", "sparse"},
                    "Newton steps of Nitsche and penalty: K factorized once, contact dofs last, a dense solve on "
                    "Gamma_c each step; or the whole matrix factorized each step");
  parser.add_choice("start", o.start, {"nested", "cold"},
                    "Newton's start for Nitsche and penalty: the level below's answer interpolated, or u = 0 inside");
  parser.add_double("krylov-max-dofs", o.krylov_max_dofs,
                    "count the Krylov iterations of each method's last matrix on levels up to this many unknowns",
                    Range::closed(0, 1e7));
  parser.add_choice("sweep", o.sweep, {"none", "gamma0", "stiffness"},
                    "also, on --sweep-level: gamma0 = 1e-3 .. 1e3 for theta = 1, 0, -1 and penalty (gamma_sweep.csv), or "
                    "E1/E2 = 1e-6 .. 1e6 with each body's traction (stiffness_sweep.csv)");
  parser.add_int("sweep-level", o.sweep_level, "the level of the sweeps (0 = coarsest; default 4, or the finest below it)",
                 Range::closed(0, 9));
  parser.add_string("out", o.out, "output folder");
  parser.add_flag("quick", o.quick, "small sizes for tests (sets n0 = 8, levels = 3; not with --n0 or --levels)");
  parser.add_flag("no-plot", o.no_plot, "write data and scripts but do not run gnuplot");
  parser.add_int("threads", o.threads, mortar::solver_threads_help, Range::closed(1, 64));
  parser.parse(argc, argv);
  mortar::set_solver_threads(o.threads);
  if (!parser.given("penalty-gamma0")) o.penalty_gamma0 = o.gamma0;  // penalty is Nitsche without consistency
  parser.apply_quick(o.quick, {{"n0", o.n0, 8}, {"levels", o.levels, 3}});
  if (!parser.given("sweep-level")) o.sweep_level = std::min(o.sweep_level, o.levels - 1);
  if (o.sweep != "none" && o.sweep_level >= o.levels)
    parser.fail("sweep-level", "level " + std::to_string(o.sweep_level) + " does not exist: levels run from 0 to " +
                                   std::to_string(o.levels - 1));
  mortar::check_two_body_meshes(parser, o, o.n0, o.levels, 1.0);  // square cells
  mortar::check_stiffness_ratio(parser, o);
  mortar::choose_softer_nonmortar(parser, o);  // the mortar references' non-mortar side
  // The finest level's memory, part by part: the sparse solves (at most 3.5 kB a dof, as in
  // chapter 5), the standard mortar's dense blocks on Gamma_c (chapter 5's S = B K^-1 B^T), and
  // Nitsche's Schur complement on the contact dofs c (S, C_cc, S + C_cc and its factor), which
  // nitsche_steps.cpp only builds up to 5000 dofs.
  const double n1 = std::ldexp(static_cast<double>(o.n0), o.levels - 1);
  const double n2 = std::max(2.0, std::round(n1 / o.h_ratio));
  const double dofs = 2 * (n1 + 1) * (std::max(1.0, std::round(n1 * o.H1 / o.L)) + 1) +
                      2 * (n2 + 1) * (std::max(1.0, std::round(n2 * o.H2 / o.L)) + 1);
  if (dofs > 4e6) parser.fail("levels", "the finest level would have " + std::to_string(static_cast<long>(dofs)) +
                                            " dofs, more than this chapter's 4e6 (lower --levels or --n0)");
  const double m = (o.nonmortar == 1 ? n1 : n2) - 1, t = (o.nonmortar == 1 ? n2 : n1) + 1;
  const double c = std::min(5000.0, 4 * (n1 + 1) + 4 * (n2 + 1));
  const std::string memory = mortar::memory_shortfall(
      {{"the sparse solves (" + std::to_string(static_cast<long>(dofs)) + " dofs)", 3500 * dofs},
       {"the mortar's S = B K^-1 B^T on Gamma_c", mortar::schur_dense_bytes(m, t) + mortar::dense_bytes(m, m)},
       {"Nitsche's Schur complement on the contact dofs", 4 * mortar::dense_bytes(c, c)}},
      mortar::machine_memory());
  if (!memory.empty()) parser.fail("levels", memory);
  mortar::prepare_output_folder(parser, o.out);
  mortar::note_nearly_incompressible(o);
}

double body1_weight(const Options& o) {
  if (o.traction == "body2") return 0;
  if (o.traction == "mean") return 0.5;
  return 1;  // body1 (harmonic: weighted segment by segment, NitscheOptions::harmonic_weight)
}

}  // namespace chapter11
