#include "common/study/bilateral_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>
#include <limits>

#include "common/linalg/memory_estimate.hpp"
#include "common/linalg/work_estimate.hpp"
#include "common/timing/stopwatch.hpp"
#include "common/study/timing_report.hpp"
#include "common/study/two_body_pictures.hpp"

namespace mortar {

namespace {
// A ceiling independent of the machine (it keeps node and dof indices far inside int);
// memory_shortfall refuses earlier wherever less than about 36 GB is free.
constexpr double max_dofs = 12'000'000;

constexpr double max_cells_per_side = 1 << 16;

// Cells along and across each body at the finest level, in floating point so that absurd
// heights or aspects cannot wrap an int before they are checked.
struct FinestSize {
  double n1, m1, n2, m2;
  double q = 1;  // degree: q n + 1 nodes along a side
  double dofs() const { return 2 * (q * n1 + 1) * (q * m1 + 1) + 2 * (q * n2 + 1) * (q * m2 + 1); }
  double largest() const { return std::max({n1, m1, n2, m2}); }
};

FinestSize finest_size(const BilateralStudyOptions& o) {
  FinestSize s;
  s.n1 = std::ldexp(static_cast<double>(o.n0), o.levels - 1);
  s.n2 = std::max(2.0, std::round(s.n1 / o.h_ratio));
  s.m1 = std::max(1.0, std::round(o.aspect * s.n1 * o.H1 / o.L));
  s.m2 = std::max(1.0, std::round(o.aspect * s.n2 * o.H2 / o.L));
  s.q = o.degree;
  return s;
}
}  // namespace

std::string mesh_label(const TwoBodyOptions& o) {
  char text[64];
  std::snprintf(text, sizeof text, "h_2/h_1 = %.4g, non-mortar body %d", o.h_ratio, o.nonmortar);
  return text;
}

void add_two_body_options(OptionParser& parser, TwoBodyOptions& o) {
  parser.add_double("h-ratio", o.h_ratio, "mesh ratio h2 / h1 on Gamma_c (body 2 gets max(2, round(n1 / r)) elements)",
                    Range::closed(0.01, 100));
  parser.add_int("nonmortar", o.nonmortar, "the non-mortar body, which carries the multipliers (1 or 2)", Range::closed(1, 2));
  parser.add_double("E1", o.E1, "Young's modulus of body 1 [Pa]", Range::closed(1e-300, 1e300));
  parser.add_double("nu1", o.nu1, "Poisson ratio of body 1", Range::open(-1, 0.5));
  parser.add_double("E2", o.E2, "Young's modulus of body 2 [Pa]", Range::closed(1e-300, 1e300));
  parser.add_double("nu2", o.nu2, "Poisson ratio of body 2", Range::open(-1, 0.5));
  parser.add_double("L", o.L, "length of Gamma_c [m]", Range::closed(1e-6, 1e6));
  parser.add_double("H1", o.H1, "height of body 1 [m] (its cells must stay within 20:1)", Range::closed(1e-9, 1e9));
  parser.add_double("H2", o.H2, "height of body 2 [m]", Range::closed(1e-9, 1e9));
  parser.add_double("jitter", o.jitter, "random node displacement, fraction of h", Range::closed(0, 0.4));
}

std::vector<MemoryPart> bilateral_memory_parts(const BilateralStudyOptions& o) {
  const FinestSize size = finest_size(o);
  // multipliers: the non-mortar side's interior nodes; t: the mortar side's nodes
  const double n_nonmortar = o.nonmortar == 1 ? size.n1 : size.n2, n_mortar = o.nonmortar == 1 ? size.n2 : size.n1;
  const double m = size.q * n_nonmortar - 1, t = size.q * n_mortar + 1;
  char sparse[96], dense[160];
  std::snprintf(sparse, sizeof sparse, "the finest level's sparse solve (%.3g dofs)", size.dofs());
  std::vector<MemoryPart> parts = {{sparse, size.dofs() * bytes_per_dof_single_solve}};
  if (o.saddle_solver == "schur") {
    std::snprintf(dense, sizeof dense, "S = B K^-1 B^T and the factor's dense block on Gamma_c (%.0f multipliers, "
                  "%.0f mortar nodes)", m, t);
    parts.push_back({dense, schur_dense_bytes(m, t)});
  } else if (o.saddle_solver == "elimination") {
    std::snprintf(dense, sizeof dense, "X = -B_s^-1 B_r and the block it adds to K on Gamma_c (%.0f x %.0f, dense)", m, t);
    parts.push_back({dense, elimination_dense_bytes(m, t)});
  }
  return parts;
}

void choose_softer_nonmortar(const OptionParser& parser, TwoBodyOptions& o) {
  constexpr double ratio = 10;
  if (!parser.given("nonmortar")) {
    if (o.E1 > ratio * o.E2) {
      o.nonmortar = 2;
      std::printf("note: body 1 is %.3g times stiffer than body 2: body 2, the softer, is the non-mortar side "
                  "(--nonmortar 1 to force body 1)\n", o.E1 / o.E2);
    }
    return;
  }
  const double stiffer = o.nonmortar == 1 ? o.E1 / o.E2 : o.E2 / o.E1;
  if (stiffer > ratio)
    std::printf("warning: the non-mortar body %d is %.3g times stiffer than the other: expect the contact pressure "
                "to oscillate from node to node (README.md, \"Hard cases\"); the softer body is the better "
                "non-mortar side\n", o.nonmortar, stiffer);
}

void check_stiffness_ratio(const OptionParser& parser, const TwoBodyOptions& o) {
  constexpr double limit = 1e10;
  const double ratio = o.E1 / o.E2;
  if (ratio <= limit && ratio >= 1 / limit) return;
  char message[320];
  std::snprintf(message, sizeof message,
                "body %d is %.3g times stiffer than body %d: beyond 1e10 the soft body's equations drown in the "
                "stiff body's round-off and the solvers call the matrix singular; bring E1 / E2 within [1e-10, 1e10] "
                "(a body that much stiffer is rigid for the other)",
                ratio > 1 ? 1 : 2, ratio > 1 ? ratio : 1 / ratio, ratio > 1 ? 2 : 1);
  const bool one_given = parser.given("E1") != parser.given("E2");  // name the one the user gave
  parser.fail(one_given ? (parser.given("E1") ? "E1" : "E2") : (ratio > 1 ? "E1" : "E2"), message);
}

namespace {
// Announces, before any work, a run whose dense blocks on Gamma_c will take minutes
// (work_estimate.hpp): bodies a few cells thick along a long Gamma_c, where the physical limit
// (one sparse Cholesky factorization of K) is a hundredth of a second.
void warn_of_a_long_run(const BilateralStudyOptions& o) {
  const FinestSize size = finest_size(o);
  const double n_nonmortar = o.nonmortar == 1 ? size.n1 : size.n2, n_mortar = o.nonmortar == 1 ? size.n2 : size.n1;
  const double m = size.q * n_nonmortar - 1, t = size.q * n_mortar + 1;
  char what[160];
  std::snprintf(what, sizeof what, "the finest level's dense blocks on Gamma_c (%s solver, %.0f multipliers, %.0f mortar nodes)",
                o.saddle_solver.c_str(), m, t);
  const std::string warning = long_run_warning(dense_block_flops(o.saddle_solver, m, t), what);
  if (warning.empty()) return;
  std::printf("%s; their cost grows like the cube of the nodes on Gamma_c: fewer --levels, a smaller --n0 or "
              "thicker bodies (--H1, --H2) give the same rates sooner\n", warning.c_str());
  std::fflush(stdout);  // seen before the work starts, even through a pipe
}
}  // namespace

void parse_bilateral_options(OptionParser& parser, BilateralStudyOptions& o, int argc, char** argv,
                             const MoreMemoryParts& more_parts) {
  parser.add_int("n0", o.n0, "body-1 elements along Gamma_c on the coarsest level", Range::closed(2, 1 << 16));
  parser.add_int("levels", o.levels, "refinement levels, h halving each time (rates need 3)", Range::closed(3, 12));
  add_two_body_options(parser, o);
  parser.add_double("aspect", o.aspect, "cell width / cell height (20 for 1:20 cells)", Range::closed(0.05, 20));
  parser.add_choice("saddle-solver", o.saddle_solver, {"elimination", "lu", "schur"},
                    "saddle-point solver: eliminate one unknown per row, one LU of the whole matrix, or the "
                    "multipliers first through S = B K^-1 B^T (K must be SPD alone: not for the patch test)");
  parser.add_choice("pressure-ends", o.pressure_ends, {"sloped", "flat"},
                    "manufactured pressure: sloped (sigma_N' != 0 at x = L) or flat (sigma_N' = 0 at both ends)");
  parser.add_string("out", o.out, "output folder");
  parser.add_flag("quick", o.quick, "small sizes for tests (sets n0 = 6, levels = 3; not with --n0 or --levels)");
  parser.add_flag("no-plot", o.no_plot, "write data and scripts but do not run gnuplot");
  parser.add_flag("profile", o.profile, "print where the finest level's time goes, beside the limit's (and write profile.csv)");
  parser.add_int("threads", o.threads, mortar::solver_threads_help, mortar::Range::closed(1, 64));
  parser.parse(argc, argv);
  mortar::set_solver_threads(o.threads);
  parser.apply_quick(o.quick, {{"n0", o.n0, 6}, {"levels", o.levels, 3}});
  check_two_body_meshes(parser, o, o.n0, o.levels, o.aspect);
  check_stiffness_ratio(parser, o);
  const FinestSize size = finest_size(o);
  if (size.largest() > max_cells_per_side || size.dofs() > max_dofs) {
    char message[256];
    std::snprintf(message, sizeof message,
                  "the finest level would have %.3g dofs and up to %.3g cells along a side "
                  "(limits %.3g and %.3g; check also --L, --H1, --H2, --aspect)",
                  size.dofs(), size.largest(), max_dofs, max_cells_per_side);
    parser.fail("levels", message);
  }
  std::vector<MemoryPart> parts = bilateral_memory_parts(o);
  if (more_parts) {
    const std::vector<MemoryPart> more = more_parts(o);
    parts.insert(parts.end(), more.begin(), more.end());
  }
  const std::string memory = memory_shortfall(parts, machine_memory());
  if (!memory.empty()) parser.fail("levels", memory);
  warn_of_a_long_run(o);
  prepare_output_folder(parser, o.out);
  note_nearly_incompressible(o);
}

ManufacturedContact manufactured_solution(const BilateralStudyOptions& o) {
  const Material m1(o.E1, o.nu1), m2(o.E2, o.nu2);
  return ManufacturedContact(m1, m2, o.pressure_ends == "flat" ? flat_ends_profile(o.L) : sloped_profile(o.L), o.L);
}

void check_two_body_meshes(const OptionParser& parser, const TwoBodyOptions& o, int n0, int levels, double aspect) {
  const double n2_coarsest = std::round(n0 / o.h_ratio);
  if (n2_coarsest < 2) {
    char message[200];
    std::snprintf(message, sizeof message,
                  "body 2 would have %.0f elements along Gamma_c on the coarsest level (n0 / h-ratio = %.3g); "
                  "it needs at least 2 to be refined with body 1: raise --n0 or lower --h-ratio",
                  n2_coarsest, n0 / o.h_ratio);
    parser.fail("h-ratio", message);
  }
  // the cells' width / height: (L / n) / (H / m), m as two_body_geometry rounds it; 10% above
  // the --aspect limit of 20 leaves room for that rounding
  constexpr double limit = 22;
  for (const double n1 : {static_cast<double>(n0), std::ldexp(static_cast<double>(n0), levels - 1)})
    for (int l = 0; l < 2; ++l) {
      const double n = l == 0 ? n1 : std::max(2.0, std::round(n1 / o.h_ratio));
      const double H = l == 0 ? o.H1 : o.H2;
      const double m = std::max(1.0, std::round(aspect * n * H / o.L));
      const double shape = (o.L / n) / (H / m);
      if (shape > limit || shape < 1 / limit) {
        char message[240];
        std::snprintf(message, sizeof message,
                      "the cells of body %d would be %.3g:1 (width L / %.0f = %.3g m, height H%d / %.0f = %.3g m); "
                      "beyond 20:1 either way the solves degrade: check --L, --H1, --H2 and --aspect",
                      l + 1, shape >= 1 ? shape : 1 / shape, n, o.L / n, l + 1, m, H / m);
        parser.fail("L", message);
      }
    }
}

void note_nearly_incompressible(const TwoBodyOptions& o) {
  for (const auto& [body, nu, E] : {std::tuple<int, double, double>{1, o.nu1, o.E1}, {2, o.nu2, o.E2}}) {
    if (nu <= 0.49) continue;
    const Material m(E, nu);
    std::printf("note: nu%d = %g is close to 1/2, where %s locks (lambda / mu = %.3g): expect the L2 error and "
                "the contact pressure to suffer (chapter 2's notes; README.md, \"Hard cases\")\n",
                body, nu, o.degree == 2 ? "P2" : "P1", m.lambda() / m.mu());
  }
}

TwoBodyGeometry two_body_geometry(const TwoBodyOptions& o, int n1, double aspect) {
  TwoBodyGeometry g;
  g.L = o.L;
  g.H1 = o.H1;
  g.H2 = o.H2;
  g.jitter = o.jitter;
  g.degree = o.degree;
  g.n1 = n1;
  g.n2 = std::max(2, static_cast<int>(std::lround(g.n1 / o.h_ratio)));
  g.m1 = std::max(1, static_cast<int>(std::lround(aspect * g.n1 * o.H1 / o.L)));
  g.m2 = std::max(1, static_cast<int>(std::lround(aspect * g.n2 * o.H2 / o.L)));
  return g;
}

TwoBodyGeometry level_geometry(const BilateralStudyOptions& o, int level) {
  return two_body_geometry(o, o.n0 << level, o.aspect);
}

BilateralOptions solver_options(const BilateralStudyOptions& o, Matching matching) {
  BilateralOptions b;
  b.matching = matching;
  b.nonmortar = o.nonmortar - 1;
  b.solver = parse_saddle_solver(o.saddle_solver);
  return b;
}

// Pressure errors relative to the norm of the exact p: the L2 ones (whole, interior, ends,
// best approximation) to ||p||_{L2}, so that the squares of interior and ends still add up to
// the whole; the mesh-dependent ones to |Gamma_c|^{1/2} ||p||_{L2} (PressureErrors::norm_hminus).
Row BilateralLevel::row() const {
  const PressureErrors& p = pressure_errors;
  return {{"h", std::max(h1, h2)},
          {"h1", h1},
          {"h2", h2},
          {"dofs", static_cast<double>(bodies.num_dofs())},
          {"multipliers", static_cast<double>(solution.lambda.size())},
          {"time_s", time_s},
          {"limit_s", limit_s},
          {"err_energy", err_energy},
          {"err_l2", err_l2},
          {"err_pressure", p.l2 / p.norm_l2},
          {"err_pressure_interior", p.l2_interior / p.norm_l2},
          {"err_pressure_ends", p.l2_ends / p.norm_l2},
          {"err_pressure_hminus", p.hminus / p.norm_hminus},
          {"err_pressure_best", p.best_l2 / p.norm_l2},
          {"err_pressure_best_interior", p.best_l2_interior / p.norm_l2},
          {"err_pressure_best_hminus", p.best_hminus / p.norm_hminus},
          {"err_jump", err_jump}};
}

BilateralLevel solve_manufactured_level(const ManufacturedContact& exact, const TwoBodyGeometry& g,
                                        const BilateralOptions& options, const BilateralSolver& solve) {
  TwoBodies bodies = make_two_bodies(g, exact.material(0), exact.material(1));
  BilateralLevel r{std::move(bodies), {}, {}, {}};
  // Timed: loads, stiffness, constraints, solve, pressure, jump, all but the mesh; beside the
  // limit of the same K, the two interleaved (linalg/physical_limit.hpp).
  SceneData scene;
  r.timing = time_against_limit(
      [&] {
        {
          const ProfilePhase phase("scene (loads)");
          scene = manufactured_scene(r.bodies, exact);
        }
        r.solution = solve(r.bodies, scene, options);
      },
      [&] { return two_body_limit_matrix(r.bodies, scene); });
  r.time_s = r.timing.time_s;
  r.limit_s = r.timing.limit_s;

  ErrorNorms norms;
  for (int l = 0; l < 2; ++l)
    norms += error_norms(r.bodies.body(l).mesh, r.bodies.body(l).material,
                         r.bodies.part(r.solution.u, l), exact.exact(l));
  r.err_energy = norms.relative_energy();  // the broken energy norm over both bodies
  r.err_l2 = norms.relative_l2();
  r.pressure = r.solution.pressure;
  r.jump = r.solution.jump;
  const auto p = [&](double x) { return exact.pressure(x); };
  const auto c = [&](double x) { return exact.normal_displacement(x); };
  r.pressure_errors = pressure_errors(r.solution.gamma, r.pressure, p);
  // the exact jump is zero: measure [u_h.n] against the size of u.n itself
  r.err_jump = l2_error(r.jump, [](double) { return 0.0; }) / l2_norm(r.jump, c);
  r.h1 = r.solution.gamma.nonmortar == 0 ? r.solution.gamma.nonmortar_trace.max_element_length()
                                         : r.solution.gamma.mortar_trace.max_element_length();
  r.h2 = r.solution.gamma.nonmortar == 0 ? r.solution.gamma.mortar_trace.max_element_length()
                                         : r.solution.gamma.nonmortar_trace.max_element_length();
  return r;
}

PatchTestResult run_patch_test(const BilateralStudyOptions& o, Matching matching, const BilateralSolver& solve) {
  TwoBodyGeometry g;
  g.L = o.L;
  g.H1 = o.H1;
  g.H2 = o.H2;
  g.n1 = 6;   // h2 / h1 = 3 / 7: n2 = 14; the traces share only the ends and x = L / 2
  g.n2 = 14;
  g.m1 = 3;
  g.m2 = 7;
  g.jitter = o.jitter;
  g.degree = o.degree;
  const TwoBodies bodies = make_two_bodies(g, Material(o.E1, o.nu1), Material(o.E2, o.nu2));
  const double p = 0.01 * std::min(o.E1, o.E2);
  const SceneData scene = patch_test_scene(bodies, p);
  // Body 1 is held in y only through the constraints, so K alone is singular: the multipliers-
  // first route (schur), which factorizes K alone, cannot take it; elimination can.
  BilateralOptions options = solver_options(o, matching);
  if (options.solver == SaddleSolver::schur) options.solver = SaddleSolver::elimination;
  const BilateralSolution s = solve(bodies, scene, options);

  PatchTestResult out;
  for (int l = 0; l < 2; ++l) {
    const Mesh& mesh = bodies.body(l).mesh;
    const auto stress = element_stresses(mesh, bodies.body(l).material, bodies.part(s.u, l));
    InterfaceCurve& curve = l == 0 ? out.sigma22_body1 : out.sigma22_body2;
    for (std::size_t t = 0; t < stress.size(); ++t) {
      out.rel_error = std::max(out.rel_error, std::fabs(stress[t][1] + p) / p);
      const auto& tri = mesh.triangles[t];
      const Eigen::Vector2d centroid = (mesh.nodes[tri[0]] + mesh.nodes[tri[1]] + mesh.nodes[tri[2]]) / 3;
      const bool touches_gamma = std::fabs(mesh.nodes[tri[0]].y()) < 1e-12 * o.L ||
                                 std::fabs(mesh.nodes[tri[1]].y()) < 1e-12 * o.L ||
                                 std::fabs(mesh.nodes[tri[2]].y()) < 1e-12 * o.L;
      if (touches_gamma) {
        curve.x.push_back(centroid.x());
        curve.value.push_back(stress[t][1] / p);
      }
    }
  }
  return out;
}

}  // namespace mortar

