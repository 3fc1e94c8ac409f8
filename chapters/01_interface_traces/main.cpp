// Chapter 1: interface traces on two nonmatching 1D grids.
//
// Gamma_c = (0, L) carries two grids: xi^1 of the non-mortar side 1 and xi^2 of the mortar
// side 2. A trace w is known on side 2 through its nodal interpolant w2, and is carried to
// side 1 in the two ways the paper glues the bodies: pointwise (w1(a) = w2(a) at the nodes of
// xi^1, space V_h^P) and by the mortar projection (int (w1 - w2) psi = 0 for every psi in
// M_h^1, space V_h^I). The program measures both against the exact w as h shrinks, and checks
// which one keeps int w: the mortar projection does, to round-off, for any pair of grids.
//
//   ch01_interface_traces                            # smooth trace, h2/h1 = 3/2
//   ch01_interface_traces --trace rough --h-ratio 1/3   # 24 kinks
//   ch01_interface_traces --jitter 0.3 --levels 9
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "common/study/convergence_study.hpp"
#include "common/linalg/memory_estimate.hpp"
#include "common/linalg/spd_solver.hpp"
#include "common/study/options.hpp"
#include "common/study/timing_report.hpp"
#include "common/interface/trace_transfer.hpp"
#include "figures.hpp"
#include "trace_functions.hpp"
#include "transfer_case.hpp"
#include "transfer_operators.hpp"

