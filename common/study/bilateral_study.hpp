// The convergence study shared by chapters 3 and 4: the manufactured two-material solution on
// a sequence of nonmatching meshes, and the patch test, for one matching at a time.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/linalg/memory_estimate.hpp"
#include "common/linalg/physical_limit.hpp"
#include "common/contact/bilateral_contact.hpp"
#include "common/contact/contact_fields.hpp"
#include "common/study/convergence_study.hpp"
#include "common/study/json_writer.hpp"
#include "common/fem/errors.hpp"
#include "common/contact/manufactured_contact.hpp"
#include "common/study/options.hpp"
#include "common/contact/pressure_norms.hpp"

namespace mortar {

// The options every two-body chapter (3, 4, 5) shares: meshes along Gamma_c, materials, sizes.
struct TwoBodyOptions {
  double h_ratio = 1.5;  // h2 / h1
  int nonmortar = 1;     // 1 or 2, as the user counts bodies
  double E1 = 1, nu1 = 0.3, E2 = 3, nu2 = 0.25;
  double L = 1, H1 = 0.5, H2 = 0.5;
  double jitter = 0;
  int degree = 1;  // q of both bodies: set by the chapter (7: P2), not an option
};
void add_two_body_options(OptionParser& parser, TwoBodyOptions& o);
// "h_2/h_1 = 1.5, non-mortar body 1": the mesh options a figure's title carries, so that runs
// with other options never give figures with the same title.
std::string mesh_label(const TwoBodyOptions& o);
// Unilateral and frictional contact (chapters 5 and 8): the non-mortar side carries the
// multipliers, and on a body more than 10 times stiffer than the other its nodal conditions see
// the soft body's motion only through their coarse image: the pressure oscillates from node to
// node (chapter 5, Hertz, E1 = 1e8 E2: L2 pressure errors 86%, 76%, 92% on levels 3-5, against
// 12%, 4.4%, 2.8% the other way round) and chapter 8's Newton method cycles. Unless
// --nonmortar is given, the softer body becomes the non-mortar side, with a note; a stiffer
// non-mortar side chosen by the user gets a warning.
void choose_softer_nonmortar(const OptionParser& parser, TwoBodyOptions& o);
// Refuses E1 / E2 beyond 1e10 either way, before any work: the soft body's equations then sit
// more than 10 of the 16 digits below the stiff body's, and the solvers stop telling them from
// round-off (ch04 --quick: the LU calls [K B^T; B 0] singular from 1e11, CHOLMOD calls K
// singular at 1e14). Up to 1e10 every solver gives the same rates to 8 digits.
void check_stiffness_ratio(const OptionParser& parser, const TwoBodyOptions& o);

struct BilateralStudyOptions : TwoBodyOptions {
  int n0 = 12;           // body-1 elements along Gamma_c on the coarsest level
  int levels = 6;
  int threads = mortar::default_solver_threads();
  double aspect = 1;  // cell width / cell height
  std::string saddle_solver = "schur";
  std::string pressure_ends = "sloped";  // the manufactured sigma_N: sloped (p'(L) != 0) or flat
  std::string out;
  bool quick = false;
  bool no_plot = false;
  bool profile = false;  // print where the finest level's time goes
};

// The memory of the finest level: its sparse solve and the dense blocks the saddle-point
// solver builds on Gamma_c (memory_estimate.hpp).
std::vector<MemoryPart> bilateral_memory_parts(const BilateralStudyOptions& o);
// What a chapter runs besides the bilateral study (chapter 6: its Hertz part), from the options.
using MoreMemoryParts = std::function<std::vector<MemoryPart>(const BilateralStudyOptions&)>;

// Declares every option of chapters 3 and 4, parses, checks the combinations and the memory
// of every part (`more_parts` too), makes --out.
void parse_bilateral_options(OptionParser& parser, BilateralStudyOptions& o, int argc, char** argv,
                             const MoreMemoryParts& more_parts = {});

// The manufactured solution --pressure-ends asks for: sloped_profile (sigma_N' != 0 at x = L,
// which caps the L2 best approximation in M_h^1 at h^{3/2}) or flat_ends_profile
// (sigma_N' = 0 at both ends, so the interior rate shows).
ManufacturedContact manufactured_solution(const BilateralStudyOptions& o);

// Refuses (status 2, naming the option) meshes that the options would make degenerate at
// the coarsest (n1 = n0) or finest level: body 2 with fewer than 2 elements before its
// max(2, .) floor, which then stays unrefined and makes rates meaningless; cells longer than
// 20:1 either way, whether from --aspect or from --L against --H1/--H2 (beyond it the solves
// stop converging and say nothing).
void check_two_body_meshes(const OptionParser& parser, const TwoBodyOptions& o, int n0, int levels, double aspect);
// A note on stdout when a body is nearly incompressible (nu > 0.49), where P1 locks: the run
// goes on (chapter 2 shows locking on purpose), but nobody should read its pressure unwarned.
void note_nearly_incompressible(const TwoBodyOptions& o);

// Meshes with n1 body-1 elements along Gamma_c: n2 = max(2, round(n1 / h_ratio)), m_l rows
// with cells of width / height = aspect. Chapters 3-5 all build their levels this way.
TwoBodyGeometry two_body_geometry(const TwoBodyOptions& o, int n1, double aspect);
// The meshes of one level of chapters 3 and 4: n1 = n0 2^level.
TwoBodyGeometry level_geometry(const BilateralStudyOptions& o, int level);
BilateralOptions solver_options(const BilateralStudyOptions& o, Matching matching);

struct BilateralLevel {
  TwoBodies bodies;
  BilateralSolution solution;
  InterfaceCurve pressure, jump;  // solution.pressure and solution.jump
  double h1 = 0, h2 = 0;
  double time_s = 0, limit_s = 0;
  TimedLevel timing{};  // both, with their spread, phases and memory peaks
  double err_energy = 0, err_l2 = 0, err_jump = 0;
  PressureErrors pressure_errors{};  // absolute; row() divides by the norms of the exact p
  Row row() const;
};

// One bilateral solve on given bodies and loads: from K to (u_h, lambda_h), the pressure and
// the jump. Chapters 3 and 4 each write their own, the steps of their matching in order
// (level.cpp); solve_bilateral is the library's, for either matching.
using BilateralSolver =
    std::function<BilateralSolution(const TwoBodies&, const SceneData&, const BilateralOptions&)>;

// A chapter's method: its matching (named in the outputs) and its own solve.
// A chapter may add columns of its own to each level's row (chapter 6: the error of the dual
// multiplier as a function).
struct BilateralMethod {
  Matching matching = Matching::integral;
  BilateralSolver solve = solve_bilateral;
  std::function<void(const BilateralLevel&, const ManufacturedContact&, Row&)> more_columns;
};

// One level of the study: the meshes, the manufactured loads, the solve (timed with the loads),
// the physical limit, then the errors of u, lambda_h and [u_h.n] against the exact solution.
BilateralLevel solve_manufactured_level(const ManufacturedContact& exact, const TwoBodyGeometry& g,
                                        const BilateralOptions& options,
                                        const BilateralSolver& solve = solve_bilateral);

// The patch test on meshes with h2 / h1 = 3 / 7: max over all triangles of
// |sigma_22 + p| / p, and sigma_22 in the triangles along Gamma_c for the figure.
struct PatchTestResult {
  double rel_error = 0;
  InterfaceCurve sigma22_body1, sigma22_body2;  // element centroids' x and sigma_22 / p
};
PatchTestResult run_patch_test(const BilateralStudyOptions& o, Matching matching,
                               const BilateralSolver& solve = solve_bilateral);

// The whole study of one chapter: every level of the manufactured solution solved by the
// chapter's own solve (one line each as it finishes), then the patch test with both matchings
// on the same meshes, the chapter's matching by the chapter's solve, the other by
// solve_bilateral.
struct BilateralStudy {
  Matching matching = Matching::integral;
  ConvergenceTable table;
  std::unique_ptr<BilateralLevel> coarsest, finest;
  PatchTestResult patch_pointwise, patch_integral;
  std::map<std::string, double> rates() const { return table.rates(); }
};
BilateralStudy run_bilateral_study(const BilateralStudyOptions& o, const ManufacturedContact& exact,
                                   const BilateralMethod& method);

// convergence.csv, its level-to-level rates local_rates.csv, and summary.json; results hold the
// finest level, the patch test of this chapter's matching (patch_test_rel_error) and of the
// other one.
// `extra` adds a chapter's own keys to results.
void write_bilateral_outputs(const BilateralStudyOptions& o, const OptionParser& parser, const BilateralStudy& study,
                             const JsonObject& extra = {});

// Pictures of the problem (common/study/two_body_pictures.hpp): meshes.png and deformed.png of
// the coarsest level, then body1.vtu, body2.vtu and contact.vtu of the finest level.
void write_bilateral_pictures(const BilateralStudyOptions& o, const BilateralStudy& study);

}  // namespace mortar
