// Chapter 2: P1 triangles, plane-strain elasticity on one body.
//
// One elastic body on the unit square, a smooth manufactured solution with non-homogeneous
// Dirichlet data (left, bottom) and tractions (right, top). The program solves it on a
// sequence of uniformly refined meshes and reports the energy and L2 errors against h, with
// the rates theory predicts for P1 (1 and 2), and each level's time against the physical
// limit (assemble K, one Cholesky factorization, one solve).
//
//   ch02_p1_triangles                         # 8 x 8 to 256 x 256 cells
//   ch02_p1_triangles --n0 16 --levels 6      # up to 512 x 512, about 526k dofs
//   ch02_p1_triangles --spd-solver simplicial_ldlt --jitter 0.3
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "common/study/convergence_study.hpp"
#include "common/linalg/memory_estimate.hpp"
#include "common/study/options.hpp"
#include "common/study/timing_report.hpp"
#include "common/study/vtu.hpp"
#include "figures.hpp"
#include "level.hpp"

namespace {

struct Options {
  int n0 = 8;
  int levels = 6;
  int threads = mortar::default_solver_threads();
  double E = 1.0;
  double nu = 0.3;
  double jitter = 0.0;
  std::string spd_solver = mortar::backend_name(mortar::fastest_spd_backend());
  std::string out = "results/ch02_p1_triangles";
  bool quick = false;
  bool no_plot = false;
  bool profile = false;  // print where the finest level's time goes
};

// 8.4M dofs: a ceiling on time; memory_shortfall (common/memory_estimate) refuses earlier on a
// machine with less than about 26 GB
constexpr int max_cells_per_side = 2048;

void parse_options(mortar::OptionParser& parser, Options& o, int argc, char** argv) {
  using mortar::Range;
  parser.add_int("n0", o.n0, "cells along each side on the coarsest level", Range::closed(1, max_cells_per_side));
  parser.add_int("levels", o.levels, "refinement levels, h halving each time (rates need 3)", Range::closed(3, 12));
  // beyond 1e300 the Lame constants E nu / ((1 + nu)(1 - 2 nu)) overflow for nu near 1/2
  parser.add_double("E", o.E, "Young's modulus E [Pa]", Range::closed(1e-300, 1e300));
  parser.add_double("nu", o.nu, "Poisson ratio nu (plane strain needs nu < 0.5)", Range::open(-1, 0.5));
  parser.add_double("jitter", o.jitter, "random node displacement, fraction of h", Range::closed(0, 0.4));
  parser.add_choice("spd-solver", o.spd_solver, {"cholmod", "simplicial_ldlt"}, "sparse Cholesky");
  parser.add_string("out", o.out, "output folder");
  parser.add_flag("quick", o.quick, "small sizes for tests (sets n0 = 4, levels = 4; not with --n0 or --levels)");
  parser.add_flag("no-plot", o.no_plot, "write data and scripts but do not run gnuplot");
  parser.add_flag("profile", o.profile, "print where the finest level's time goes, beside the limit's (and write profile.csv)");
  parser.add_int("threads", o.threads, mortar::solver_threads_help, mortar::Range::closed(1, 64));
  parser.parse(argc, argv);
  mortar::set_solver_threads(o.threads);
  parser.apply_quick(o.quick, {{"n0", o.n0, 4}, {"levels", o.levels, 4}});
  // in floating point: n0 2^(levels-1) cannot wrap before it is compared
  const double n = std::ldexp(static_cast<double>(o.n0), o.levels - 1);
  if (n > max_cells_per_side)
    parser.fail("levels", "the finest level would have " + std::to_string(static_cast<long long>(n)) +
                              " cells per side, more than " + std::to_string(max_cells_per_side));
  const std::string memory = mortar::memory_shortfall(2 * (n + 1) * (n + 1), mortar::bytes_per_dof_single_solve,
                                                      mortar::machine_memory());
  if (!memory.empty()) parser.fail("levels", memory);
  if (o.spd_solver == "cholmod" && !mortar::cholmod_available())
    parser.fail("spd-solver", "this build has no CHOLMOD (install libsuitesparse-dev and rebuild)");
  mortar::prepare_output_folder(parser, o.out);
}

}  // namespace

int main(int argc, char** argv) {
  // 1. Options, checked before any work starts.
  Options o;
  mortar::OptionParser parser("ch02_p1_triangles",
                              "P1 plane-strain elasticity on the unit square: errors against h "
                              "for a smooth manufactured solution.");
  parse_options(parser, o, argc, argv);
  try {
    // 2. Material and exact solution.
    const mortar::Material material(o.E, o.nu);
    const chapter02::ManufacturedSolution exact(material, 0.01);
    chapter02::LevelSetup setup;
    setup.jitter = o.jitter;
    setup.backend = o.spd_solver == "cholmod" ? mortar::SpdBackend::cholmod
                                              : mortar::SpdBackend::simplicial_ldlt;

    // 3. Refine: one row per level, printed as it finishes.
    mortar::ConvergenceTable table;
    chapter02::LevelResult finest, plotted;
    for (int level = 0; level < o.levels; ++level) {
      setup.n = o.n0 << level;
      chapter02::LevelResult r = chapter02::solve_level(setup, material, exact);
      table.add({{"h", r.mesh.max_edge_length()},
                 {"n", setup.n},
                 {"dofs", r.dofs},
                 {"time_s", r.time_s},
                 {"limit_s", r.limit_s},
                 {"err_energy", r.norms.relative_energy()},
                 {"err_l2", r.norms.relative_l2()},
                 {"err_h1", r.norms.relative_h1_semi()}});
      if (setup.n <= 16 || level == 0) plotted = r;  // a mesh still readable in a figure
      finest = std::move(r);
    }

    // 4. Write convergence.csv, summary.json and the finest solution for ParaView.
    const auto rates = table.rates();
    mortar::JsonObject results;
    results.set("h_m", finest.mesh.max_edge_length())
        .set("dofs", finest.dofs)
        .set("err_energy", finest.norms.relative_energy())
        .set("err_l2", finest.norms.relative_l2())
        .set("spd_solver", o.spd_solver);
    mortar::add_timing(results, finest.timing);
    table.write_csv(o.out + "/convergence.csv");
    mortar::write_summary(o.out + "/summary.json", parser, rates, results);
    if (o.profile) mortar::report_profile(finest.timing, o.out);
    mortar::write_vtu(o.out + "/solution.vtu", finest.mesh, finest.u,
                      mortar::element_stresses(finest.mesh, material, finest.u));
    std::printf("rates (three finest levels): energy %.3f (theory 1), L2 %.3f (theory 2)\n",
                rates.at("err_energy"), rates.at("err_l2"));
    if (o.nu > 0.49)
      std::printf("note: nu = %g is close to 1/2, where P1 locks (lambda / mu = %.3g): expect the "
                  "L2 error and its rate to suffer (see the chapter notes)\n",
                  o.nu, material.lambda() / material.mu());
    std::printf("finest level: %d dofs, %.3f s, %.2f x the physical limit (%.3f s)\n",
                finest.dofs, finest.time_s, finest.time_s / finest.limit_s, finest.limit_s);

    // 5. Figures.
    chapter02::plot_error_vs_h(o.out, table, !o.no_plot);
    chapter02::plot_error_vs_time(o.out, table, !o.no_plot);
    chapter02::plot_deformed_mesh(o.out, plotted.mesh, plotted.u, !o.no_plot);
    std::printf("wrote %s\n", o.out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ch02_p1_triangles: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