namespace {

struct Options {
  int n0 = 12;
  int levels = 7;
  int threads = mortar::default_solver_threads();
  double h_ratio = 1.5;
  std::string trace = "smooth";
  double L = 1.0;
  double jitter = 0.0;
  std::string out = "results/ch01_interface_traces";
  bool quick = false;
  bool no_plot = false;
  bool profile = false;  // print where the finest level's time goes
};

// The sweep puts up to 10 n1 elements on side 2 (ratio 1/10): keep it within a minute.
constexpr long long max_side1_elements = 1 << 16;

// What the run holds at its largest, counted before any work: the three transfers of
// operator_facts as dense matrices (n1 = 4 n0), and the traces of the finest level, where the
// sweep's ratio 1/10 gives side 2 ten times the elements (trace_bytes_per_node covers the
// nodes, the merged grid and the mortar matrices of both sides).
void check_memory(const mortar::OptionParser& parser, const Options& o) {
  constexpr double trace_bytes_per_node = 1000;
  const double facts_n1 = 4.0 * o.n0, facts_n2 = std::max(1.0, std::round(facts_n1 / o.h_ratio));
  const double finest_n1 = std::ldexp(static_cast<double>(o.n0), o.levels - 1);
  const double finest_nodes = finest_n1 + std::max(10 * finest_n1, finest_n1 / o.h_ratio) + 2;
  char dense[128], traces[96];
  std::snprintf(dense, sizeof dense, "the transfers as three dense %.0f x %.0f matrices (n1 = 4 n0)", facts_n1 + 1,
                facts_n2 + 1);
  std::snprintf(traces, sizeof traces, "the finest level's traces (%.3g nodes)", finest_nodes);
  const std::string memory = mortar::memory_shortfall(
      {{dense, 3 * mortar::dense_bytes(facts_n1 + 1, facts_n2 + 1)}, {traces, finest_nodes * trace_bytes_per_node}},
      mortar::machine_memory(), "use a smaller --n0, a larger --h-ratio or fewer --levels");
  if (!memory.empty()) parser.fail("n0", memory);
}

void parse_options(mortar::OptionParser& parser, Options& o, int argc, char** argv) {
  using mortar::Range;
  parser.add_int("n0", o.n0, "side-1 elements on the coarsest level", Range::closed(2, max_side1_elements));
  parser.add_int("levels", o.levels, "refinement levels, h halving each time (rates need 3)", Range::closed(3, 20));
  parser.add_double("h-ratio", o.h_ratio, "mesh ratio r = h2 / h1 (side 2 gets round(n1 / r) elements)",
                    Range::closed(0.01, 100));
  parser.add_choice("trace", o.trace, {"smooth", "kink", "rough", "edge"},
                    "trace for the convergence table (edge: a sqrt(1 - x^2/a^2)_+ pressure shape)");
  parser.add_double("L", o.L, "length of Gamma_c [m]", Range::closed(1e-6, 1e6));
  parser.add_double("jitter", o.jitter, "random node displacement, fraction of h", Range::closed(0, 0.4));
  parser.add_string("out", o.out, "output folder");
  parser.add_flag("quick", o.quick, "small sizes for tests (sets levels = 4; not with --levels)");
  parser.add_flag("no-plot", o.no_plot, "write data and scripts but do not run gnuplot");
  parser.add_flag("profile", o.profile, "print where the finest level's time goes, beside the limit's (and write profile.csv)");
  parser.add_int("threads", o.threads, mortar::solver_threads_help, mortar::Range::closed(1, 64));
  parser.parse(argc, argv);
  mortar::set_solver_threads(o.threads);
  parser.apply_quick(o.quick, {{"levels", o.levels, 4}});  // refuses --levels beside --quick
  if (static_cast<long long>(o.n0) << (o.levels - 1) > max_side1_elements)
    parser.fail("levels", "the finest level would have more than " +
                              std::to_string(max_side1_elements) + " side-1 elements");
  check_memory(parser, o);
  mortar::prepare_output_folder(parser, o.out);
}

double rate_or_nan(const std::map<std::string, double>& rates, const std::string& name) {
  const auto it = rates.find(name);
  return it == rates.end() ? std::nan("") : it->second;
}

mortar::Row table_row(const chapter01::TransferResult& r) {
  // a trace with a square-root edge has no H1 error (w' is not square integrable): no column
  const bool h1 = std::isfinite(r.mortar_errors.h1);
  mortar::Row row = {{"h", std::max(r.trace1.max_element_length(), r.trace2.max_element_length())},
                     {"h1", r.trace1.max_element_length()},
                     {"h2", r.trace2.max_element_length()},
                     {"n1", r.trace1.num_elements()},
                     {"n2", r.trace2.num_elements()},
                     {"dofs", r.trace1.num_nodes()},
                     {"time_s", r.time_s},
                     {"limit_s", r.limit_s},
                     {"err_mortar_l2", r.mortar_errors.l2}};
  if (h1) row.push_back({"err_mortar_h1", r.mortar_errors.h1});
  row.push_back({"err_pointwise_l2", r.pointwise_errors.l2});
  if (h1) row.push_back({"err_pointwise_h1", r.pointwise_errors.h1});
  row.push_back({"mortar_integral_rel_error", r.mortar_errors.integral_rel_error});
  row.push_back({"pointwise_integral_rel_error", r.pointwise_errors.integral_rel_error});
  return row;
}

// Every trace, every ratio from 1/10 to 10, every level: the worst integral errors, and the
// rows of cases.csv. A ratio whose grids are nested (every node of xi^2 on xi^1, where
// pointwise transfer is exact) says so in its label.
struct Sweep {
  double worst_mortar = 0, worst_pointwise = 0;
  std::vector<chapter01::IntegralCurve> smooth_curves;
};

Sweep sweep_ratios(const Options& o) {
  const std::vector<std::pair<std::string, double>> ratios = {
      {"1/10", 0.1}, {"1/3", 1.0 / 3}, {"2/3", 2.0 / 3}, {"1", 1.0}, {"3/2", 1.5}, {"3", 3.0}, {"10", 10.0}};
  Sweep s;
  std::ofstream csv(o.out + "/cases.csv");
  csv << "trace,h_ratio,level,n1,n2,h1,h2,nested,err_mortar_l2,err_pointwise_l2,err_mortar_h1,"
         "err_pointwise_h1,mortar_integral_rel_error,pointwise_integral_rel_error\n";
  for (const std::string trace : {"smooth", "kink", "rough"}) {
    const chapter01::TraceFunction w = chapter01::trace_function(trace, o.L);
    for (const auto& [label, ratio] : ratios) {
      chapter01::IntegralCurve curve{"h2/h1 = " + label, {}, {}, {}};
      int nested_levels = 0;
      double lowest = 1e300, highest = 0;  // the actual h2/h1, after rounding n2
      for (int level = 0; level < o.levels; ++level) {
        const int n1 = o.n0 << level;
        const auto r = chapter01::run_transfer_case({n1, chapter01::side2_elements(n1, ratio), o.jitter}, w);
        const bool nested = chapter01::nested(r.trace2, r.trace1);
        nested_levels += nested;
        const double actual = r.trace2.max_element_length() / r.trace1.max_element_length();
        lowest = std::min(lowest, actual);
        highest = std::max(highest, actual);
        csv << trace << "," << label << "," << level << "," << n1 << "," << r.trace2.num_elements()
            << "," << r.trace1.max_element_length() << "," << r.trace2.max_element_length() << ","
            << nested << ","
            << r.mortar_errors.l2 << "," << r.pointwise_errors.l2 << "," << r.mortar_errors.h1
            << "," << r.pointwise_errors.h1 << "," << r.mortar_errors.integral_rel_error << ","
            << r.pointwise_errors.integral_rel_error << "\n";
        s.worst_mortar = std::max(s.worst_mortar, r.mortar_errors.integral_rel_error);
        s.worst_pointwise = std::max(s.worst_pointwise, r.pointwise_errors.integral_rel_error);
        curve.h1.push_back(r.trace1.max_element_length());
        curve.pointwise.push_back(r.pointwise_errors.integral_rel_error);
        curve.mortar.push_back(r.mortar_errors.integral_rel_error);
      }
      if (highest > 1.05 * ratio || lowest < ratio / 1.05) {
        char actual[64];
        std::snprintf(actual, sizeof actual, " (actual %.3g to %.3g)", lowest, highest);
        curve.label += actual;
      }
      if (nested_levels > 0)
        curve.label += " (xi^2 in xi^1 at " + std::to_string(nested_levels) + " of " +
                       std::to_string(o.levels) + " levels)";
      if (trace == "smooth" && ratio != 1.0) s.smooth_curves.push_back(curve);
    }
  }
  return s;
}


// The transfers as matrices on one level (n1 = 4 n0): forces of a uniform traction carried
// from side 1 to side 2, how far one side-2 hat reaches on side 1, and int w without the end
// modification of M_h^1.
struct OperatorFacts {
  int n1 = 0, n2 = 0;
  chapter01::ForceTransfer mortar_force, pointwise_force;
  chapter01::Reach mortar_reach, pointwise_reach;
  double plain_hats_integral_rel_error = 0;
};

OperatorFacts operator_facts(const Options& o, const chapter01::TraceFunction& w) {
  OperatorFacts f;
  f.n1 = 4 * o.n0;
  f.n2 = chapter01::side2_elements(f.n1, o.h_ratio);
  const auto t1 = mortar::uniform_trace(o.L, f.n1, o.jitter, 1), t2 = mortar::uniform_trace(o.L, f.n2, o.jitter, 2);
  const Eigen::MatrixXd mortar = chapter01::mortar_matrix(t1, t2, mortar::end_modified_p1(t1));
  const Eigen::MatrixXd pointwise = chapter01::pointwise_matrix(t1, t2);
  f.mortar_force = chapter01::uniform_traction_transfer(mortar, t1, t2);
  f.pointwise_force = chapter01::uniform_traction_transfer(pointwise, t1, t2);
  f.mortar_reach = chapter01::reach_of_middle_hat(mortar);
  f.pointwise_reach = chapter01::reach_of_middle_hat(pointwise);
  std::vector<double> w2;
  for (double x : t2.x) w2.push_back(w.value(x));
  const Eigen::VectorXd w1 = chapter01::mortar_matrix(t1, t2, chapter01::plain_interior_hats(t1)) *
                             Eigen::Map<const Eigen::VectorXd>(w2.data(), static_cast<Eigen::Index>(w2.size()));
  const double int2 = mortar::integral(t2, w2);
  f.plain_hats_integral_rel_error =
      std::fabs(mortar::integral(t1, std::vector<double>(w1.data(), w1.data() + w1.size())) - int2) / std::fabs(int2);
  return f;
}

void print_operator_facts(const OperatorFacts& f) {
  std::printf("as matrices w1 = P w2 (n1 = %d, n2 = %d), a uniform traction carried from side 1 to side 2 "
              "as F2 = P^T F1:\n"
              "  total force |sum F2 - sum F1| / sum F1: mortar %.1e, pointwise %.1e (equal and opposite for both)\n"
              "  nodal forces max |F2 - consistent load| / max load: mortar %.1e, pointwise %.2f\n"
              "  one side-2 hat reaches %d of %d side-1 nodes by the mortar projection (decay %.3f per element), "
              "%d by pointwise transfer\n"
              "  plain interior hats as M_h (no end modification): |int w1 - int w2| / |int w2| = %.2e\n",
              f.n1, f.n2, f.mortar_force.total_rel_error, f.pointwise_force.total_rel_error,
              f.mortar_force.nodal_rel_error, f.pointwise_force.nodal_rel_error, f.mortar_reach.nodes_reached,
              f.mortar_reach.nodes, f.mortar_reach.decay_per_element, f.pointwise_reach.nodes_reached,
              f.plain_hats_integral_rel_error);
}

}  // namespace

