// Chapter 9: chapter 6's contact problem (dual mortar basis, weighted gap, semismooth Newton)
// on PETSc under MPI. Run as
//
//   mpirun -n 2 build/ch09_parallel_petsc --quick
//   mpirun -n 2 build/ch09_parallel_petsc --n0 48 --levels 2 -ksp_monitor -log_view
//   mpirun -n 2 build/ch09_parallel_petsc -pc_type cholesky -pc_factor_mat_solver_type mumps
//
// The steps, in lecture order:
//   1. the command line, split between the course and PETSc (petsc_options.cpp);
//   2. each rank's band of cell rows, built alone (rank_part.cpp), and its stiffness assembled
//      where its rows live (distributed_system.cpp);
//   3. the contact line, whole on every rank from the cells along Gamma_c: chapter 6's dual
//      basis, the rows of B and the weighted gap;
//   4. the condensation A = T^T K T on the distributed matrix (distributed_condensation.cpp);
//   5. the semismooth Newton method, one Krylov solve per step (distributed_newton.cpp), from
//      the level below's answer (nested_start.cpp);
//   6. chapter 6's CHOLMOD answer on rank 0, and the differences (cholmod_reference.cpp);
//   7. the table, summary.json and the figures, by rank 0 (figures.cpp).
#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <numeric>
#include <stdexcept>

#include "cholmod_reference.hpp"
#include "common/contact/constraints.hpp"
#include "common/contact/contact_scenes.hpp"
#include "common/study/bilateral_study.hpp"
#include "common/study/convergence_study.hpp"
#include "common/linalg/memory_estimate.hpp"
#include "common/study/json_writer.hpp"
#include "common/study/options.hpp"
#include "common/timing/machine_load.hpp"
#include "common/timing/stopwatch.hpp"
#include "distributed_condensation.hpp"
#include "distributed_newton.hpp"
#include "nested_start.hpp"
#include "figures.hpp"
#include "petsc_check.hpp"
#include "petsc_options.hpp"
#include "condensed_solver.hpp"

