// The chapter programs end to end: bad input is refused with status 2 and a message naming
// the option; small runs keep the output contract and show the rates theory predicts.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "hertz_best_approximation.hpp"
#include "program_run.hpp"

namespace {

ProgramRun run(const std::string& command) { return run_command(command); }

std::string out_dir(const std::string& name) {
  const std::string dir = std::string(WORK_DIR) + "/" + name;
  std::filesystem::remove_all(dir);
  return dir;
}

// The whole text of a file ("" when it cannot be read).
std::string file_text(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// Reads "section": { ... "key": number ... } from a summary.json written by write_summary.
double summary_value(const std::string& dir, const std::string& section, const std::string& key) {
  const std::string json = file_text(dir + "/summary.json");
  const auto start = json.find("\"" + section + "\": {");
  if (start == std::string::npos) return std::nan("");
  const auto end = json.find('}', start);
  const std::string block = json.substr(start, end - start);
  std::smatch m;
  if (!std::regex_search(block, m, std::regex("\"" + key + "\": ([-+0-9.eE]+)"))) return std::nan("");
  return std::stod(m[1]);
}


}  // namespace



// Malformed or out-of-range input: status 2, a message naming the option, nothing written.
// Each program gets the common cases plus its own; every list has at least 20.
struct BadInput {
  std::string args, option;
};

std::vector<BadInput> common_bad_inputs() {
  return {{"--bogus 1", "bogus"},          {"--n0", "n0"},
          {"--n0 abc", "n0"},              {"--n0 nan", "n0"},
          {"--n0 inf", "n0"},              {"--n0 -4", "n0"},
          {"--n0 0", "n0"},                {"--n0 2.5", "n0"},
          {"--n0 1e400", "n0"},            {"--levels 0", "levels"},
          {"--levels -1", "levels"},       {"--levels 1000000", "levels"},
          {"--levels --no-plot", "levels"}, {"--jitter -0.1", "jitter"},
          {"--jitter nan", "jitter"},      {"--jitter 0.9", "jitter"},
          {"--no-plot=1", "no-plot"},      {"--out /proc/forbidden/x", "out"},
          {"--out", "out"}};
}

void expect_all_refused(const std::string& program, std::vector<BadInput> cases,
                        const std::vector<BadInput>& own) {
  cases.insert(cases.end(), own.begin(), own.end());
  ASSERT_GE(cases.size(), 20u);
  const std::string dir = std::string(WORK_DIR) + "/refused";
  for (const BadInput& c : cases) {
    std::filesystem::remove_all(dir);
    const std::string out = c.option == "out" ? "" : " --out " + dir;
    const ProgramRun r = run(program + out + " " + c.args);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find("--" + c.option), std::string::npos)
        << "the message for '" << c.args << "' does not name --" << c.option << ":\n" << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir)) << "'" << c.args << "' left output behind";
  }
}

TEST(Programs, ch01_refuses_malformed_input) {
  expect_all_refused(CH01, common_bad_inputs(),
                     {{"--n0 1", "n0"}, {"--h-ratio 0", "h-ratio"}, {"--h-ratio -3/2", "h-ratio"},
                      {"--h-ratio 1/0", "h-ratio"}, {"--L 0", "L"}, {"--L -1", "L"}, {"--L 1e-160", "L"},
                      {"--trace wiggly", "trace"}, {"--levels 2", "levels"}});
}

TEST(Programs, ch02_refuses_malformed_input) {
  expect_all_refused(CH02, common_bad_inputs(),
                     {{"--E -1", "E"}, {"--E 0", "E"}, {"--E inf", "E"}, {"--E 0x10", "E"},
                      {"--nu 0.5", "nu"}, {"--nu 0.7", "nu"}, {"--nu -1", "nu"}, {"--nu nan", "nu"},
                      {"--n0 1024 --levels 5", "levels"}, {"--spd-solver qr", "spd-solver"},
                      {"--E 1.7e308", "E"}});
}

TEST(Programs, ch03_and_ch04_refuse_malformed_input) {
  const std::vector<BadInput> own = {
      {"--n0 1", "n0"}, {"--E1 -1", "E1"}, {"--E2 0", "E2"}, {"--E1 nan", "E1"}, {"--nu1 0.5", "nu1"},
      {"--nu2 1", "nu2"}, {"--h-ratio 0", "h-ratio"}, {"--h-ratio -3/2", "h-ratio"},
      {"--h-ratio inf", "h-ratio"}, {"--nonmortar 3", "nonmortar"}, {"--nonmortar 0", "nonmortar"},
      {"--n0 4096 --levels 6", "levels"}, {"--saddle-solver cg", "saddle-solver"}, {"--aspect 0", "aspect"},
      {"--H1 -1", "H1"}, {"--L 1e-6 --H1 536.870912 --H2 858.9934592 --n0 4", "levels"},
      {"--pressure-ends steep", "pressure-ends"}, {"--pressure-ends", "pressure-ends"},
      // degenerate meshes: 1e5:1 cells through --L, body 2 held at its floor of 2 elements
      {"--L 1e6", "L"}, {"--H2 1e-4", "L"}, {"--h-ratio 100", "h-ratio"}, {"--n0 2 --h-ratio 3/2", "h-ratio"},
      // E beyond 1e300: the Lame constants overflow
      {"--E1 1.7e308 --E2 1.7e308", "E1"}};
  expect_all_refused(CH03, common_bad_inputs(), own);
  expect_all_refused(CH04, common_bad_inputs(), own);
}

TEST(Programs, ch05_refuses_malformed_input) {
  expect_all_refused(CH05, common_bad_inputs(),
                     {{"--scene moon", "scene"}, {"--matching glue", "matching"}, {"--solver newton", "solver"},
                      {"--acceleration heavy", "acceleration"}, {"--rho -1", "rho"}, {"--rho nan", "rho"},
                      {"--tol 0", "tol"}, {"--tol 1", "tol"}, {"--tol 1e-300", "tol"}, {"--R 0", "R"}, {"--delta nan", "delta"},
                      {"--delta inf", "delta"}, {"--E1 -2", "E1"}, {"--nu2 0.5", "nu2"}, {"--h-ratio 0", "h-ratio"},
                      {"--n0 4096 --levels 8", "levels"},
                      // degenerate scenes: an imposed displacement beyond the body's height, cells of
                      // 1e5:1, body 2 unrefined, E where B K^-1 B^T leaves the range of double
                      {"--delta 1.5", "delta"}, {"--delta -1", "delta"}, {"--L 1e6", "L"},
                      {"--h-ratio 50", "h-ratio"}, {"--E1 1e-160", "E1"}, {"--E2 1e300", "E2"}});
}