int main(int argc, char** argv) {
  // 1. Options, checked before any work starts.
  Options o;
  mortar::OptionParser parser("ch01_interface_traces",
                              "Pointwise transfer against mortar projection of a trace between "
                              "two nonmatching 1D grids on Gamma_c.");
  parse_options(parser, o, argc, argv);
  try {
    // 2. The convergence table of the chosen trace and mesh ratio.
    const chapter01::TraceFunction w = chapter01::trace_function(o.trace, o.L);
    mortar::ConvergenceTable table;
    chapter01::TransferResult finest;
    for (int level = 0; level < o.levels; ++level) {
      const int n1 = o.n0 << level;
      finest = chapter01::run_transfer_case({n1, chapter01::side2_elements(n1, o.h_ratio), o.jitter}, w);
      table.add(table_row(finest));
    }

    // 3. The sweep over traces and mesh ratios 1/10 .. 10: conservation of int w.
    const Sweep sweep = sweep_ratios(o);

    // 4. The transfers as matrices: forces, reach, and the end modification.
    const OperatorFacts facts = operator_facts(o, w);

    // 5. convergence.csv and summary.json.
    const auto rates = table.rates();
    mortar::JsonObject results;
    results.set("h1_m", finest.trace1.max_element_length())
        .set("h2_m", finest.trace2.max_element_length())
        .set("err_mortar_l2", finest.mortar_errors.l2)
        .set("err_pointwise_l2", finest.pointwise_errors.l2)
        .set("mortar_integral_rel_error", sweep.worst_mortar)
        .set("pointwise_integral_rel_error", sweep.worst_pointwise)
        .set("mortar_uniform_traction_nodal_rel_error", facts.mortar_force.nodal_rel_error)
        .set("pointwise_uniform_traction_nodal_rel_error", facts.pointwise_force.nodal_rel_error)
        .set("pointwise_total_force_rel_error", facts.pointwise_force.total_rel_error)
        .set("mortar_hat_reach_nodes", facts.mortar_reach.nodes_reached)
        .set("plain_hats_integral_rel_error", facts.plain_hats_integral_rel_error);
    mortar::add_timing(results, finest.timing);
    table.write_csv(o.out + "/convergence.csv");
    mortar::write_summary(o.out + "/summary.json", parser, rates, results);
    if (o.profile) mortar::report_profile(finest.timing, o.out);
    // Interpolation theory: smooth in H^2 (L2 2, H1 1); kinks in H^{3/2-eps} (3/2, 1/2);
    // a square-root edge in H^{1-eps} (L2 1, and w' not square integrable: no H1 error).
    const bool smooth = o.trace == "smooth", edge = o.trace == "edge";
    const double l2_theory = smooth ? 2.0 : edge ? 1.0 : 1.5;
    const double h1_theory = smooth ? 1.0 : edge ? std::nan("") : 0.5;
    // an edge trace has no H1 column: its rate is undefined, and said so rather than "nan"
    const auto h1_rate = [&](const char* column) {
      const double r = rate_or_nan(rates, column);
      char text[32];
      std::snprintf(text, sizeof text, "%.3f", r);
      return std::isnan(r) ? std::string("undefined") : std::string(text);
    };
    std::printf("rates (three finest levels): mortar L2 %.3f, H1 %s; pointwise L2 %.3f, H1 %s\n"
                "interpolation theory for a %s trace: L2 %s, H1 %s\n",
                rates.at("err_mortar_l2"), h1_rate("err_mortar_h1").c_str(), rates.at("err_pointwise_l2"),
                h1_rate("err_pointwise_h1").c_str(), o.trace.c_str(), smooth ? "2" : edge ? "1" : "3/2",
                smooth ? "1" : edge ? "none (w' is not square integrable: no H1 columns)"
                               : "1/2 (error bounds; with one kink the constant moves from level to level)");
    std::printf("worst |int w1 - int w2| / |int w2| over all cases: mortar %.2e, pointwise %.2e\n",
                sweep.worst_mortar, sweep.worst_pointwise);
    print_operator_facts(facts);

    // 6. Figures.
    char label[96];
    std::snprintf(label, sizeof label, "%s trace, h2/h1 = %g", o.trace.c_str(), o.h_ratio);
    const chapter01::TraceFunction kink = chapter01::trace_function("kink", o.L);
    chapter01::plot_transfers(o.out, chapter01::run_transfer_case({4, 13, 0.0}, kink), kink, !o.no_plot);
    chapter01::plot_error_vs_h(o.out, table, label, l2_theory, h1_theory, !o.no_plot);
    chapter01::plot_error_vs_time(o.out, table, label, !o.no_plot);
    chapter01::plot_integral_errors(o.out, sweep.smooth_curves, !o.no_plot);
    std::printf("wrote %s\n", o.out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ch01_interface_traces: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