namespace {

struct Options : mortar::TwoBodyOptions {
  int n0 = 12, levels = 5;
  double delta = 0.02, R = 1;
  double ksp_rtol = chapter09::NewtonOptions{}.ksp_rtol, loose_rtol = chapter09::NewtonOptions{}.loose_rtol;
  double agreement = 1e-8;  // the largest relative difference to chapter 6's answer accepted
  std::string reference = "answer";  // answer | limit | none
  std::string scene = "hertz";       // hertz | manufactured
  std::string start = "nested";      // nested | cold
  double glue_weight = chapter09::NewtonOptions{}.glue_weight;
  bool quick = false, no_plot = false;
  std::string out = "results/ch09_parallel_petsc";
};

// The memory of the finest level, all ranks together (they share this machine's memory when
// run here): the distributed solve, measured at 1.58-1.75 kB per unknown over two ranks from
// 1.7M to 13.7M unknowns (K, its glued copy K_P, T, GAMG's hierarchy, the Krylov vectors and
// each rank's band of the mesh), counted at 1.75 kB; then, its matrices freed, chapter 6's CHOLMOD answer or the limit on rank
// 0. The two never hold memory at once: each must fit on its own.
void check_memory(const mortar::OptionParser& parser, const Options& o) {
  const double n1 = std::ldexp(static_cast<double>(o.n0), o.levels - 1);
  const double n2 = std::max(2.0, std::round(n1 / o.h_ratio));
  const double m1 = std::max(1.0, std::round(n1 * o.H1 / o.L)), m2 = std::max(1.0, std::round(n2 * o.H2 / o.L));
  const double dofs = 2 * (n1 + 1) * (m1 + 1) + 2 * (n2 + 1) * (m2 + 1);
  char distributed[96];
  std::snprintf(distributed, sizeof distributed, "the distributed solve (%.3g unknowns, all ranks)", dofs);
  std::string memory = mortar::memory_shortfall({{distributed, 1750 * dofs}}, mortar::machine_memory());
  if (memory.empty() && o.reference != "none")
    memory = mortar::memory_shortfall({{"chapter 6's CHOLMOD answer or limit on rank 0 (--reference none skips it)",
                                        mortar::bytes_per_dof_single_solve * dofs}},
                                      mortar::machine_memory());
  if (!memory.empty()) parser.fail("levels", memory);
}

// The slender-body limit. With frictionless contact, a body much taller than Gamma_c is long
// (H/L) holds its sideways bending only by its bending stiffness, about (L/H)^3 of its axial
// one; double precision then fixes u only to about eps N (H/L)^3 / 30 of its size (N unknowns;
// measured with GAMG, MUMPS and CHOLMOD from H/L = 10 to 1000 within a factor 3: at
// --L 1e-3 --n0 4 --levels 1, 5.8e-4 predicted 4.2e-4). Beyond --agreement / 3 no solver can
// give chapter 6's answer to --agreement, and neither answer means more: refused.
void check_slenderness(const mortar::OptionParser& parser, const Options& o) {
  const double n1 = std::ldexp(static_cast<double>(o.n0), o.levels - 1);
  const double n2 = std::max(2.0, std::round(n1 / o.h_ratio));
  const double m1 = std::max(1.0, std::round(n1 * o.H1 / o.L)), m2 = std::max(1.0, std::round(n2 * o.H2 / o.L));
  const double dofs = 2 * (n1 + 1) * (m1 + 1) + 2 * (n2 + 1) * (m2 + 1);
  const double slender = std::max(1.0, std::max(o.H1, o.H2) / o.L);
  const double attainable = std::numeric_limits<double>::epsilon() * dofs * std::pow(slender, 3) / 30;
  if (attainable <= o.agreement / 3) return;
  char why[320];
  if (slender > 1)
    std::snprintf(why, sizeof why,
                  "bodies %.3g times as tall as Gamma_c is long bend sideways under a stiffness (L/H)^3 of their "
                  "own: double precision fixes u only to about %.1e at %.3g unknowns, above --agreement %.0e / 3",
                  slender, attainable, dofs, o.agreement);
  else
    std::snprintf(why, sizeof why, "double precision fixes u only to about %.1e at %.3g unknowns, above %.0e / 3",
                  attainable, dofs, o.agreement);
  parser.fail(slender > 1 ? "L" : "agreement", why);
}

void declare_options(mortar::OptionParser& parser, Options& o) {
  o.H1 = o.H2 = 1;  // chapter 5's Hertz scene: square blocks of one material
  o.E2 = 1;
  o.nu2 = 0.3;
  parser.add_int("n0", o.n0, "body-1 elements along Gamma_c on the coarsest level", mortar::Range::closed(2, 1 << 14));
  parser.add_int("levels", o.levels, "refinement levels, h halving each time", mortar::Range::closed(1, 10));
  mortar::add_two_body_options(parser, o);
  parser.add_double("delta", o.delta, "downward displacement of the top of body 1 [m]", mortar::Range::closed(0, 1e6));
  parser.add_double("R", o.R, "radius of the gap (x - L/2)^2 / (2R) [m]", mortar::Range::closed(1e-6, 1e12));
  parser.add_double("ksp-rtol", o.ksp_rtol, "relative tolerance of each Krylov solve",
                    mortar::Range::closed(1e-15, 1e-2));
  parser.add_double("loose-rtol", o.loose_rtol,
                    "while the active set still moves, each Krylov solve reduces its own residual by this factor; "
                    "the final solve reaches --ksp-rtol (= --ksp-rtol: an exact Newton method)",
                    mortar::Range::closed(1e-15, 0.1));
  parser.add_double("agreement", o.agreement,
                    "with --reference answer, the largest relative difference to chapter 6's answer accepted "
                    "(more ends the run with status 1)",
                    mortar::Range::closed(1e-15, 1));
  parser.add_choice("scene", o.scene, {"hertz", "manufactured"},
                    "chapter 5's Hertz scene (unilateral), or chapter 4's manufactured solution (bilateral)");
  parser.add_choice("start", o.start, {"nested", "cold"},
                    "each level's Newton method starts from the level below's answer (displacement "
                    "interpolated, multipliers along Gamma_c), or from u = 0 with no node in contact");
  parser.add_double("glue-weight", o.glue_weight,
                    "GAMG (or -pc_type) is built once per level on K glued along the first active set with this "
                    "weight alpha (times K's diagonal); 0: on K itself",
                    mortar::Range::closed(0, 1e6));
  parser.add_choice("reference", o.reference, {"answer", "limit", "none"},
                    "chapter 6's CHOLMOD answer and the physical limit on rank 0; the limit alone; or neither");
  parser.add_string("out", o.out, "output folder (written by rank 0)");
  parser.add_flag("quick", o.quick, "small sizes for tests (sets n0 = 8, levels = 2; not with --n0 or --levels)");
  parser.add_flag("no-plot", o.no_plot, "write data and scripts but do not run gnuplot");
}

void parse_options(mortar::OptionParser& parser, Options& o, int argc, char** argv) {
  parser.parse(argc, argv);
  parser.apply_quick(o.quick, {{"n0", o.n0, 8}, {"levels", o.levels, 2}});
  mortar::check_two_body_meshes(parser, o, o.n0, o.levels, 1.0);
  mortar::check_stiffness_ratio(parser, o);
  mortar::choose_softer_nonmortar(parser, o);  // as chapter 6, whose answer is the reference
  if (o.delta >= o.H1) parser.fail("delta", "delta must stay below the height of body 1 (small strain)");
  check_slenderness(parser, o);
  check_memory(parser, o);
}

// The largest |a - b| over the largest |b|.
double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const double scale = b.cwiseAbs().maxCoeff();
  return scale > 0 ? (a - b).cwiseAbs().maxCoeff() / scale : (a - b).cwiseAbs().maxCoeff();
}