namespace mortar {

BilateralStudy run_bilateral_study(const BilateralStudyOptions& o, const ManufacturedContact& exact,
                                   const BilateralMethod& method) {
  BilateralStudy study;
  study.matching = method.matching;
  const BilateralOptions solver = solver_options(o, method.matching);
  for (int level = 0; level < o.levels; ++level) {
    auto solved = std::make_unique<BilateralLevel>(
        solve_manufactured_level(exact, level_geometry(o, level), solver, method.solve));
    Row row = solved->row();
    if (method.more_columns) method.more_columns(*solved, exact, row);
    study.table.add(row);
    (level == 0 ? study.coarsest : study.finest) = std::move(solved);
  }
  const bool own_pointwise = method.matching == Matching::pointwise;
  study.patch_pointwise = run_patch_test(o, Matching::pointwise, own_pointwise ? method.solve : solve_bilateral);
  study.patch_integral = run_patch_test(o, Matching::integral, own_pointwise ? solve_bilateral : method.solve);
  return study;
}

void write_bilateral_outputs(const BilateralStudyOptions& o, const OptionParser& parser, const BilateralStudy& study,
                             const JsonObject& extra) {
  const BilateralLevel& f = *study.finest;
  const bool integral = study.matching == Matching::integral;
  JsonObject results;
  results.set("h1_m", f.h1)
      .set("h2_m", f.h2)
      .set("dofs", f.bodies.num_dofs())
      .set("multipliers", static_cast<int>(f.solution.lambda.size()))
      .set("err_energy", f.err_energy)
      .set("err_l2", f.err_l2)
      .set("err_pressure", f.pressure_errors.l2 / f.pressure_errors.norm_l2)
      .set("err_pressure_hminus", f.pressure_errors.hminus / f.pressure_errors.norm_hminus)
      .set("err_pressure_best", f.pressure_errors.best_l2 / f.pressure_errors.norm_l2)
      .set("err_jump", f.err_jump)
      .set("patch_test_rel_error", (integral ? study.patch_integral : study.patch_pointwise).rel_error)
      .set(integral ? "patch_test_rel_error_pointwise" : "patch_test_rel_error_integral",
           (integral ? study.patch_pointwise : study.patch_integral).rel_error)
      .set("matching", matching_name(study.matching))
      .set("saddle_solver", o.saddle_solver);
  add_timing(results, f.timing);
  results.merge(extra);
  study.table.write_csv(o.out + "/convergence.csv");
  study.table.local_rates().write_csv(o.out + "/local_rates.csv", true);  // level to level
  write_summary(o.out + "/summary.json", parser, study.rates(), results);
  if (o.profile) report_profile(f.timing, o.out);
}

void write_bilateral_pictures(const BilateralStudyOptions& o, const BilateralStudy& study) {
  const std::string name = matching_name(study.matching) + " matching, " + mesh_label(o);
  const BilateralLevel& c = *study.coarsest;
  const bool run = !o.no_plot;
  write_figure(o.out, "meshes", two_body_meshes(c.bodies, c.solution.gamma, study.matching, name), run);
  write_figure(o.out, "deformed", deformed_two_bodies(c.bodies, c.solution.u, name + ", coarsest level"), run);
  const BilateralLevel& f = *study.finest;
  write_two_body_vtu(o.out, f.bodies, f.solution.u, f.pressure, f.jump);
}

}  // namespace mortar
