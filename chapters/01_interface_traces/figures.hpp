// The figures of chapter 1.
#pragma once

#include <string>
#include <vector>

#include "common/study/convergence_study.hpp"
#include "transfer_case.hpp"

namespace chapter01 {

// The two grids, the merged grid, w, its side-2 interpolant and both transfers to side 1.
void plot_transfers(const std::string& folder, const TransferResult& r, const TraceFunction& w,
                    bool run);
// Reference slopes l2_rate and h1_rate; h1_rate NaN drops the H1 curves (no H1 error exists).
void plot_error_vs_h(const std::string& folder, const mortar::ConvergenceTable& table,
                     const std::string& case_label, double l2_rate, double h1_rate, bool run);
void plot_error_vs_time(const std::string& folder, const mortar::ConvergenceTable& table,
                        const std::string& case_label, bool run);

struct IntegralCurve {
  std::string label;
  std::vector<double> h1, pointwise, mortar;
};
void plot_integral_errors(const std::string& folder, const std::vector<IntegralCurve>& curves,
                          bool run);

}  // namespace chapter01