// The distributed u, whole on rank 0 (empty elsewhere).
Eigen::VectorXd gather_on_rank_0(Vec u) {
  VecScatter scatter;
  Vec whole;
  chapter09::check(VecScatterCreateToZero(u, &scatter, &whole), "VecScatterCreateToZero");
  chapter09::check(VecScatterBegin(scatter, u, whole, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  chapter09::check(VecScatterEnd(scatter, u, whole, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  PetscInt n = 0;
  chapter09::check(VecGetLocalSize(whole, &n), "VecGetLocalSize");
  const PetscScalar* a;
  chapter09::check(VecGetArrayRead(whole, &a), "VecGetArrayRead");
  Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(a, n);
  chapter09::check(VecRestoreArrayRead(whole, &a), "VecRestoreArrayRead");
  VecScatterDestroy(&scatter);
  VecDestroy(&whole);
  return out;
}

// Step 3: the rows of B (chapter 6's dual basis, integral matching) and the weighted gap G of
// the Hertz scene (zero for the glued manufactured one), on any two bodies that hold Gamma_c.
struct ContactLine {
  mortar::Constraints constraints;
  Eigen::VectorXd G;
  std::vector<double> x;  // each row's node along Gamma_c
};
ContactLine contact_line(const mortar::TwoBodies& bodies, const mortar::SceneData& scene, const Options& o) {
  const mortar::ContactInterface gamma = mortar::make_dual_interface(bodies, o.nonmortar - 1);
  ContactLine line;
  line.constraints = mortar::constraint_rows(bodies, gamma, mortar::integral_matching_rows(gamma),
                                             scene.prescribed_mask(bodies.num_dofs()));
  for (int node : line.constraints.row_node) line.x.push_back(gamma.nonmortar_trace.x[node]);
  const double L = o.L, R = o.R;
  line.G = o.scene == "hertz" ? mortar::tested_gap(gamma, line.constraints, [L, R](double x) {
    return (x - 0.5 * L) * (x - 0.5 * L) / (2 * R);
  }) : Eigen::VectorXd::Zero(line.constraints.B.rows());
  return line;
}

// Chapter 6's answer is the reference: a difference beyond --agreement, or another active set, is
// a failure (on every rank: the difference was broadcast), not a line to read.
void check_agreement(const mortar::ConvergenceTable& table, int level, double agreement) {
  const double difference = table.column("max_rel_diff_vs_cholmod").back();
  const bool identical = table.column("active_set_identical").back() > 0;
  if (difference <= agreement && identical) return;
  char line[200];
  std::snprintf(line, sizeof line, "level %d differs from chapter 6's answer by %.2e (max relative), above --agreement %.0e%s",
                level, difference, agreement, identical ? "" : ", and its active set differs");
  throw std::runtime_error(line);
}

// Rank 0's failure (empty: none), thrown on every rank.
void broadcast_failure(std::string& failure) {
  int size = static_cast<int>(failure.size());
  MPI_Bcast(&size, 1, MPI_INT, 0, PETSC_COMM_WORLD);
  if (size == 0) return;
  failure.resize(static_cast<std::size_t>(size));
  MPI_Bcast(failure.data(), size, MPI_CHAR, 0, PETSC_COMM_WORLD);
  throw std::runtime_error(failure);
}

// The slowest rank's time for f.
template <class F>
double timed(F&& f) {
  MPI_Barrier(PETSC_COMM_WORLD);
  const mortar::Stopwatch clock;
  f();
  double t = clock.seconds(), slowest = 0;
  MPI_Allreduce(&t, &slowest, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  return slowest;
}

// The finest level's multipliers along Gamma_c: each row's node x, lambda_i (a pressure) and
// whether it is active.
struct Multipliers {
  std::vector<double> x, lambda;
  std::vector<bool> active;
};
void write_multipliers(const std::string& path, const Multipliers& m) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) throw std::runtime_error("cannot write " + path);
  std::fprintf(f, "x,lambda,active\n");
  for (std::size_t i = 0; i < m.x.size(); ++i) std::fprintf(f, "%.17g,%.17g,%d\n", m.x[i], m.lambda[i], m.active[i] ? 1 : 0);
  std::fclose(f);
}

// One linear solve with the contact solve's preconditioner on K, to the same final tolerance:
// assembly, set-up, and CG on K u = f from u = 0. The unit of k, the linear solves a contact
// solve costs (the whole contact solve's time over this one's).
double linear_solve_s(const chapter09::Ownership& rows, const chapter09::Part& part, const mortar::SceneData& scene,
                      double rtol, int& iterations) {
  chapter09::DistributedSystem system;
  struct Solution {  // freed whatever happens
    Vec u = nullptr;
    ~Solution() { if (u != nullptr) VecDestroy(&u); }
  } x;
  return timed([&] {
    chapter09::assemble(system, rows, part, scene);
    chapter09::CondensedSolver solver(system.K, nullptr, rtol);
    solver.set_up();
    chapter09::check(VecDuplicate(system.f, &x.u), "VecDuplicate");
    chapter09::check(VecSet(x.u, 0.0), "VecSet");
    iterations = solver.solve(system.f, x.u, rtol, false);
  });
}

int run(const Options& o, const mortar::OptionParser& parser) {
  const bool root = chapter09::rank() == 0;
  // the machine's CPU clock, to say at the end whether other work shared the cores
  const mortar::CpuClock cpu_start = mortar::CpuClock::now();
  const mortar::Stopwatch wall;
  mortar::ConvergenceTable table;
  double worst_difference = 0;
  bool all_identical = true;
  int ksp_max = 0;
  double ratio_last = std::nan(""), limit_last = std::nan(""), cumulative_s = 0, k_last = std::nan("");
  std::vector<int> steps_per_level, setups_per_level;
  std::unique_ptr<chapter09::CoarseAnswer> coarse;  // the level below's answer (--start nested)
  Multipliers finest;  // the last level's, for multipliers.csv
  std::string solver;
  const bool hertz = o.scene == "hertz";
  const mortar::Material material1(o.E1, o.nu1), material2(o.E2, o.nu2);
  // Hertz: pressed between plates, the gap of a cylinder; manufactured: chapter 4's exact
  // solution, its body forces and boundary data, glued (every pivot fixed at w = 0)
  const mortar::ManufacturedContact exact(material1, material2, mortar::sloped_profile(o.L), o.L);
  const auto scene_of = [&](const mortar::TwoBodies& bodies) {
    return hertz ? mortar::pressed_between_plates(bodies, o.delta) : mortar::manufactured_scene(bodies, exact);
  };
  for (int level = 0; level < o.levels; ++level) {
    mortar::reset_peak_memory();
    // one stage per level: -log_view then shows each level's set-up and solves apart
    PetscLogStage stage;
    chapter09::check(PetscLogStageRegister(("level " + std::to_string(level)).c_str(), &stage), "PetscLogStageRegister");
    chapter09::check(PetscLogStagePush(stage), "PetscLogStagePush");
    // The level: who owns which cell rows, this rank's band of them, and the contact line on
    // every rank (steps 2 and 3).
    const mortar::TwoBodyGeometry geometry = mortar::two_body_geometry(o, o.n0 << level, 1.0);
    const chapter09::RowSplit split(geometry, chapter09::ranks());
    if (root && level == 0) chapter09::plot_partition(o.out, split, material1, material2, !o.no_plot);
    const chapter09::Part strip = split.contact_strip(material1, material2);
    const ContactLine line = contact_line(strip.bodies, scene_of(strip.bodies), o);
    double h = 0;

    // Steps 2, 4 and 5, timed together: the whole distributed contact solve, from the level
    // below's answer when there is one. Its matrices are freed before the linear solve and
    // chapter 6's answer start: no two of them hold memory at once.
    chapter09::NewtonResult newton;
    chapter09::NewtonOptions newton_options;
    newton_options.ksp_rtol = o.ksp_rtol;
    newton_options.loose_rtol = o.loose_rtol;
    newton_options.bilateral = !hertz;
    newton_options.glue_weight = o.glue_weight;
    double time_s = 0, linear_s = 0, memory_mb = 0;
    int linear_iterations = 0;
    {
      const chapter09::Part part = split.part(chapter09::rank(), material1, material2);
      const mortar::SceneData scene = scene_of(part.bodies);
      const double own_h = part.bodies.max_edge_length();
      MPI_Allreduce(&own_h, &h, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
      {
        chapter09::DistributedSystem system;
        chapter09::DistributedCondensation condensed;
        chapter09::NewtonStart start;
        time_s = timed([&] {
          chapter09::assemble(system, split.ownership(chapter09::rank()), part, scene);
          chapter09::condense(condensed, system, chapter09::global_rows(strip, line.constraints, split.num_dofs()),
                              line.G);
          if (coarse) {
            chapter09::check(VecDuplicate(condensed.r, &start.u), "VecDuplicate");
            chapter09::interpolate_displacement(*coarse, part, start.u);
            start.lambda = chapter09::interpolate_multipliers(*coarse, line.x);
          }
          chapter09::solve_contact(newton, system, condensed, newton_options, coarse ? &start : nullptr);
        });
      }
      // the resident-set peaks of all ranks, added: they share this machine's memory
      const double peak = mortar::peak_memory_bytes() / 1e6;
      MPI_Allreduce(&peak, &memory_mb, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
      linear_s = linear_solve_s(split.ownership(chapter09::rank()), part, scene, o.ksp_rtol, linear_iterations);
    }
    // the whole contact solve of this level: with a nested start, every level up to it
    cumulative_s = (o.start == "nested" ? cumulative_s : 0.0) + time_s;
    const Eigen::VectorXd u = gather_on_rank_0(newton.u);
    const int ksp = *std::max_element(newton.ksp_iterations.begin(), newton.ksp_iterations.end());
    ksp_max = std::max(ksp_max, ksp);
    steps_per_level.push_back(newton.steps);
    setups_per_level.push_back(newton.pc_setups);
    k_last = cumulative_s / linear_s;
    solver = newton.ksp_type + " + " + newton.pc_type;

    const int dofs = static_cast<int>(split.num_dofs());
    mortar::Row row = {{"h", h},
                       {"dofs", dofs},
                       {"multipliers", static_cast<double>(newton.lambda.size())},
                       {"ranks", chapter09::ranks()},
                       {"newton_steps", newton.steps},
                       {"ksp_iterations_max", ksp},
                       {"time_s", time_s}};
    row.push_back({"ksp_iterations_total", std::accumulate(newton.ksp_iterations.begin(), newton.ksp_iterations.end(), 0)});
    row.push_back({"memory_mb", memory_mb});
    row.push_back({"pc_setup_s", newton.setup_s});  // the preconditioner, K_P included, built once
    row.push_back({"pc_setups", newton.pc_setups});
    row.push_back({"active_first", newton.first_active});
    row.push_back({"active_last", newton.last_active});
    row.push_back({"cumulative_s", cumulative_s});
    row.push_back({"linear_s", linear_s});
    row.push_back({"linear_iterations", linear_iterations});
    row.push_back({"linear_solves", k_last});
    if (o.reference != "none") {
      // Step 6: the level's physical limit and, with --reference answer, chapter 6's answer
      // (rank 0), and how far the distributed one is from it.
      double difference = 0, limit_s = 0, cholmod_s = 0;
      int identical = 1;
      mortar::reset_peak_memory();
      std::string failure;  // rank 0's, said by every rank: none may wait for a rank that has stopped
      if (root) try {
        // rank 0 builds the whole level for it, and its own contact line: an independent check
        // of the bands and the strip
        const mortar::TwoBodies bodies = mortar::make_two_bodies(geometry, material1, material2);
        const mortar::SceneData scene = scene_of(bodies);
        if (o.reference == "answer") {
          const ContactLine whole = contact_line(bodies, scene, o);
          const chapter09::CholmodAnswer a =
              chapter09::cholmod_answer(bodies, scene, whole.constraints, whole.G, hertz);
          const Eigen::VectorXd lambda = Eigen::Map<const Eigen::VectorXd>(newton.lambda.data(), a.lambda.size());
          difference = std::max(relative_difference(u, a.u), relative_difference(lambda, a.lambda));
          identical = newton.active == a.active;
          limit_s = a.limit_s;
          cholmod_s = a.time_s;
        } else {
          limit_s = chapter09::physical_limit(bodies, scene);
        }
      } catch (const std::exception& e) {
        failure = std::string("chapter 6's answer: ") + e.what();
      }
      broadcast_failure(failure);
      // rank 0's peak through chapter 6's answer or the limit (CHOLMOD's factor)
      double cholmod_mb = mortar::peak_memory_bytes() / 1e6;
      MPI_Bcast(&cholmod_mb, 1, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
      MPI_Bcast(&difference, 1, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
      MPI_Bcast(&identical, 1, MPI_INT, 0, PETSC_COMM_WORLD);
      MPI_Bcast(&limit_s, 1, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
      ratio_last = cumulative_s / limit_s;
      limit_last = limit_s;
      row.push_back({"limit_s", limit_s});
      row.push_back({"cholmod_memory_mb", cholmod_mb});
      if (o.reference == "answer") {
        worst_difference = std::max(worst_difference, difference);
        all_identical = all_identical && identical;
        row.push_back({"cholmod_time_s", cholmod_s});
        row.push_back({"max_rel_diff_vs_cholmod", difference});
        // the difference to chapter 6 as the table's error column: round-off, no rate expected
        row.push_back({"err_vs_cholmod", difference});
        row.push_back({"active_set_identical", identical});
      }
    }
    table.add(row);
    if (root) {
      std::printf("level %d: %d dofs, %d ranks, %d Newton steps, Krylov iterations per solve (' while the active set moves):", level,
                  dofs, chapter09::ranks(), newton.steps);
      for (std::size_t k = 0; k < newton.ksp_iterations.size(); ++k)
        std::printf(" %d%s", newton.ksp_iterations[k], newton.tight[k] ? "" : "'");
      std::printf(" (%s + %s), preconditioner built %d time%s, %.3g s (%.3g s with the levels below), %.0f MB; "
                  "one linear solve %.3g s (%d iterations): %.2f linear solves",
                  newton.ksp_type.c_str(), newton.pc_type.c_str(), newton.pc_setups, newton.pc_setups == 1 ? "" : "s",
                  time_s, cumulative_s, memory_mb, linear_s, linear_iterations, k_last);
      if (o.reference == "limit") std::printf("; %.2f x the limit", ratio_last);
      if (o.reference == "answer")
        std::printf("; against chapter 6 (CHOLMOD): max relative difference %.2e, active set %s, %.2f x the limit",
                    table.column("max_rel_diff_vs_cholmod").back(),
                    table.column("active_set_identical").back() > 0 ? "identical" : "DIFFERENT", ratio_last);
      std::printf("\n");
    }
    if (o.reference == "answer") check_agreement(table, level, o.agreement);
    finest = {line.x, newton.lambda, newton.active};
    if (o.start == "nested") {  // kept for the next level; the one below is freed
      coarse.reset();
      coarse = std::make_unique<chapter09::CoarseAnswer>(split, newton.u, line.x, newton.lambda);
      newton.u = nullptr;
    }
    PetscLogStagePop();
  }
  // The timings above mean what they say only if no other work shared the cores (a loaded
  // machine once made PETSc look slower than CHOLMOD): the CPU time of other processes.
  double own_s = mortar::CpuClock::now().own_s - cpu_start.own_s, own_s_all = 0;
  MPI_Allreduce(&own_s, &own_s_all, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  const mortar::MachineLoad load = mortar::machine_load(cpu_start, mortar::CpuClock::now(), own_s_all, wall.seconds());
  if (root) {
    std::printf("machine: %s\n", load.describe().c_str());
    mortar::JsonObject results;
    results.set("machine_load_average", load.load_average)
        .set("other_work_share", load.other_work_share)
        .set("timings_meaningful", load.meaningful());
    results.set("ranks", chapter09::ranks())
        .set("dofs", table.column("dofs").back())
        .set("newton_steps", steps_per_level.back())
        .set("newton_steps_per_level", steps_per_level)
        .set("pc_setups_per_level", setups_per_level)
        .set("linear_solves_per_contact_solve", k_last)
        .set("ksp_iterations_max", ksp_max);
    if (o.reference == "answer")
      results.set("max_rel_diff_vs_cholmod", worst_difference).set("active_set_identical", all_identical);
    if (o.reference != "none") results.set("limit_ratio", ratio_last).set("limit_s", limit_last);
    table.write_csv(o.out + "/convergence.csv");
    write_multipliers(o.out + "/multipliers.csv", finest);
    chapter09::plot_solves(o.out, table, solver, o.ksp_rtol, !o.no_plot);
    mortar::write_summary(o.out + "/summary.json", parser, table.rates(), results);
    std::printf("wrote %s\n", o.out.c_str());
  }
  return 0;
}

}  // namespace

// Step 1: the options, every refusal before any work. Each check runs alike on every rank, so
// that all stop together with status 2; rank 0 alone speaks.
int checked_run(chapter09::SplitArguments& args) {
  Options o;
  mortar::OptionParser parser("ch09_parallel_petsc",
                              "Chapter 6's unilateral contact (dual mortar basis, semismooth Newton) on PETSc under "
                              "MPI: distributed assembly, condensation, CG + GAMG; checked against chapter 6.");
  declare_options(parser, o);
  for (const std::string& a : args.course)
    if (a == "--help") {  // the parser would print it and exit before MPI ends
      std::printf("%s", parser.usage().c_str());
      return 0;
    }
  std::vector<char*> course_argv = chapter09::argv_of(args.course);
  parse_options(parser, o, static_cast<int>(args.course.size()), course_argv.data());
  const std::string refusal = chapter09::petsc_options_refusal(args.petsc);
  if (!refusal.empty()) {
    std::fprintf(stderr, "ch09_parallel_petsc: %s\n", refusal.c_str());
    return 2;
  }
  if (chapter09::rank() == 0) mortar::prepare_output_folder(parser, o.out);
  return run(o, parser);
}

int main(int argc, char** argv) {
  // MPI first, PETSc second: so that a bad -options_file is refused in one line, and every
  // rank ends through MPI_Finalize, whatever the status.
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  // One voice: the other ranks' output would repeat rank 0's.
  if (rank != 0 &&
      (std::freopen("/dev/null", "w", stdout) == nullptr || std::freopen("/dev/null", "w", stderr) == nullptr))
    MPI_Abort(MPI_COMM_WORLD, 1);
  chapter09::SplitArguments args = chapter09::split_arguments(argc, argv);
  int status = 0;
  if (const std::string file = chapter09::unreadable_options_file(args.petsc); !file.empty()) {
    std::fprintf(stderr, "ch09_parallel_petsc: %s\n", file.c_str());
    status = 2;
  } else {
    std::vector<char*> petsc_argv = chapter09::argv_of(args.petsc);
    int petsc_argc = static_cast<int>(args.petsc.size());
    char** petsc_pointer = petsc_argv.data();
    if (PetscInitialize(&petsc_argc, &petsc_pointer, nullptr, nullptr) != 0) {
      std::fprintf(stderr, "ch09_parallel_petsc: PETSc could not start with these options\n");
      status = 2;
    } else {
      chapter09::quiet_petsc_errors();
      try {
        status = checked_run(args);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "ch09_parallel_petsc: error: %s\n", e.what());
        status = 1;
      }
      PetscFinalize();
    }
  }
  MPI_Finalize();
  return status;
}