TEST(Programs, ch01_mortar_conserves_the_integral_and_pointwise_does_not) {
  const std::string dir = out_dir("ch01");
  const ProgramRun r = run(std::string(CH01) + " --quick --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_LT(summary_value(dir, "results", "mortar_integral_rel_error"), 1e-12);
  EXPECT_GT(summary_value(dir, "results", "pointwise_integral_rel_error"), 1e-4);
  EXPECT_TRUE(std::filesystem::exists(dir + "/cases.csv"));
}

// P1 theory: energy error O(h), L2 error O(h^2). On the small levels 16..64 cells the fitted
// rates are already within 0.05 of the theory (1.00 and 1.99 measured); the band is 0.1.
TEST(Programs, ch02_energy_and_l2_rates_match_p1_theory_on_small_levels) {
  for (const char* solver : {"simplicial_ldlt", "cholmod"}) {
    const std::string dir = out_dir(std::string("ch02_") + solver);
    const ProgramRun r = run(std::string(CH02) + " --n0 8 --levels 4 --no-plot --spd-solver " + solver + " --out " + dir);
    if (std::string(solver) == "cholmod" && r.status == 2 &&
        r.output.find("no CHOLMOD") != std::string::npos)
      continue;  // a build without SuiteSparse
    ASSERT_EQ(r.status, 0) << r.output;
    const double energy = summary_value(dir, "rates", "err_energy");
    const double l2 = summary_value(dir, "rates", "err_l2");
    EXPECT_NEAR(energy, 1.0, 0.1) << solver << ": observed energy rate " << energy;
    EXPECT_NEAR(l2, 2.0, 0.1) << solver << ": observed L2 rate " << l2;
    EXPECT_GT(summary_value(dir, "results", "limit_ratio"), 0.0);
  }
}

TEST(Programs, ch02_jittered_meshes_keep_the_rates) {
  const std::string dir = out_dir("ch02_jitter");
  const ProgramRun r = run(std::string(CH02) + " --n0 8 --levels 4 --jitter 0.3 --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NEAR(summary_value(dir, "rates", "err_energy"), 1.0, 0.1);
  EXPECT_NEAR(summary_value(dir, "rates", "err_l2"), 2.0, 0.15);
}


TEST(Programs, ch04_passes_the_patch_test_and_ch03_fails_it_on_the_same_meshes) {
  const std::string d3 = out_dir("ch03"), d4 = out_dir("ch04");
  const ProgramRun r3 = run(std::string(CH03) + " --quick --no-plot --out " + d3);
  const ProgramRun r4 = run(std::string(CH04) + " --quick --no-plot --out " + d4);
  ASSERT_EQ(r3.status, 0) << r3.output;
  ASSERT_EQ(r4.status, 0) << r4.output;
  EXPECT_LT(summary_value(d4, "results", "patch_test_rel_error"), 1e-10);
  EXPECT_GT(summary_value(d3, "results", "patch_test_rel_error"), 1e-4);
  EXPECT_GT(summary_value(d4, "results", "limit_ratio"), 0.0);
}

// Theorem 4.2: O(h) in the energy norm for integral matching, and with the inf-sup condition
// O(h) for the multiplier in H^{-1/2}, here its mesh-dependent stand-in. On levels of 12..48
// body-1 elements the fitted rates are 0.99-1.00 (energy) and 1.5 or more (pressure in
// H^{-1/2}_h) for every ratio measured (band: >= 0.9).
TEST(Programs, ch04_energy_rate_is_one_for_nonnested_and_nested_ratios) {
  for (const char* ratio : {"3/2", "1/3", "3"}) {
    const std::string dir = out_dir("ch04_rates");
    const ProgramRun r = run(std::string(CH04) + " --n0 12 --levels 3 --no-plot --h-ratio " + ratio + " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_GE(summary_value(dir, "rates", "err_energy"), 0.9) << "h2/h1 = " << ratio;
    EXPECT_GE(summary_value(dir, "rates", "err_pressure"), 0.9) << "h2/h1 = " << ratio;
    EXPECT_GE(summary_value(dir, "rates", "err_pressure_hminus"), 0.9) << "h2/h1 = " << ratio;
    for (const char* key : {"err_pressure_hminus", "err_pressure_best"})
      EXPECT_GT(summary_value(dir, "results", key), 0.0) << key << ", h2/h1 = " << ratio;
  }
}

// Quasi-optimality in L2 on small runs (--quick: 6, 12, 24 non-mortar elements): the computed
// lambda_h against the L2 best approximation of -sigma_N in M_h^1 (never below it: lambda_h
// is in M_h^1). Measured ratios at the finest level: 1.34 (h2/h1 = 3/2), 1.25 (2/3), 1.31
// (1/3), 1.12 (3/2, body 2 non-mortar); band: at most 2. Where the non-mortar side is three
// times finer than the mortar side the multipliers outrun what the coarse side can transmit:
// 4.58 (h2/h1 = 3) and 24.9 (1/3, body 2 non-mortar); band: above 3.
TEST(Programs, ch04_pressure_is_near_its_best_approximation_unless_the_nonmortar_side_is_finer) {
  struct Case {
    std::string options;
    bool quasi_optimal;
  };
  for (const Case& c : {Case{"--h-ratio 3/2", true}, Case{"--h-ratio 2/3", true}, Case{"--h-ratio 1/3", true},
                        Case{"--h-ratio 3/2 --nonmortar 2", true}, Case{"--h-ratio 3", false},
                        Case{"--h-ratio 1/3 --nonmortar 2", false}}) {
    const std::string dir = out_dir("ch04_best");
    const ProgramRun r = run(std::string(CH04) + " --quick --no-plot " + c.options + " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
    const double ratio = summary_value(dir, "results", "err_pressure") / summary_value(dir, "results", "err_pressure_best");
    EXPECT_GE(ratio, 1.0) << c.options;
    if (c.quasi_optimal) {
      EXPECT_LE(ratio, 2.0) << c.options;
    } else {
      EXPECT_GT(ratio, 3.0) << c.options;
    }
  }
}


TEST(Programs, ch06_refuses_malformed_input) {
  expect_all_refused(CH06, common_bad_inputs(),
                     {{"--n0 1", "n0"}, {"--E1 -1", "E1"}, {"--E2 0", "E2"}, {"--nu1 0.5", "nu1"},
                      {"--nu2 0.7", "nu2"}, {"--h-ratio 0", "h-ratio"}, {"--h-ratio inf", "h-ratio"},
                      {"--nonmortar 3", "nonmortar"}, {"--hertz-start warm", "hertz-start"},
                      {"--hertz-start", "hertz-start"}, {"--no-hertz=yes", "no-hertz"}, {"--aspect 0", "aspect"}});
}

// One column of a CSV file with a header row.
std::vector<double> csv_column(const std::string& path, const std::string& name) {
  std::ifstream in(path);
  std::string line, cell;
  std::getline(in, line);
  std::istringstream header(line);
  int index = -1;
  for (int k = 0; std::getline(header, cell, ','); ++k)
    if (cell == name) index = k;
  std::vector<double> values;
  while (index >= 0 && std::getline(in, line)) {
    std::istringstream row(line);
    for (int k = 0; std::getline(row, cell, ','); ++k)
      if (k == index) values.push_back(std::stod(cell));
  }
  return values;
}

// Chapter 6 on levels of 12, 24 and 48 non-mortar elements: D diagonal to round-off, the patch
// test to round-off, the energy rate of Theorem 4.2 (measured 0.97-1.00 for these ratios; band
// >= 0.9, as chapter 4's), the dual function O(h) in L2, and the Hertz part reporting both bases.
TEST(Programs, ch06_dual_basis_keeps_the_rate_and_passes_the_patch_test) {
  for (const char* ratio : {"3/2", "2/3", "1/3", "3"}) {
    const std::string dir = out_dir("ch06_rates");
    const ProgramRun r =
        run(std::string(CH06) + " --n0 12 --levels 3 --no-plot --no-compare --h-ratio " + ratio + " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_GE(summary_value(dir, "rates", "err_energy"), 0.9) << "h2/h1 = " << ratio;
    EXPECT_LT(summary_value(dir, "results", "d_offdiagonal_max"), 1e-13) << "h2/h1 = " << ratio;
    EXPECT_LT(summary_value(dir, "results", "patch_test_rel_error"), 1e-10) << "h2/h1 = " << ratio;
    EXPECT_GT(summary_value(dir, "results", "patch_test_rel_error_pointwise"), 1e-4) << "h2/h1 = " << ratio;
    EXPECT_GT(summary_value(dir, "results", "limit_ratio"), 0.0);
    EXPECT_GE(summary_value(dir, "results", "hertz_iterations_dual"), 1.0);
    EXPECT_GE(summary_value(dir, "results", "hertz_iterations_standard"), 1.0);
    EXPECT_EQ(summary_value(dir, "results", "hertz_complementarity_residual_dual"), 0.0);
    EXPECT_LT(summary_value(dir, "rates", "err_pressure_function"), 1.2) << "h2/h1 = " << ratio;
    EXPECT_GT(summary_value(dir, "rates", "err_pressure_function"), 0.8) << "h2/h1 = " << ratio;
  }
}

// The standard basis beside it on the same meshes (standard.csv): the energy errors of the two
// bases agree to 1% (measured: 0.01-0.06%), the pressure errors do not (the dual function is
// only O(h) in L2).
TEST(Programs, ch06_dual_and_standard_energy_errors_agree) {
  const std::string dir = out_dir("ch06_compare");
  const ProgramRun r = run(std::string(CH06) + " --quick --no-plot --no-hertz --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const auto dual = csv_column(dir + "/convergence.csv", "err_energy");
  const auto standard = csv_column(dir + "/standard.csv", "err_energy");
  ASSERT_EQ(dual.size(), 3u);
  ASSERT_EQ(standard.size(), 3u);
  for (std::size_t k = 0; k < dual.size(); ++k) EXPECT_NEAR(dual[k] / standard[k], 1.0, 0.01) << "level " << k;
  const auto function = csv_column(dir + "/convergence.csv", "err_pressure_function");
  const auto pressure = csv_column(dir + "/standard.csv", "err_pressure");
  EXPECT_GT(function.back(), 2 * pressure.back());
  EXPECT_FALSE(std::filesystem::exists(dir + "/hertz.csv"));
}

// The Hertz part of chapter 6 is pressed by a displacement: u does not depend on the unit of
// E and the force is proportional to it, for every E the options accept. Its solvers work on
// S = B K^-1 B^T ~ 1/E: unscaled they stopped at E = 1e-156 ("the residual is inf") and at
// 1e-160 gave a force 0.71% off.
TEST(Programs, ch06_hertz_force_is_proportional_to_E_from_1e_minus300_to_1e300) {
  const std::string unit = out_dir("ch06_hertz_E_1");
  ASSERT_EQ(run(std::string(CH06) + " --quick --no-plot --no-compare --out " + unit).status, 0);
  for (const std::string E : {"1e-300", "1e-160", "1e-156", "1e150", "1e300"}) {
    const std::string dir = out_dir("ch06_hertz_E_" + E);
    const ProgramRun r = run(std::string(CH06) + " --quick --no-plot --no-compare --E1 " + E + " --E2 " + E +
                             " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
    for (const char* key : {"hertz_total_force_standard", "hertz_total_force_dual"}) {
      const double f1 = summary_value(unit, "results", key);
      ASSERT_GT(f1, 0.0);
      EXPECT_NEAR(summary_value(dir, "results", key) / std::stod(E), f1, 1e-9 * f1) << key << ", E = " << E;
    }
  }
}

TEST(Programs, ch05_hertz_both_solvers_agree_and_report_every_key) {
  const std::string dp = out_dir("ch05_pdas"), du = out_dir("ch05_uzawa");
  const ProgramRun p = run(std::string(CH05) + " --quick --no-compare --no-plot --solver pdas --out " + dp);
  const ProgramRun u = run(std::string(CH05) + " --quick --no-compare --no-plot --solver uzawa --out " + du);
  ASSERT_EQ(p.status, 0) << p.output;
  ASSERT_EQ(u.status, 0) << u.output;
  const double fp = summary_value(dp, "results", "total_force"), fu = summary_value(du, "results", "total_force");
  EXPECT_GT(fp, 0.0);
  EXPECT_NEAR(fu, fp, 1e-5 * fp);
  for (const char* key : {"contact_half_width", "max_pressure", "iterations", "complementarity_residual",
                          "hertz_half_width_rel_error", "hertz_peak_pressure_rel_error", "limit_ratio",
                          "hertz_discretization_error", "hertz_model_error", "reference_rel_error_estimate"})
    EXPECT_TRUE(std::isfinite(summary_value(dp, "results", key))) << key;
  EXPECT_LE(summary_value(du, "results", "complementarity_residual"), 1e-8);
  EXPECT_TRUE(std::filesystem::exists(dp + "/contact.csv"));
}

// The Hertz scene reports two numbers: the discretization error (finest level against the
// finite-body reference) and the model error (the reference against half-space Hertz). Both
// must be there and finite, and the reference must be finer than what it measures: its own
// estimated error (the change from cells twice as long) below a third of the discretization
// error, and its contact edges within one element of the finest level's discrete contact set.
TEST(Programs, ch05_hertz_reports_discretization_and_model_error_apart) {
  const std::string dir = out_dir("ch05_hertz_split");
  const ProgramRun r = run(std::string(CH05) + " --quick --no-compare --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const double discretization = summary_value(dir, "results", "hertz_discretization_error");
  const double model = summary_value(dir, "results", "hertz_model_error");
  const double reference = summary_value(dir, "results", "reference_rel_error_estimate");
  ASSERT_TRUE(std::isfinite(discretization) && std::isfinite(model) && std::isfinite(reference)) << r.output;
  EXPECT_GT(model, 0.0);
  EXPECT_GT(reference, 0.0);
  EXPECT_LT(reference, discretization / 3) << r.output;
  EXPECT_NE(r.output.find("model error (reference against half-space Hertz"), std::string::npos) << r.output;
  const std::string json = file_text(dir + "/summary.json");
  EXPECT_NE(json.find("\"reference_edges_within_one_element\": true"), std::string::npos) << json;
}

// The reference's estimated error is honest: a reference twice as fine (one more level, and
// the reference is tied to the finest level) moves its force, half-width and peak pressure
// by less than the coarser run said its own error was.
TEST(Programs, ch05_hertz_reference_moves_less_than_its_estimated_error_when_refined) {
  const std::string coarse = out_dir("ch05_reference_coarse"), fine = out_dir("ch05_reference_fine");
  const ProgramRun c = run(std::string(CH05) + " --n0 8 --levels 3 --no-compare --no-plot --out " + coarse);
  const ProgramRun f = run(std::string(CH05) + " --n0 8 --levels 4 --no-compare --no-plot --out " + fine);
  ASSERT_EQ(c.status, 0) << c.output;
  ASSERT_EQ(f.status, 0) << f.output;
  const std::pair<const char*, const char*> values[] = {
      {"reference_total_force", "reference_total_force_rel_change"},
      {"reference_half_width_m", "reference_half_width_rel_change"},
      {"reference_peak_pressure_pa", "reference_peak_pressure_rel_change"}};
  for (const auto& [name, change] : values) {
    const double vc = summary_value(coarse, "results", name), vf = summary_value(fine, "results", name);
    const double estimate = summary_value(coarse, "results", change);
    ASSERT_TRUE(std::isfinite(vc) && std::isfinite(vf) && std::isfinite(estimate)) << name;
    EXPECT_LT(std::fabs(vf - vc) / vf, estimate) << name << ": " << vc << " -> " << vf;
  }
}

TEST(Programs, ch05_rho_too_large_is_reported_with_status_1) {
  const ProgramRun r = run(std::string(CH05) + " --quick --no-compare --no-plot --solver uzawa --rho 1e6 --out " +
                           out_dir("ch05_rho"));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("Uzawa diverges"), std::string::npos) << r.output;
}

// With the active set as the study's solver, a --rho beyond Uzawa's bound fails only Uzawa's rows
// of the comparison: the run goes on, says so, and draws its figures (the 1/h line of the
// iterations figure is drawn through Uzawa's points only when there are some).
TEST(Programs, ch05_survives_a_comparison_in_which_uzawa_fails) {
  const std::string dir = out_dir("ch05_rho_compare");
  const ProgramRun r = run(std::string(CH05) + " --quick --rho 999999 --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("failed: Uzawa diverges"), std::string::npos) << r.output;
  for (const char* figure : {"iterations.png", "error_vs_time.png", "error_vs_h.png", "pressure.png"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + figure)) << figure;
}

// No contact at all: every error is zero, and a figure says "slope undefined", never "nan".
TEST(Programs, ch05_zero_errors_have_no_slope_in_the_figures) {
  const std::string dir = out_dir("ch05_zero_slopes");
  const ProgramRun r = run(std::string(CH05) + " --quick --no-compare --no-plot --delta 0 --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string script = file_text(dir + "/error_vs_h.gp");
  EXPECT_EQ(script.find("nan"), std::string::npos) << script;
  EXPECT_NE(script.find("slope undefined"), std::string::npos) << script;
}

TEST(Programs, ch05_grazing_contact_has_zero_force) {
  const std::string dir = out_dir("ch05_grazing");
  const ProgramRun r = run(std::string(CH05) + " --quick --no-compare --no-plot --delta 0 --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(summary_value(dir, "results", "total_force"), 0.0);
  EXPECT_EQ(summary_value(dir, "results", "contact_half_width"), 0.0);
}

// A stiff body on a soft one, forced to be the non-mortar side, makes S badly conditioned: plain
// Uzawa needs about 2e5 steps at the third level. Slow is not divergent: the run must finish.
TEST(Programs, ch05_plain_uzawa_on_a_stiffness_ratio_of_1e6_converges) {
  const std::string dir = out_dir("ch05_stiff");
  const ProgramRun r = run(std::string(CH05) +
                           " --E2 1e-6 --nonmortar 1 --solver uzawa --acceleration none --levels 3 --no-compare --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_LE(summary_value(dir, "results", "complementarity_residual"), 1e-8);
  EXPECT_GT(summary_value(dir, "results", "iterations"), 1e4);
}

// The signorini scene has an exact solution with a contact zone and a separation zone: the
// energy error must fall (Theorem 5.1 promises h^{1/4}; the optimal rate is 1) and the
// contact point must be found to within an element, for both matchings.
TEST(Programs, ch05_signorini_scene_converges_and_finds_the_contact_point) {
  for (const std::string matching : {"integral", "pointwise"}) {
    const std::string dir = out_dir("ch05_signorini_" + matching);
    const ProgramRun r = run(std::string(CH05) + " --scene signorini --levels 4 --no-compare --no-plot --matching " +
                             matching + " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
    for (const char* key : {"err_energy", "err_l2", "err_pressure", "err_total_force", "err_contact_point"})
      EXPECT_TRUE(std::isfinite(summary_value(dir, "rates", key))) << key;
    // the finest three of four levels (n1 = 16 to 64): local rates measured 0.99-1.02
    EXPECT_GT(summary_value(dir, "rates", "err_energy"), 0.9) << matching << "\n" << r.output;
    const double h1 = summary_value(dir, "results", "h1_m");
    EXPECT_LT(summary_value(dir, "results", "contact_point_error_m"), h1) << matching;
    EXPECT_NEAR(summary_value(dir, "results", "exact_contact_point_m"), 0.5 + std::sqrt(2.0) / 10, 1e-9);  // 10 digits in JSON
    EXPECT_TRUE(std::filesystem::exists(dir + "/local_rates.csv"));
  }
}

// The hertz-exact scene is an exact solution with true contact edges (pressure like a square
// root, gap opening like a power 3/2): the exact field passes its own check, the energy error
// falls like h for both matchings, the half-width is found to within about an element and the
// force balance holds. Measured at levels 3-5 (n1 = 32 to 128): local energy rates 0.89-0.98
// for both matchings, half-width errors 0.04-0.67 h1.
TEST(Programs, ch05_hertz_exact_scene_converges_like_h_and_finds_the_contact_edges) {
  for (const std::string matching : {"integral", "pointwise"}) {
    const std::string dir = out_dir("ch05_hertz_exact_" + matching);
    const ProgramRun r = run(std::string(CH05) + " --scene hertz-exact --levels 6 --no-compare --no-plot --matching " +
                             matching + " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_LT(summary_value(dir, "results", "exact_solution_check"), 1e-10);
    const double rate = summary_value(dir, "rates", "err_energy");
    EXPECT_GT(rate, 0.9) << matching << "\n" << r.output;
    EXPECT_LT(rate, 1.1) << matching;
    // the value itself (h1 = 1/128, h2 = 3/256): 0.02853 integral, 0.02867 pointwise
    EXPECT_NEAR(summary_value(dir, "results", "err_energy"), matching == "integral" ? 0.02853 : 0.02867, 3e-4);
    const double h1 = summary_value(dir, "results", "h1_m");
    EXPECT_LT(summary_value(dir, "results", "half_width_error_m"), 1.5 * h1) << matching;
    EXPECT_NEAR(summary_value(dir, "results", "exact_half_width_m"), std::sqrt(2.0) / 6, 1e-9);
    EXPECT_LT(summary_value(dir, "results", "err_total_force"), 0.01) << matching;
    EXPECT_GT(summary_value(dir, "results", "active_set_changes"), 0) << matching;
    EXPECT_EQ(csv_column(dir + "/local_rates.csv", "err_energy").size(), 5u);
    // the best approximation of the pressure in M_h^1 against its closed form on the non-mortar
    // trace (n1 = 4, 8, ..., 128 elements of (0, 1)): the norms must cut at the edges x0 +- a
    // (measured 3% off at n1 = 8 when they did not)
    const std::vector<double> best = csv_column(dir + "/convergence.csv", "err_pressure_best");
    ASSERT_EQ(best.size(), 6u);
    for (int k = 0; k < 6; ++k) {
      const double exact = hertz_best::relative_best_error(1.0, 4 << k, 0.5, std::sqrt(2.0) / 6);
      EXPECT_NEAR(best[k], exact, 1e-6 * exact) << matching << ", level " << k;
    }
  }
}

// The hertz-exact scene scales with its lengths (a = L sqrt(2)/6, boxes L x H): the relative
// errors do not depend on the unit of length, nor on R, which only sets the amplitude (the
// problem is linear). --delta, which this scene does not use, must not refuse a small body.
TEST(Programs, ch05_hertz_exact_errors_do_not_depend_on_the_unit_of_length) {
  std::map<std::string, double> energy, pressure;
  for (const std::string L : {"1", "1e-5", "1e5"}) {
    const std::string dir = out_dir("ch05_hertz_exact_L" + L);
    const ProgramRun r = run(std::string(CH05) + " --scene hertz-exact --levels 4 --no-compare --no-plot --L " + L +
                             " --H1 " + L + " --H2 " + L + " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
    energy[L] = summary_value(dir, "results", "err_energy");
    pressure[L] = summary_value(dir, "results", "err_pressure");
  }
  for (const std::string L : {"1e-5", "1e5"}) {
    EXPECT_NEAR(energy[L] / energy["1"], 1.0, 1e-6) << "L = " << L;
    EXPECT_NEAR(pressure[L] / pressure["1"], 1.0, 1e-6) << "L = " << L;
  }
}

// The column h of convergence.csv, which every rate uses, is max(h1, h2): h1 when body 2 is the
// finer (h2/h1 = 1/3), h2 when it is the coarser (3/2). A rate at a fixed ratio is blind to
// which one is written, so the column itself is checked.
TEST(Programs, convergence_tables_give_h_as_the_larger_of_h1_and_h2) {
  const std::vector<std::pair<std::string, std::string>> programs = {
      {CH03, ""}, {CH04, ""}, {CH05, " --no-compare"}, {CH06, " --no-compare --no-hertz"}, {CH07, " --no-p1"}};
  for (const auto& [program, skip] : programs)
    for (const std::string ratio : {"1/3", "3/2"}) {
      const std::string dir = out_dir("h_column");
      const ProgramRun r = run(program + skip + " --quick --no-plot --h-ratio " + ratio + " --out " + dir);
      ASSERT_EQ(r.status, 0) << program << "\n" << r.output;
      const auto h = csv_column(dir + "/convergence.csv", "h"), h1 = csv_column(dir + "/convergence.csv", "h1"),
                 h2 = csv_column(dir + "/convergence.csv", "h2");
      ASSERT_EQ(h.size(), 3u) << program;
      ASSERT_EQ(h1.size(), h.size()) << program;
      ASSERT_EQ(h2.size(), h.size()) << program;
      for (std::size_t k = 0; k < h.size(); ++k) {
        EXPECT_EQ(h[k], std::max(h1[k], h2[k])) << program << " at h2/h1 = " << ratio << ", level " << k;
        EXPECT_NE(h1[k], h2[k]) << program;
      }
      std::filesystem::remove_all(dir);
    }
}

// Chapter 6's dual basis inside chapter 5 (--solver dual-newton): integral matching only, and on
// hertz-exact the same energy error as the standard basis to within 2% (measured 0.5% at n1 = 64).
TEST(Programs, ch05_dual_newton_solver_is_integral_only_and_agrees_with_the_standard_basis) {
  const ProgramRun refused = run(std::string(CH05) + " --scene hertz-exact --solver dual-newton --matching pointwise "
                                 "--no-plot --out " + out_dir("ch05_dual_refused"));
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("--solver"), std::string::npos) << refused.output;
  const std::string dual = out_dir("ch05_hertz_exact_dual"), standard = out_dir("ch05_hertz_exact_standard");
  for (const auto& [dir, solver] : {std::pair{dual, "dual-newton"}, std::pair{standard, "pdas"}}) {
    const ProgramRun r = run(std::string(CH05) + " --scene hertz-exact --levels 5 --no-compare --no-plot --solver " +
                             solver + " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
  }
  const double e_dual = summary_value(dual, "results", "err_energy"), e_std = summary_value(standard, "results", "err_energy");
  EXPECT_NEAR(e_dual / e_std, 1.0, 0.02) << e_dual << " " << e_std;
}

// summary.json records every option with the value used: a flag given on the command line
// must read true there (--no-compare once read false through a dangling reference).
TEST(Programs, ch05_summary_records_the_no_compare_flag_as_given) {
  const std::string dir = out_dir("ch05_no_compare");
  const ProgramRun r = run(std::string(CH05) + " --quick --no-compare --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string json = file_text(dir + "/summary.json");
  const auto options = json.substr(0, json.find('}'));  // the "options" block comes first
  EXPECT_NE(options.find("\"no-compare\": true"), std::string::npos) << json;
  EXPECT_NE(options.find("\"quick\": true"), std::string::npos) << json;
  EXPECT_NE(options.find("\"no-plot\": true"), std::string::npos) << json;
}

// A run the machine cannot hold is refused before any work, naming the memory it needs and
// what the machine has. An address-space limit (`ulimit -v`) makes the test independent of
// the machine; 1 GB holds neither chapter 4's 856k dofs (about 3 GB) nor the Hertz scene's
// level 5 with its reference.
TEST(Programs, a_run_larger_than_memory_is_refused_before_it_starts) {
  const std::string dir = out_dir("memory_refused");
  const std::vector<std::string> commands = {std::string(CH04) + " --levels 7", std::string(CH03) + " --levels 7",
                                             std::string(CH05) + " --levels 5", std::string(CH02) + " --n0 8 --levels 9"};
  for (const std::string& command : commands) {
    const ProgramRun r = run("bash -c 'ulimit -v 1000000; exec " + command + " --no-plot --out " + dir + "'");
    EXPECT_EQ(r.status, 2) << command << "\n" << r.output;
    EXPECT_NE(r.output.find("--levels"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("GB of memory"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("ulimit -v"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir)) << command << " left output behind";
  }
}

// Beyond a stiffness ratio of 1e10 the solvers called the matrix singular (the LU from 1e11,
// CHOLMOD at 1e14) after the run had started: now refused at once, naming the option given.
// Bodies one cell thick along a Gamma_c of 4096 elements: the sparse solve of K takes 0.02 s,
// the dense blocks on Gamma_c some 4e11 operations (237 s, 4517 times the physical limit, with
// no word before). The estimate is printed before any work: within the first seconds, and not
// for the same bodies on a Gamma_c a quarter as long (about 1/60 of the work).
TEST(Programs, ch04_announces_minutes_of_dense_work_on_gamma_c_before_it_starts) {
  const std::string dir = out_dir("ch04_long_run"), thin = " --H1 0.000244140625 --H2 0.000244140625";
  const ProgramRun r = run("timeout 5 " + std::string(CH04) + " --n0 1024 --levels 3" + thin + " --no-plot --out " + dir);
  EXPECT_NE(r.output.find("warning: the finest level's dense blocks on Gamma_c (schur solver, 4095 multipliers, "
                          "2732 mortar nodes) need about 4.3e+11 floating-point operations"),
            std::string::npos)
      << r.output;
  const ProgramRun small = run(std::string(CH04) + " --n0 256 --levels 3 --H1 0.0009765625 --H2 0.0009765625 "
                               "--no-plot --out " + dir);
  EXPECT_EQ(small.status, 0) << small.output;
  EXPECT_EQ(small.output.find("floating-point operations"), std::string::npos) << small.output;
}

TEST(Programs, stiffness_ratios_beyond_1e10_are_refused_before_any_work) {
  const std::string dir = out_dir("stiffness_ratio");
  for (const char* program : {CH03, CH04, CH05, CH06, CH07, CH08, CH10})
    for (const std::string option : {"--E1 1e11", "--E2 1e-11", "--E2 4e10"}) {
      const ProgramRun r = run(std::string(program) + " --quick " + option + " --no-plot --out " + dir);
      EXPECT_EQ(r.status, 2) << program << " " << option << "\n" << r.output;
      EXPECT_NE(r.output.find(option.substr(0, 4) + ": body "), std::string::npos) << r.output;
      EXPECT_NE(r.output.find("within [1e-10, 1e10]"), std::string::npos) << r.output;
      EXPECT_FALSE(std::filesystem::exists(dir));
    }
  // 1e10 itself is solved, with the rates of E1 = E2 (chapter 4: energy 0.958 at 1e8 and 1e10)
  const ProgramRun r = run(std::string(CH04) + " --quick --E1 1e10 --E2 1 --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NEAR(summary_value(dir, "rates", "err_energy"), 0.9585, 1e-3);
}

// Chapter 5 on Hertz with body 1 1e8 times stiffer: as the non-mortar side it made the pressure
// oscillate from node to node (L2 error 86% on level 3); by default the softer body is now the
// non-mortar side (12%), with a note, and a user who forces the stiff one is warned.
TEST(Programs, ch05_makes_the_softer_body_the_non_mortar_side) {
  const std::string dir = out_dir("ch05_softer_nonmortar");
  const std::string command = std::string(CH05) + " --scene hertz-exact --E1 1e8 --levels 4 --no-compare --no-plot";
  ProgramRun r = run(command + " --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("body 2, the softer, is the non-mortar side"), std::string::npos) << r.output;
  const std::vector<double> chosen = csv_column(dir + "/convergence.csv", "err_pressure");
  ASSERT_EQ(chosen.size(), 4u);
  EXPECT_NEAR(chosen.back(), 0.122, 0.005);
  r = run(command + " --nonmortar 1 --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("warning: the non-mortar body 1 is 1e+08 times stiffer"), std::string::npos) << r.output;
  EXPECT_GT(csv_column(dir + "/convergence.csv", "err_pressure").back(), 0.5);
}

// The manufactured solutions are functions of x/L and y/L (manufactured_contact.hpp), and
// chapter 6's Hertz part follows --L: a run in micrometres or in kilometres gives the relative
// errors and rates of the run in metres (before, y in cos(y) was in metres: at L = 1e5 chapter
// 4 printed err_energy 370 against 0.015).
TEST(Programs, relative_errors_do_not_depend_on_the_unit_of_length) {
  const std::vector<std::string> commands = {
      std::string(CH03) + " --quick", std::string(CH04) + " --levels 4",
      std::string(CH05) + " --scene signorini --quick --no-compare",
      std::string(CH05) + " --scene bilateral --quick --no-compare", std::string(CH06) + " --quick --no-compare",
      std::string(CH07) + " --quick"};
  for (const std::string& command : commands) {
    std::map<std::string, std::vector<double>> at;  // L -> rate, finest error, Hertz force / L
    for (const std::string L : {"1", "1e-06", "1e+06"}) {
      const double length = std::stod(L);
      const std::string dir = out_dir("unit_of_length");
      char heights[96];
      std::snprintf(heights, sizeof heights, " --L %s --H1 %.17g --H2 %.17g", L.c_str(), length / 2, length / 2);
      const ProgramRun r = run(command + heights + " --no-plot --out " + dir);
      ASSERT_EQ(r.status, 0) << command << heights << "\n" << r.output;
      const std::vector<double> energy = csv_column(dir + "/convergence.csv", "err_energy");
      ASSERT_FALSE(energy.empty()) << command;
      at[L] = {summary_value(dir, "rates", "err_energy"), energy.back(),
               command.find("ch06") != std::string::npos ? summary_value(dir, "results", "hertz_total_force_dual") / length
                                                         : 1.0};
    }
    for (const std::string L : {"1e-06", "1e+06"})
      for (std::size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(at[L][k], at["1"][k], 1e-6 * std::fabs(at["1"][k])) << command << " --L " << L << ", value " << k;
  }
}

// The parts of a run that are not the finest level's sparse solve are counted too: chapter
// 1's transfers as dense matrices, the dense blocks the saddle-point and contact solvers build
// on Gamma_c (bodies one cell thick make them the whole run), and chapter 6's Hertz part on
// square blocks. Each run below needs 39 to 286 GB; under an 8 GB address space each is
// refused at once, naming the part, and leaves nothing behind. Chapters 2 and 8 (all sparse)
// are tried the same way, chapter 8 under 3 GB.
TEST(Programs, runs_whose_dense_or_second_parts_exceed_memory_are_refused_at_once) {
  const std::string dir = out_dir("dense_refused");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {std::string(CH01) + " --n0 1000 --h-ratio 0.01 --levels 3", "three dense 4001 x 400001 matrices"},
      {std::string(CH01) + " --n0 16384 --levels 3", "three dense 65537 x 43692 matrices"},
      {std::string(CH03) + " --n0 16384 --levels 3 --H1 1.52587890625e-05 --H2 1.52587890625e-05",
       "(65535 multipliers, 43692 mortar nodes)"},
      {std::string(CH04) + " --n0 16384 --levels 3 --H1 1.52587890625e-05 --H2 1.52587890625e-05",
       "S = B K^-1 B^T and the factor's dense block on Gamma_c (65535 multipliers, 43692 mortar nodes)"},
      {std::string(CH04) + " --n0 16384 --levels 3 --H1 1.52587890625e-05 --H2 1.52587890625e-05 "
                           "--saddle-solver elimination",
       "X = -B_s^-1 B_r"},
      {std::string(CH05) + " --n0 8192 --levels 3 --H1 0.00048828125 --H2 0.00048828125 --scene signorini",
       "S = B K^-1 B^T, its active block"},
      {std::string(CH06) + " --h-ratio 0.01 --n0 12 --levels 3 --H2 0.01", "the Hertz part's finest level (4.61e+07 dofs"},
      {std::string(CH07) + " --n0 8192 --levels 3 --H1 6.103515625e-05 --H2 6.103515625e-05",
       "(65535 multipliers, 43691 mortar nodes)"},
      // and the two programs whose memory is all in the sparse solve (25.6 and 4.96 GB)
      {std::string(CH02) + " --n0 8 --levels 9", "8.4e+06 dofs and need about"},
      {std::string(CH08) + " --n0 128 --levels 4", "1.52e+06 dofs and need about"}};
  for (const auto& [command, part] : cases) {
    const auto start = std::chrono::steady_clock::now();
    const std::string limit = command.find("ch08") != std::string::npos ? "3000000" : "8000000";
    const ProgramRun r = run("bash -c 'ulimit -v " + limit + "; exec " + command + " --no-plot --out " + dir + "'");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.status, 2) << command << "\n" << r.output;
    EXPECT_NE(r.output.find("GB of memory"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(part), std::string::npos) << command << "\n" << r.output;
    EXPECT_LT(seconds, 1.0) << command;
    EXPECT_FALSE(std::filesystem::exists(dir)) << command << " left output behind";
  }
}

// Under an address-space limit smaller than the libraries' own buffers, OpenBLAS retries a
// failed mmap for ever inside the factorization: the run must be refused before it gets there.
TEST(Programs, a_tiny_address_space_is_refused_not_a_hang) {
  const std::string dir = out_dir("tiny_address_space");
  const ProgramRun r = run("timeout 60 bash -c 'ulimit -v 300000; exec " + std::string(CH02) +
                           " --quick --no-plot --out " + dir + "'");
  EXPECT_EQ(r.status, 2) << "124 is the timeout: a hang\n" << r.output;
  EXPECT_NE(r.output.find("GB of memory"), std::string::npos) << r.output;
}

// --quick sets --n0 and --levels: an explicit value beside it is refused, not silently replaced.
TEST(Programs, quick_with_an_explicit_size_is_refused) {
  for (const char* program : {CH01, CH02, CH03, CH04, CH05, CH08})
    for (const std::string option : {"n0", "levels"}) {
      if (program == std::string(CH01) && option == "n0") continue;  // chapter 1's --quick sets levels only
      const std::string dir = out_dir("quick_refused");
      const ProgramRun r = run(std::string(program) + " --quick --" + option + " 4 --no-plot --out " + dir);
      EXPECT_EQ(r.status, 2) << program << " --" << option << "\n" << r.output;
      EXPECT_NE(r.output.find("--" + option + ": cannot be combined with --quick"), std::string::npos) << r.output;
      EXPECT_FALSE(std::filesystem::exists(dir));
    }
}

// A body 1e7 times stiffer than the other: the LU of the saddle point is as accurate as
// elimination and must not be called singular.
TEST(Programs, ch04_lu_on_a_stiffness_ratio_of_1e7_agrees_with_elimination) {
  std::vector<std::string> dirs;
  for (const std::string solver : {"lu", "elimination"}) {
    dirs.push_back(out_dir("ch04_stiff_" + solver));
    const ProgramRun r = run(std::string(CH04) + " --quick --no-plot --E1 1e7 --E2 1 --saddle-solver " + solver +
                             " --out " + dirs.back());
    ASSERT_EQ(r.status, 0) << solver << "\n" << r.output;
  }
  for (const char* key : {"err_energy", "err_pressure"}) {
    const double lu = summary_value(dirs[0], "results", key), el = summary_value(dirs[1], "results", key);
    EXPECT_NEAR(lu, el, 1e-6 * el) << key;
  }
}

// A load of 1e-12 m: the penetration is tiny next to the open gap far from the contact, and
// the stopping test must not accept the first Uzawa iterate for it.
TEST(Programs, ch05_uzawa_and_pdas_agree_on_a_load_of_1e_12) {
  std::vector<double> force;
  for (const std::string solver : {"uzawa", "pdas"}) {
    const std::string dir = out_dir("ch05_small_load_" + solver);
    const ProgramRun r = run(std::string(CH05) + " --delta 1e-12 --matching pointwise --quick --no-compare --no-plot"
                             " --solver " + solver + " --out " + dir);
    ASSERT_EQ(r.status, 0) << solver << "\n" << r.output;
    force.push_back(summary_value(dir, "results", "total_force"));
  }
  EXPECT_GT(force[1], 0.0);
  EXPECT_NEAR(force[0], force[1], 1e-6 * force[1]);
}

// A contact zone narrower than one element (R = 1e-4: half-width about 1e-3, h1 = 1/32): no
// multiplier becomes active, yet the top moved down by delta = 0.02 and the bodies overlap by
// that much at x = L/2. The program must say so, never that the bodies do not touch.
TEST(Programs, ch05_a_contact_zone_narrower_than_an_element_is_reported_as_penetration) {
  const std::string dir = out_dir("ch05_tiny_zone");
  const ProgramRun r = run(std::string(CH05) + " --R 1e-4 --quick --no-compare --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("warning: the bodies interpenetrate"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("the bodies do not touch"), std::string::npos) << r.output;
  EXPECT_NEAR(summary_value(dir, "results", "max_penetration_m"), 0.02, 1e-6);
  EXPECT_NEAR(summary_value(dir, "results", "max_penetration_x_m"), 0.5, 1e-9);
  // and where the bodies really do not touch (delta = 0), the pointwise gap agrees
  const std::string open = out_dir("ch05_no_touch");
  const ProgramRun g = run(std::string(CH05) + " --delta 0 --quick --no-compare --no-plot --out " + open);
  ASSERT_EQ(g.status, 0) << g.output;
  EXPECT_LE(summary_value(open, "results", "max_penetration_m"), 0.0);
  EXPECT_NE(g.output.find("the bodies do not touch"), std::string::npos) << g.output;
  // pointwise matching sees the overlap at one node of xi^1: one active node and a force, while
  // the reference (integral, graded) sees none. It must not say the bodies do not touch, nor
  // call the round-off at that node (1e-17 m, where [u.n] = g is imposed) a penetration.
  const std::string point = out_dir("ch05_tiny_zone_pointwise");
  const ProgramRun p = run(std::string(CH05) + " --R 1e-4 --matching pointwise --quick --no-compare --no-plot --out " + point);
  ASSERT_EQ(p.status, 0) << p.output;
  EXPECT_NE(p.output.find("note: the finest level has 1 node in contact (total force 0.00412 N/m)"), std::string::npos)
      << p.output;
  EXPECT_EQ(p.output.find("the bodies do not touch"), std::string::npos) << p.output;
  EXPECT_EQ(p.output.find("interpenetrate"), std::string::npos) << p.output;
}

TEST(Programs, ch07_refuses_malformed_input) {
  expect_all_refused(CH07, common_bad_inputs(),
                     {{"--n0 1", "n0"}, {"--E1 -1", "E1"}, {"--E2 0", "E2"}, {"--nu1 0.5", "nu1"},
                      {"--nu2 0.7", "nu2"}, {"--h-ratio 0", "h-ratio"}, {"--h-ratio inf", "h-ratio"},
                      {"--nonmortar 3", "nonmortar"}, {"--matching mortar", "matching"},
                      {"--matching", "matching"}, {"--no-p1=yes", "no-p1"}, {"--aspect 0", "aspect"}});
}

// Chapter 7 on P2 levels of 6, 12 and 24 non-mortar elements (272 to 3572 unknowns). Integral
// matching: the energy rate of Theorem 4.2 with q = 2 (measured 1.92-1.98 over these levels at
// the four ratios; band >= 1.85) and the L2 rate 3 (measured 3.02-3.11; band >= 2.9), the patch
// test to round-off. Pointwise matching at h2/h1 = 1/3: Theorem 4.1's h^{1/2} already shows
// (measured 0.51; band <= 0.7), and the patch test fails.
TEST(Programs, ch07_p2_rates_and_patch_tests) {
  for (const char* ratio : {"3/2", "2/3", "1/3", "3"}) {
    const std::string dir = out_dir("ch07_rates");
    const ProgramRun r = run(std::string(CH07) + " --quick --no-plot --no-p1 --h-ratio " + ratio + " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_GE(summary_value(dir, "rates", "err_energy"), 1.85) << "h2/h1 = " << ratio;
    EXPECT_GE(summary_value(dir, "rates", "err_l2"), 2.9) << "h2/h1 = " << ratio;
    EXPECT_LT(summary_value(dir, "results", "patch_test_rel_error"), 1e-10) << "h2/h1 = " << ratio;
    EXPECT_GT(summary_value(dir, "results", "patch_test_rel_error_pointwise"), 1e-4) << "h2/h1 = " << ratio;
  }
  const std::string dir = out_dir("ch07_pointwise");
  const ProgramRun r =
      run(std::string(CH07) + " --quick --no-plot --no-p1 --matching pointwise --h-ratio 1/3 --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_LE(summary_value(dir, "rates", "err_energy"), 0.7);
  EXPECT_GT(summary_value(dir, "rates", "err_energy"), 0.3);
  EXPECT_GT(summary_value(dir, "results", "patch_test_rel_error"), 1e-4);
}

// The pressure on the middle half of Gamma_c (chapter 7's notes, "The pressure"), default run:
// away from the P1 end elements the best approximation in M_h^1 reaches h^3, while lambda_h and
// its element means stay at h^2, a full order below (last local rates: 3.00, 2.00, 2.00), and
// the finest values, 192 non-mortar elements.
TEST(Programs, ch07_pressure_is_an_order_below_its_best_approximation_in_the_middle) {
  const std::string dir = out_dir("ch07_middle");
  const ProgramRun r = run(std::string(CH07) + " --no-plot --no-p1 --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const auto last_rate = [&](const std::string& column) { return csv_column(dir + "/local_rates.csv", column).back(); };
  EXPECT_NEAR(last_rate("err_pressure_middle"), 2.0, 0.03);
  EXPECT_NEAR(last_rate("err_pressure_best_middle"), 3.0, 0.03);
  EXPECT_NEAR(last_rate("err_pressure_means_middle"), 2.0, 0.03);
  const auto finest = [&](const std::string& column) { return csv_column(dir + "/convergence.csv", column).back(); };
  EXPECT_NEAR(finest("err_pressure_middle"), 2.246e-05, 1e-2 * 2.246e-05);
  EXPECT_NEAR(finest("err_pressure_best_middle"), 2.924e-08, 1e-2 * 2.924e-08);
  EXPECT_NEAR(finest("err_pressure_means_middle"), 4.888e-06, 1e-2 * 4.888e-06);
}

// P2 beside P1 with the same unknowns (p1.csv): P2's energy error is below P1's at every level
// from the second on, and it reaches P1's finest error with fewer unknowns.
TEST(Programs, ch07_p2_beats_p1_at_equal_unknowns) {
  const std::string dir = out_dir("ch07_p1");
  const ProgramRun r = run(std::string(CH07) + " --quick --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  const auto p2 = csv_column(dir + "/convergence.csv", "err_energy");
  const auto p1 = csv_column(dir + "/p1.csv", "err_energy");
  const auto d2 = csv_column(dir + "/convergence.csv", "dofs"), d1 = csv_column(dir + "/p1.csv", "dofs");
  ASSERT_EQ(p2.size(), 3u);
  ASSERT_EQ(p1.size(), 3u);
  for (std::size_t k = 0; k < p2.size(); ++k) EXPECT_EQ(d1[k], d2[k]) << "level " << k;
  for (std::size_t k = 1; k < p2.size(); ++k) EXPECT_LT(p2[k], p1[k]) << "level " << k;
  EXPECT_GT(summary_value(dir, "results", "dofs_ratio_p1_over_p2"), 1.0);
}

TEST(Programs, ch08_refuses_malformed_input) {
  expect_all_refused(CH08, common_bad_inputs(),
                     {{"--scene moon", "scene"}, {"--law glue", "law"}, {"--solver cg", "solver"},
                      {"--start warm", "start"}, {"--friction -1", "friction"}, {"--friction nan", "friction"},
                      {"--load-steps 0", "load-steps"}, {"--load-steps -3", "load-steps"}, {"--E1 -1", "E1"},
                      {"--nu2 0.5", "nu2"}, {"--h-ratio 0", "h-ratio"}, {"--nonmortar 3", "nonmortar"},
                      {"--n0 4096 --levels 8", "levels"},
                      // combinations: gross sliding, Tresca where the threshold is F lambda_n, no
                      // friction to hold Cattaneo's body 1, a fixed point for Tresca, E out of range
                      {"--scene cattaneo --q-ratio 1", "q-ratio"}, {"--scene cattaneo --law tresca", "law"},
                      {"--scene cattaneo --friction 0", "friction"}, {"--scene cattaneo --delta 1.5", "delta"},
                      {"--solver fixed-point --law tresca", "solver"}, {"--E1 1e300", "E1"}, {"--E2 1e-160", "E2"},
                      {"--friction 11", "friction"},
                      // several discrete Coulomb solutions beyond F = 4 on the manufactured scene
                      // (the Newton steps cycled at F = 5 and 10, the fixed point settled 100%
                      // off); a Cattaneo contact zone under one element (one node held body 1 and
                      // slid: no solution)
                      {"--quick --no-compare --friction 5", "friction"}, {"--levels 5 --friction 10", "friction"},
                      {"--friction 10 --solver fixed-point", "friction"},
                      {"--scene cattaneo --n0 16 --levels 3 --no-compare --R 1e-3", "R"},
                      {"--scene cattaneo --n0 16 --levels 3 --no-compare --R 1e-6", "R"},
                      {"--scene cattaneo --n0 16 --levels 3 --no-compare --delta 1e-12", "delta"},
                      // the exact Cattaneo scene: two materials whose shear moves the pressure; delta
                      {"--scene cattaneo-exact --E2 3", "E2"}, {"--scene cattaneo-exact --nu2 0.25", "nu2"},
                      {"--scene cattaneo-exact --delta 0.01", "delta"}, {"--scene cattaneo-exact --law tresca", "law"}});
}

// --solver fixed-point beside the Newton method: the comparison runs Newton against the fixed
// point (it ran the fixed point twice, "answers differ by 0.0e+00", and labelled both Newton):
// Newton's Coulomb steps are LUs, the fixed point's Tresca steps never, and the answers agree
// to the fixed point's tolerance without being the same run.
TEST(Programs, ch08_fixed_point_is_compared_with_newton) {
  const std::string dir = out_dir("ch08_fixed_point");
  const ProgramRun r = run(std::string(CH08) + " --quick --solver fixed-point --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(summary_value(dir, "results", "lu_steps"), 0.0);  // the study itself: the fixed point
  for (double lu : csv_column(dir + "/solvers.csv", "newton_lu_steps")) EXPECT_GT(lu, 0.0);
  for (double difference : csv_column(dir + "/solvers.csv", "difference")) {
    EXPECT_GT(difference, 0.0);
    EXPECT_LT(difference, 1e-8);
  }
}

// Cattaneo's scene where the Newton method failed: the fixed point (its first Tresca problem,
// frictionless, left body 1 free: "matrix singular") now starts with no slip and gives Newton's
// answer; F = 1e6 with Q = 0.6 F P sticks at every node of every load step (it cycled, residual
// 4e2 after 50 steps, before the restart from the no-slip solution).
TEST(Programs, ch08_cattaneo_fixed_point_and_huge_friction) {
  const std::string cattaneo = " --scene cattaneo --n0 16 --levels 3 --load-steps 3 --no-compare --no-plot --out ";
  const std::string dn = out_dir("ch08_cattaneo_newton"), df = out_dir("ch08_cattaneo_fixed_point"),
                    dh = out_dir("ch08_cattaneo_1e6");
  const ProgramRun n = run(std::string(CH08) + cattaneo + dn);
  const ProgramRun f = run(std::string(CH08) + cattaneo + df + " --solver fixed-point");
  const ProgramRun h = run(std::string(CH08) + cattaneo + dh + " --friction 1e6");
  ASSERT_EQ(n.status, 0) << n.output;
  ASSERT_EQ(f.status, 0) << f.output;
  ASSERT_EQ(h.status, 0) << h.output;
  EXPECT_NEAR(summary_value(df, "results", "tangential_traction_rel_error_l2") /
                  summary_value(dn, "results", "tangential_traction_rel_error_l2"),
              1.0, 1e-6);
  for (double slip : csv_column(dh + "/cattaneo.csv", "slip_nodes")) EXPECT_EQ(slip, 0.0);
  for (double stick : csv_column(dh + "/cattaneo.csv", "stick_nodes")) EXPECT_GT(stick, 0.0);
}

// The manufactured Tresca scene (chapter 8 notes): Theorem-like O(h) in energy over five levels
// (measured local rates 0.89, 0.98, 0.98, 1.00), O(h^2) in L2, a stick-slip point within a few
// elements, at most 5 Newton steps per level from the coarser level's statuses. The finest
// energy error is pinned (measured 0.01975 for this command) against a constant-factor slip.
TEST(Programs, ch08_manufactured_tresca_converges_like_h) {
  const std::string dir = out_dir("ch08_tresca");
  const ProgramRun r = run(std::string(CH08) + " --law tresca --levels 5 --no-compare --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_GE(summary_value(dir, "rates", "err_energy"), 0.9);
  EXPECT_GE(summary_value(dir, "rates", "err_l2"), 1.8);
  EXPECT_NEAR(summary_value(dir, "results", "err_energy"), 0.0198, 0.001);
  EXPECT_LE(summary_value(dir, "results", "stick_slip_point_error_h"), 6.0);
  EXPECT_LE(summary_value(dir, "results", "newton_steps_max"), 5.0);
  EXPECT_EQ(summary_value(dir, "results", "lu_steps"), 0.0);  // Tresca: every step symmetric
  EXPECT_EQ(csv_column(dir + "/local_rates.csv", "err_energy").size(), 4u);
}

// The manufactured stick-slip point is of square-root type (the shear leaves the threshold like
// sqrt(x_c - x), the slip starts like (x - x_c)^{3/2}), and the computed point x_c,h (midway
// between the last stick node and the next) lies within one element of x_c at every level from
// h1 = 1/32 to 1/256, under both laws (measured 0.75, 0.005, 0.51, 0.52 elements). The degenerate
// solution it replaced, whose margin grew like (x_c - x)^2, put it 3 to 7.5 elements short.
TEST(Programs, ch08_stick_slip_point_is_within_one_element_at_every_level) {
  for (const char* law : {"coulomb", "tresca"}) {
    const std::string dir = out_dir(std::string("ch08_frontier_") + law);
    const ProgramRun r =
        run(std::string(CH08) + " --law " + law + " --n0 32 --levels 4 --no-compare --no-plot --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
    const auto off = csv_column(dir + "/convergence.csv", "stick_slip_point_error_h");
    ASSERT_EQ(off.size(), 4u);
    for (std::size_t k = 0; k < off.size(); ++k) EXPECT_LT(off[k], 1.0) << law << ", level " << k;
  }
}

// Coulomb on the same exact solution: the same energy errors as Tresca to a fraction of a
// percent (the two discrete thresholds differ by the pressure's error), LU steps for the
// slip rows, and the fixed point on Tresca thresholds reaching the Newton answer.
TEST(Programs, ch08_coulomb_agrees_with_tresca_and_with_its_fixed_point) {
  const std::string dc = out_dir("ch08_coulomb"), dt = out_dir("ch08_tresca_quick");
  const ProgramRun c = run(std::string(CH08) + " --quick --no-plot --out " + dc);
  const ProgramRun t = run(std::string(CH08) + " --quick --no-plot --law tresca --out " + dt);
  ASSERT_EQ(c.status, 0) << c.output;
  ASSERT_EQ(t.status, 0) << t.output;
  EXPECT_NEAR(summary_value(dc, "results", "err_energy") / summary_value(dt, "results", "err_energy"), 1.0, 0.01);
  EXPECT_GT(summary_value(dc, "results", "lu_steps"), 0.0);
  for (double difference : csv_column(dc + "/solvers.csv", "difference")) EXPECT_LT(difference, 1e-8);
  for (double steps : csv_column(dc + "/solvers.csv", "fixed_point_outer")) EXPECT_GT(steps, 1.0);
}

// Cattaneo-Mindlin on three levels: the stick half-width within an element of sqrt(1 - Q/(F P))
// a, the pressure unchanged by the shear for one material (beta = 0), and the load paths: Q in
// one step gives the same answer as in three (monotone loading); P and Q together stick on a
// wider zone (Mindlin: everywhere, in the limit of small steps; in three steps the nodes that
// enter contact during a step slip: measured 0.094 of 0.109 m) and give another shear.
TEST(Programs, ch08_cattaneo_stick_zone_and_load_paths) {
  const std::string dir = out_dir("ch08_cattaneo");
  const ProgramRun r =
      run(std::string(CH08) + " --scene cattaneo --n0 16 --levels 3 --load-steps 3 --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* key : {"stick_half_width_error_m", "stick_half_width_error_h", "tangential_traction_rel_error_l2",
                          "newton_steps_max", "limit_ratio"})
    EXPECT_FALSE(std::isnan(summary_value(dir, "results", key))) << key;
  EXPECT_LE(summary_value(dir, "results", "stick_half_width_error_h"), 1.0);
  EXPECT_LT(summary_value(dir, "results", "tangential_traction_rel_error_l2"), 0.2);
  EXPECT_LT(summary_value(dir, "results", "pressure_change_rel_l2"), 0.02);
  EXPECT_LE(summary_value(dir, "results", "newton_steps_max"), 15.0);
  const auto difference = csv_column(dir + "/paths.csv", "shear_difference");
  const auto stick = csv_column(dir + "/paths.csv", "stick_half_width");
  const auto contact = csv_column(dir + "/paths.csv", "contact_half_width");
  ASSERT_EQ(difference.size(), 3u);
  EXPECT_LT(difference[1], 1e-8);
  EXPECT_GT(difference[2], 0.1);
  EXPECT_LT(stick[0], 0.9 * contact[0]);
  EXPECT_GT(stick[2], stick[0] + 0.01);
}

// Cattaneo-Mindlin made exact (cattaneo-exact): the field is the finite problem's solution
// (checked against the equations), so the shear's error falls with h instead of stopping at the
// half-plane model's. Four levels, three shear steps: measured energy local rates 0.81, 0.90,
// 0.90 and shear errors falling at every level (0.72 to 0.093 over h1 = 1/8 to 1/64 in ten
// steps); the stick half-width within an element of c = a sqrt(1 - Q/(F P)) at every level.
TEST(Programs, ch08_cattaneo_exact_shear_converges) {
  const std::string dir = out_dir("ch08_cattaneo_exact");
  const ProgramRun r = run(std::string(CH08) + " --scene cattaneo-exact --levels 4 --load-steps 3 --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_LT(summary_value(dir, "results", "exact_solution_check"), 1e-9);
  const auto energy = csv_column(dir + "/local_rates.csv", "err_energy");
  const auto shear = csv_column(dir + "/convergence.csv", "err_tangential");
  const auto stick = csv_column(dir + "/convergence.csv", "stick_half_width_error_h");
  ASSERT_EQ(shear.size(), 4u);
  for (double rate : energy) EXPECT_GT(rate, 0.75);
  for (std::size_t k = 1; k < shear.size(); ++k) EXPECT_LT(shear[k], 0.9 * shear[k - 1]) << "level " << k;
  for (double e : stick) EXPECT_LT(e, 1.0);
  EXPECT_LT(summary_value(dir, "results", "err_pressure"), 0.04);
}

// A figure's reference slope never ends a run: at Q/(F P) = 1e-12 the shear error is 0 at every
// level (Q is round-off against F P), and the slope drawn through it has no point to pass
// through. It used to end the run with status 1 after a successful solve.
TEST(Programs, ch08_a_zero_error_series_draws_without_its_reference_slope) {
  const std::string dir = out_dir("ch08_zero_series");
  const ProgramRun r = run(std::string(CH08) + " --scene cattaneo --n0 16 --levels 3 --load-steps 1 --q-ratio 1e-12 "
                           "--no-compare --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("reference slope 1 left out"), std::string::npos) << r.output;
}

// The manufactured scene scales with L: the same relative errors for L = 2e-6, 1 and 1e6 m
// (measured: equal to 1.3e-6 of themselves, the round-off of the scaled meshes; a length left in
// metres anywhere changes them by orders of magnitude).
TEST(Programs, ch08_errors_do_not_depend_on_the_unit_of_length) {
  std::vector<double> energy, tangential;
  for (const char* L : {"2e-6", "1", "1e6"}) {
    const std::string dir = out_dir("ch08_unit");
    const std::string H = std::to_string(std::stod(L) / 2);
    const ProgramRun r = run(std::string(CH08) + " --quick --no-compare --no-plot --L " + L + " --H1 " + H + " --H2 " +
                             H + " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
    energy.push_back(summary_value(dir, "results", "err_energy"));
    tangential.push_back(summary_value(dir, "results", "err_tangential"));
  }
  for (std::size_t k = 1; k < energy.size(); ++k) {
    EXPECT_NEAR(energy[k] / energy[0], 1.0, 1e-5);
    EXPECT_NEAR(tangential[k] / tangential[0], 1.0, 1e-5);
  }
}

// A rerun into the same folder leaves none of the earlier run's files that it did not write
// itself (hertz.csv after --no-hertz, standard.csv after --no-compare, p1.csv after --no-p1,
// Cattaneo's files after the manufactured scene), and keeps a file of the user's.
TEST(Programs, a_rerun_leaves_no_stale_file_of_a_part_it_skips) {
  struct Case {
    std::string program, first, second;
    std::vector<std::string> stale;
  };
  const std::vector<Case> cases = {
      {CH06, "--quick", "--quick --no-hertz --no-compare", {"hertz.csv", "standard.csv", "hertz_pressure.png"}},
      {CH07, "--quick", "--quick --no-p1", {"p1.csv"}},
      {CH08, "--scene cattaneo --n0 8 --levels 3 --load-steps 2", "--quick --no-compare", {"cattaneo.csv", "paths.csv"}}};
  for (const Case& c : cases) {
    const std::string dir = out_dir("rerun");
    ASSERT_EQ(run(c.program + " " + c.first + " --out " + dir).status, 0) << c.first;
    for (const std::string& f : c.stale) ASSERT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
    std::ofstream(dir + "/notes_of_mine.txt") << "keep";
    ASSERT_EQ(run(c.program + " " + c.second + " --out " + dir).status, 0) << c.second;
    for (const std::string& f : c.stale) EXPECT_FALSE(std::filesystem::exists(dir + "/" + f)) << c.program << ": " << f;
    EXPECT_TRUE(std::filesystem::exists(dir + "/summary.json"));
    EXPECT_TRUE(std::filesystem::exists(dir + "/notes_of_mine.txt"));
  }
}

// No program prints nan or inf where a value is undefined or out of range: chapter 1's H1 rate
// of an edge trace (no H1 column), chapter 6 at E = 1e300 (squares of the pressure overflowed),
// chapter 7 when P2 never reaches P1's finest error. Chapter 6's relative errors at E = 1e300
// are those at E = 1.
TEST(Programs, undefined_values_are_said_not_printed_as_nan_or_inf) {
  const std::regex bad(R"((^|[^A-Za-z])(nan|NaN|NAN|inf|Inf|INF)([^A-Za-z]|$))");
  struct Case {
    std::string command, must_say;
  };
  const std::string d1 = out_dir("undefined_ch01"), d6 = out_dir("undefined_ch06"), d6b = out_dir("undefined_ch06_E1"), d7 = out_dir("undefined_ch07");
  const std::vector<Case> cases = {
      {std::string(CH01) + " --trace edge --quick --no-plot --out " + d1, "H1 undefined"},
      {std::string(CH06) + " --quick --no-plot --E1 1e300 --E2 1e300 --out " + d6, ""},
      {std::string(CH07) + " --n0 2 --levels 3 --no-plot --matching pointwise --h-ratio 1/10 --out " + d7,
       "P2 does not reach it"}};
  for (const Case& c : cases) {
    const ProgramRun r = run(c.command);
    ASSERT_EQ(r.status, 0) << c.command << "\n" << r.output;
    EXPECT_FALSE(std::regex_search(r.output, bad)) << c.command << "\n" << r.output;
    EXPECT_NE(r.output.find(c.must_say), std::string::npos) << c.command;
  }
  for (const char* f : {"/convergence.csv", "/hertz.csv"}) EXPECT_FALSE(std::regex_search(file_text(d6 + f), bad)) << f;
  ASSERT_EQ(run(std::string(CH06) + " --quick --no-plot --E1 1 --E2 1 --out " + d6b).status, 0);
  for (const char* column : {"err_energy", "err_pressure", "err_pressure_function"}) {
    const auto big = csv_column(d6 + "/convergence.csv", column), unit = csv_column(d6b + "/convergence.csv", column);
    ASSERT_EQ(big.size(), unit.size());
    for (std::size_t k = 0; k < big.size(); ++k) EXPECT_NEAR(big[k] / unit[k], 1.0, 1e-9) << column << " level " << k;
  }
}

// Every two-body chapter says so when a body is nearly incompressible, as chapter 2 does: P1
// locks there (chapter 4's pressure was 55% off at nu = 0.4999 with no word).
TEST(Programs, nearly_incompressible_bodies_are_noted) {
  for (const std::string& program : {std::string(CH04), std::string(CH05), std::string(CH08)}) {
    const std::string dir = out_dir("locking");
    const ProgramRun r = run(program + " --quick --no-plot --nu2 0.4999 --out " + dir +
                             (program == CH04 ? "" : " --no-compare"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("note: nu2 = 0.4999 is close to 1/2, where P1 locks"), std::string::npos) << program;
    const ProgramRun plain = run(program + " --quick --no-plot --out " + dir + (program == CH04 ? "" : " --no-compare"));
    EXPECT_EQ(plain.output.find("locks"), std::string::npos) << program;
  }
}

// Chapter 5 accepts |delta| < H1, and says so when the strain is no longer small (99.9%).
TEST(Programs, ch05_a_large_compression_is_noted) {
  const std::string dir = out_dir("ch05_large_delta");
  const ProgramRun r = run(std::string(CH05) + " --quick --no-plot --no-compare --delta 0.999 --out " + dir);
  EXPECT_NE(r.output.find("compresses body 1 by 99.9% of its height"), std::string::npos) << r.output;
  const ProgramRun small = run(std::string(CH05) + " --quick --no-plot --no-compare --out " + dir);
  EXPECT_EQ(small.output.find("compresses body 1"), std::string::npos);
}

// Parser messages that name the real problem: an integer out of range is out of range (not
// "expects an integer"), and "--=3" has no option name.
TEST(Programs, parser_messages_name_the_real_problem) {
  const std::string dir = out_dir("parser_messages");
  const ProgramRun big = run(std::string(CH04) + " --n0 2147483647 --no-plot --out " + dir);
  EXPECT_EQ(big.status, 2);
  EXPECT_NE(big.output.find("--n0: must be in"), std::string::npos) << big.output;
  EXPECT_EQ(big.output.find("expects an integer"), std::string::npos) << big.output;
  const ProgramRun unnamed = run(std::string(CH04) + " --=3 --no-plot --out " + dir);
  EXPECT_EQ(unnamed.status, 2);
  EXPECT_NE(unnamed.output.find("has no option name"), std::string::npos) << unnamed.output;
  EXPECT_FALSE(std::filesystem::exists(dir));
}

// ---------------------------------------------------------------------------------------------
// Chapter 10: the adaptive loop beside uniform refinement

namespace {

// The triangles of body `body` (1 or 2) in a mesh figure's script: "body 2 (64 triangles)".
// Body `body`'s triangles at adaptive step `step`, from convergence.csv (-1: no such step).
int triangles_at_step(const std::string& dir, int body, int step) {
  const std::vector<double> column = csv_column(dir + "/convergence.csv", "triangles_" + std::to_string(body));
  return step < static_cast<int>(column.size()) ? static_cast<int>(column[step]) : -1;
}

// The header row of a CSV file.
std::vector<std::string> csv_header(const std::string& path) {
  std::ifstream in(path);
  std::string line, cell;
  std::getline(in, line);
  std::vector<std::string> names;
  std::istringstream header(line);
  while (std::getline(header, cell, ',')) names.push_back(cell);
  return names;
}

// The output contract every chapter keeps (the course's output checker): convergence.csv with
// h, dofs, time_s and an err_* column, every cell finite; summary.json with the four sections,
// each err_* rate and results.limit_ratio, results.limit_s finite.
void expect_output_contract(const std::string& dir) {
  const std::vector<std::string> columns = csv_header(dir + "/convergence.csv");
  for (const char* c : {"h", "dofs", "time_s"})
    EXPECT_NE(std::find(columns.begin(), columns.end(), c), columns.end()) << dir << ": no column " << c;
  int err_columns = 0;
  for (const std::string& c : columns) {
    for (double v : csv_column(dir + "/convergence.csv", c)) EXPECT_TRUE(std::isfinite(v)) << dir << ": " << c;
    if (c.rfind("err_", 0) == 0) {
      ++err_columns;
      EXPECT_TRUE(std::isfinite(summary_value(dir, "rates", c))) << dir << ": rates." << c;
    }
  }
  EXPECT_GT(err_columns, 0) << dir;
  const std::string json = file_text(dir + "/summary.json");
  for (const char* section : {"\"options\": {", "\"program\": ", "\"rates\": {", "\"results\": {"})
    EXPECT_NE(json.find(section), std::string::npos) << dir << ": " << section;
  for (const char* key : {"limit_ratio", "limit_s"})
    EXPECT_TRUE(std::isfinite(summary_value(dir, "results", key))) << dir << ": results." << key;
}

}  // namespace

TEST(Programs, ch10_refuses_malformed_input) {
  expect_all_refused(CH10, common_bad_inputs(),
                     {{"--E1 -1", "E1"}, {"--E2 0", "E2"}, {"--nu1 0.5", "nu1"}, {"--nu2 0.7", "nu2"},
                      {"--n0 0", "n0"}, {"--n0 1", "n0"}, {"--theta 1.5", "theta"}, {"--theta -0.1", "theta"},
                      {"--theta nan", "theta"}, {"--bogus", "bogus"}, {"--scene moon", "scene"},
                      {"--target 0", "target"}, {"--target 1", "target"}, {"--max-steps 0", "max-steps"},
                      {"--max-dofs 10", "max-dofs"}, {"--uniform-target 0", "uniform-target"},
                      {"--start warm", "start"}, {"--refine body3", "refine"}, {"--nonmortar 3", "nonmortar"},
                      {"--h-ratio 0", "h-ratio"},
                      // combinations: --quick sets the target; a gap radius and a push where the
                      // scene has none; a stiffness ratio beyond 1e10
                      {"--quick --target 0.1", "target"}, {"--scene punch --R 2", "R"},
                      {"--scene bilateral --R 2", "R"}, {"--scene hertz-exact --delta 0.1", "delta"},
                      {"--scene bilateral --delta 0.1", "delta"}, {"--E1 1e11", "E1"}});
}

// The issue's "done means" on the two scenes with an exact solution, at --quick sizes (target
// 0.05 on the estimate, uniform levels to 5% true error): every key of summary.json, one
// convergence.csv row per adaptive step with its columns, and the output contract. The 1% keys
// are written (null: --quick stops above 1%, measured 1.60% and 1.11% at the last step). The
// effectivity band over both runs, measured 2.712-3.836 (hertz-exact) and 4.358-4.986
// (bilateral), pinned at 0.9 x its smallest and 1.1 x its largest value. Runs of 13 s and 2 s.
TEST(Programs, ch10_quick_runs_write_every_key_of_the_done_means) {
  struct Case {
    std::string scene;
    double effectivity_min, effectivity_max;
  };
  for (const Case& c : {Case{"hertz-exact", 2.712, 3.836}, Case{"bilateral", 4.358, 4.986}}) {
    const std::string dir = out_dir("ch10_" + c.scene);
    const ProgramRun r = run(std::string(CH10) + " --scene " + c.scene + " --quick --no-plot --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
    expect_output_contract(dir);
    for (const char* key : {"effectivity_min", "effectivity_max", "effectivity_ratio", "newton_steps_last", "steps",
                            "rate_in_n_adaptive", "rate_in_n_uniform", "err_energy_rel", "estimator_rel"})
      EXPECT_TRUE(std::isfinite(summary_value(dir, "results", key))) << c.scene << ": " << key;
    const std::string json = file_text(dir + "/summary.json");
    for (const char* key : {"time_to_1pct_adaptive_s", "time_to_1pct_uniform_s", "speedup_at_1pct"})
      EXPECT_NE(json.find(std::string("\"") + key + "\": "), std::string::npos) << c.scene << ": " << key;
    const double lo = summary_value(dir, "results", "effectivity_min"), hi = summary_value(dir, "results", "effectivity_max");
    EXPECT_GE(lo, 0.9 * c.effectivity_min) << c.scene;
    EXPECT_LE(hi, 1.1 * c.effectivity_max) << c.scene;
    EXPECT_NEAR(summary_value(dir, "results", "effectivity_ratio"), hi / lo, 1e-6 * hi / lo);
    EXPECT_LE(summary_value(dir, "results", "newton_steps_last"), 3.0) << c.scene;
    const std::string csv = dir + "/convergence.csv";
    const std::vector<std::string> columns = csv_header(csv);
    for (const char* column : {"dofs", "err_energy", "estimator", "effectivity", "time_s"})
      EXPECT_NE(std::find(columns.begin(), columns.end(), column), columns.end()) << c.scene << ": " << column;
    const std::vector<double> step = csv_column(csv, "step"), dofs = csv_column(csv, "dofs"),
                              time = csv_column(csv, "time_s"), effectivity = csv_column(csv, "effectivity");
    ASSERT_EQ(static_cast<double>(step.size()), summary_value(dir, "results", "steps")) << c.scene;
    for (std::size_t k = 0; k < step.size(); ++k) {
      EXPECT_EQ(step[k], static_cast<double>(k)) << c.scene;
      EXPECT_GE(effectivity[k], lo) << c.scene << ", step " << k;
      EXPECT_LE(effectivity[k], hi) << c.scene << ", step " << k;
      if (k > 0) {
        EXPECT_GT(dofs[k], dofs[k - 1]) << c.scene << ", step " << k;
        EXPECT_GE(time[k], time[k - 1]) << c.scene << ": time_s counts every step so far";
      }
    }
    EXPECT_EQ(summary_value(dir, "results", "dofs"), dofs.back());
    EXPECT_TRUE(std::filesystem::exists(dir + "/uniform.csv"));
  }
}

// The punch: no closed form, errors against the strain energy extrapolated from the last
// adaptive steps. Adaptive refinement keeps N^-1/2 (measured 0.485; band >= 0.45), uniform
// refinement loses it to the corners' r^(lambda-1) pressure (measured 0.300 over levels of 6.5k
// to 100k dofs; the wedge equation's lambda/2 = 0.278; band [0.25, 0.35]); the corner's pressure
// exponent on the last adaptive mesh (measured -0.433) near the equation's -0.4443. --quick
// alone refines uniformly to 1.6M dofs (48 s); --max-dofs 1e5 stops uniform refinement at
// 100k dofs and leaves the adaptive run as it was (25 steps, 38k dofs): 1.7 s.
TEST(Programs, ch10_punch_adaptive_keeps_the_rate_uniform_loses_it) {
  const std::string dir = out_dir("ch10_punch");
  const ProgramRun r = run(std::string(CH10) + " --scene punch --quick --max-dofs 1e5 --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  expect_output_contract(dir);
  const double adaptive = summary_value(dir, "results", "rate_in_n_adaptive");
  const double uniform = summary_value(dir, "results", "rate_in_n_uniform");
  EXPECT_GE(adaptive, 0.45) << r.output;
  EXPECT_GE(uniform, 0.25) << r.output;
  EXPECT_LE(uniform, 0.35) << r.output;
  EXPECT_NEAR(summary_value(dir, "results", "pressure_exponent_theory"), -0.4443, 1e-4);
  EXPECT_NEAR(summary_value(dir, "results", "pressure_exponent_measured"), -0.4443, 0.05);
  EXPECT_NEAR(summary_value(dir, "results", "dundurs_alpha"), 9.0 / 11, 1e-9);
  for (const char* key : {"reference_strain_energy", "finest_strain_energy", "newton_steps_last"})
    EXPECT_TRUE(std::isfinite(summary_value(dir, "results", key))) << key;
  EXPECT_EQ(csv_column(dir + "/convergence.csv", "dofs").size(),
            static_cast<std::size_t>(summary_value(dir, "results", "steps")));
}

// --refine body1: body 2 keeps its first mesh (64 triangles at every snapshot) while body 1
// refines; --refine body2 the other way round. Seven steps of hertz-exact, 0.1 s each.
TEST(Programs, ch10_a_body_that_may_not_refine_keeps_its_first_mesh) {
  for (int refined : {1, 2}) {
    const std::string dir = out_dir("ch10_refine_body" + std::to_string(refined));
    const ProgramRun r = run(std::string(CH10) + " --refine body" + std::to_string(refined) +
                             " --max-steps 7 --no-uniform --no-plot --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
    const int kept = 3 - refined;
    const int kept0 = triangles_at_step(dir, kept, 0);
    const int refined0 = triangles_at_step(dir, refined, 0);
    ASSERT_GT(kept0, 0) << r.output;
    for (int step : {3, 6}) {
      EXPECT_EQ(triangles_at_step(dir, kept, step), kept0) << "--refine body" << refined << ", step " << step;
      EXPECT_GT(triangles_at_step(dir, refined, step), refined0) << "--refine body" << refined << ", step " << step;
    }
    for (double v : csv_column(dir + "/convergence.csv", "err_energy")) EXPECT_TRUE(std::isfinite(v));
  }
}

// Doerfler's ends: theta = 1 bisects every triangle once per step (body 1's 100 triangles are
// 6400 after six steps), theta = 0 one triangle and its closure per step (40 steps to the step
// limit, body 1 at 106 triangles after six); both end with status 0 and write no NaN.
// --theta 1 --quick refines to 675k dofs (47 s): --max-dofs 2e4 stops it at 7 steps (1.3 s);
// --theta 0 --quick takes 3-6 s, most of it the uniform levels.
TEST(Programs, ch10_theta_one_and_zero_run_to_a_clear_end) {
  for (const std::string options : {"--theta 1 --max-dofs 2e4", "--theta 0"}) {
    const std::string dir = out_dir("ch10_theta");
    const ProgramRun r = run(std::string(CH10) + " --quick " + options + " --no-plot --out " + dir);
    ASSERT_EQ(r.status, 0) << options << "\n" << r.output;
    expect_output_contract(dir);
    const std::regex bad(R"((^|[,:\[ ])[-+]?(nan|inf|infinity)([\],} ]|$))", std::regex::icase);
    for (const char* f : {"/convergence.csv", "/uniform.csv", "/summary.json"})
      EXPECT_FALSE(std::regex_search(file_text(dir + f), bad)) << options << ": " << f;
    const int body1_0 = triangles_at_step(dir, 1, 0), body1_6 = triangles_at_step(dir, 1, 6);
    if (options.find("--theta 1") != std::string::npos) {
      EXPECT_EQ(body1_6, 64 * body1_0) << "theta = 1 bisects every triangle once per step";
    } else {
      EXPECT_EQ(summary_value(dir, "results", "steps"), 40.0);
      EXPECT_LT(body1_6, body1_0 + 20);
    }
  }
}

// Where a value is undefined the program says so, as every chapter does: with --quick the 1%
// error is never reached ("adaptive nan s ... nan times faster" was printed), and the punch has
// no exact error to print on each step ("err_energy=nan (nan%)").
TEST(Programs, ch10_undefined_values_are_said_not_printed_as_nan) {
  const std::regex bad(R"((^|[^A-Za-z])(nan|NaN|NAN|inf|Inf|INF)([^A-Za-z]|$))");
  for (const std::string options : {"--scene bilateral --quick", "--scene punch --max-steps 8 --no-uniform"}) {
    const std::string dir = out_dir("ch10_undefined");
    const ProgramRun r = run(std::string(CH10) + " " + options + " --no-plot --out " + dir);
    ASSERT_EQ(r.status, 0) << options << "\n" << r.output;
    EXPECT_FALSE(std::regex_search(r.output, bad)) << options << "\n" << r.output;
  }
}

// The punch's reference needs six adaptive steps: --max-steps 2 is refused before any work
// (status 2, naming the option), not after the loop with status 1 (it was: after the uniform
// levels, 23 s into the run).
TEST(Programs, ch10_punch_with_too_few_steps_for_its_reference_is_refused_before_work) {
  const std::string dir = out_dir("ch10_punch_two_steps");
  const auto start = std::chrono::steady_clock::now();
  const ProgramRun r = run(std::string(CH10) + " --scene punch --max-steps 2 --max-dofs 1e4 --no-plot --out " + dir);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--max-steps"), std::string::npos) << r.output;
  EXPECT_LT(seconds, 1.0);
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(Programs, ch11_refuses_malformed_input) {
  expect_all_refused(CH11, common_bad_inputs(),
                     {{"--E1 -1", "E1"}, {"--E2 0", "E2"}, {"--nu1 0.5", "nu1"}, {"--nu2 0.7", "nu2"},
                      {"--theta 1.5", "theta"}, {"--theta nan", "theta"}, {"--gamma0 0", "gamma0"},
                      {"--gamma0 -1", "gamma0"}, {"--penalty-gamma0 inf", "penalty-gamma0"},
                      {"--traction body3", "traction"}, {"--scene moon", "scene"}, {"--start warm", "start"},
                      {"--sweep everything", "sweep"}, {"--sweep gamma0 --levels 3 --sweep-level 3", "sweep-level"},
                      {"--krylov-max-dofs -1", "krylov-max-dofs"}, {"--h-ratio 0", "h-ratio"},
                      {"--quick --levels 4", "levels"}, {"--E1 1e11", "E1"}, {"--levels 11", "levels"}});
}

// The issue's "done means" at --quick sizes (levels of n1 = 8, 16, 32; 3,146 dofs at the end):
// convergence.csv with one column group per method, local_rates.csv, each method's energy rate,
// Newton steps and limit_ratio in summary.json, and the finest errors of each method pinned.
// They were computed once by this program and checked independently:
//  - the standard and dual mortar columns are chapter 5's own program on the same meshes
//    (ch05_unilateral_uzawa --scene hertz-exact --n0 8 --levels 3, with and without
//    --solver dual-newton), run here beside it: the same numbers to 1e-9;
//  - Nitsche's and penalty's discrete equations are those of a brute-force quadrature
//    (test_nitsche_contact: 4000 midpoints a segment, and central differences for the matrix),
//    their Newton residual is below 1e-12, and a cold start (u = 0 inside: 9-11 Newton steps
//    instead of 5-6) reaches the same errors to 1e-9.
TEST(Programs, ch11_quick_pins_the_finest_errors_of_every_method) {
  struct Pinned {
    const char* method;
    double energy, l2, pressure;
  };
  const Pinned pinned[] = {{"nitsche", 0.1086286723, 0.00345013533, 0.1576509056},
                           {"penalty", 0.1075315622, 0.003676347246, 0.1546620934},
                           {"penalty_fixed", 0.1085011062, 0.009745535249, 0.04807353409},
                           {"mortar", 0.1095315672, 0.003290620788, 0.1427825748},
                           {"dual", 0.1083101476, 0.003558901093, 0.04363608588}};
  const std::string dir = out_dir("ch11_quick"), cold = out_dir("ch11_quick_cold");
  const ProgramRun r = run(std::string(CH11) + " --quick --no-plot --out " + dir);
  ASSERT_EQ(r.status, 0) << r.output;
  expect_output_contract(dir);
  ASSERT_TRUE(std::filesystem::exists(dir + "/local_rates.csv"));
  const ProgramRun c = run(std::string(CH11) + " --quick --no-plot --start cold --out " + cold);
  ASSERT_EQ(c.status, 0) << c.output;
  const std::string csv = dir + "/convergence.csv";
  ASSERT_EQ(csv_column(csv, "h").size(), 3u);
  for (const Pinned& p : pinned) {
    const std::string m = p.method;
    EXPECT_NEAR(csv_column(csv, "err_energy_" + m).back(), p.energy, 1e-9) << m;
    EXPECT_NEAR(csv_column(csv, "err_l2_" + m).back(), p.l2, 1e-11) << m;
    EXPECT_NEAR(csv_column(csv, "err_pressure_" + m).back(), p.pressure, 1e-9) << m;
    EXPECT_NEAR(summary_value(dir, "results", "err_energy_" + m), p.energy, 1e-9) << m;
    EXPECT_TRUE(std::isfinite(summary_value(dir, "rates", "err_energy_" + m))) << m;
    EXPECT_GE(summary_value(dir, "results", "newton_steps_" + m), 1.0) << m;
    EXPECT_GT(summary_value(dir, "results", "limit_ratio_" + m), 0.0) << m;
    if (m != "mortar" && m != "dual") {
      EXPECT_LT(summary_value(dir, "results", "newton_residual_" + m), 1e-12) << m;
      EXPECT_LT(summary_value(dir, "results", "patch_test_rel_error_" + m), 1e-12) << m;
      EXPECT_NEAR(csv_column(cold + "/convergence.csv", "err_energy_" + m).back(), p.energy, 1e-9) << m;
      EXPECT_NEAR(csv_column(cold + "/convergence.csv", "err_l2_" + m).back(), p.l2, 1e-11) << m;
      EXPECT_LT(summary_value(dir, "results", "newton_steps_" + m), summary_value(cold, "results", "newton_steps_" + m))
          << m << ": the nested start saves Newton steps";
    }
  }
  EXPECT_EQ(summary_value(dir, "results", "limit_ratio"), summary_value(dir, "results", "limit_ratio_nitsche"));
  // chapter 5's program on the same meshes: the mortar columns
  for (const bool dual : {false, true}) {
    const std::string ch05 = out_dir(dual ? "ch11_ch05_dual" : "ch11_ch05");
    const ProgramRun r5 = run(std::string(CH05) + " --scene hertz-exact --n0 8 --levels 3 --no-compare --no-plot" +
                              (dual ? " --solver dual-newton" : "") + " --out " + ch05);
    ASSERT_EQ(r5.status, 0) << r5.output;
    const std::string m = dual ? "dual" : "mortar";
    for (const char* e : {"err_energy", "err_l2", "err_pressure", "half_width_error_m"})
      EXPECT_NEAR(csv_column(ch05 + "/convergence.csv", e).back(), csv_column(csv, std::string(e) + "_" + m).back(), 1e-9)
          << m << ": " << e;
  }
}

// What the theory says about gamma0, measured at --quick sizes: theta = -1 is stable for any
// gamma0 > 0 (Chouly, Hild and Renard 2015) and at gamma0 = 1e-3 stays within 2% of the mortar's
// energy error (measured 0.1110 against 0.1095); theta = 1 needs gamma0 large enough and at 1e-3
// does not converge (60 Newton steps), its iterate 12 times as far off; theta = 0 converges
// but to an error of 0.73. Penalty at the same gamma, without consistency, is 8 times off
// (measured 0.938).
TEST(Programs, ch11_skew_symmetric_nitsche_is_stable_for_a_tiny_gamma0_and_symmetric_is_not) {
  std::map<int, double> energy;
  std::map<int, double> converged;
  for (const int theta : {1, 0, -1}) {
    const std::string dir = out_dir("ch11_theta_" + std::to_string(theta + 1));
    const ProgramRun r = run(std::string(CH11) + " --quick --no-plot --gamma0 1e-3 --theta " + std::to_string(theta) +
                             " --out " + dir);
    ASSERT_EQ(r.status, 0) << r.output;
    energy[theta] = summary_value(dir, "results", "err_energy_nitsche");
    const std::string json = file_text(dir + "/summary.json");
    converged[theta] = json.find("\"converged_nitsche\": true") != std::string::npos ? 1.0
                       : json.find("\"converged_nitsche\": false") != std::string::npos ? 0.0 : std::nan("");
    if (theta == -1) {
      EXPECT_NEAR(energy[theta] / summary_value(dir, "results", "err_energy_mortar"), 1.0, 0.02);
      EXPECT_GT(summary_value(dir, "results", "err_energy_penalty"), 5 * energy[theta]);
    }
  }
  EXPECT_EQ(converged[-1], 1.0);
  EXPECT_EQ(converged[0], 1.0);
  EXPECT_EQ(converged[1], 0.0);
  EXPECT_GT(energy[1], 10 * energy[-1]);
  EXPECT_GT(energy[0], 5 * energy[-1]);
}
