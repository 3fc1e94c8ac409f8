// Figures of chapters 3 and 4: errors against h with the theorem's slopes, error against
// time, the pressure and the jump along Gamma_c, sigma_22 along Gamma_c in the patch test.
#pragma once

#include <string>
#include <vector>

#include "common/bilateral_study.hpp"
#include "common/plot.hpp"

namespace mortar {

void plot_contact_errors(const std::string& folder, const ConvergenceTable& table,
                         const std::string& title, const std::vector<ReferenceSlope>& slopes,
                         bool run);
void plot_contact_error_vs_time(const std::string& folder, const ConvergenceTable& table,
                                const std::string& title, bool run);
void plot_pressure(const std::string& folder, const BilateralLevel& level,
                   const ManufacturedContact& exact, const std::string& title, bool run);
void plot_jump(const std::string& folder, const BilateralLevel& level, const std::string& title,
               bool run);
void plot_patch_test(const std::string& folder, const PatchTestResult& pointwise,
                     const PatchTestResult& integral, bool run);

}  // namespace mortar
