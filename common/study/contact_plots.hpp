// Figures of chapters 3 and 4: errors against h with the theorem's slopes, error against
// time, the pressure and the jump along Gamma_c (all of it, and a zoom on four elements),
// sigma_22 along Gamma_c in the patch test.
#pragma once

#include <string>
#include <vector>

#include "common/study/bilateral_study.hpp"
#include "common/study/plot.hpp"

namespace mortar {

// Errors against h: u in energy and L2, the pressure in L2 and in the mesh-dependent H^{-1/2}
// norm each beside its best approximation in M_h^1, the jump. Series, in order (the anchors
// of the slopes): 0 energy, 1 u L2, 2 pressure L2, 3 its best approximation, 4 pressure
// H^{-1/2}_h, 5 its best approximation, 6 jump. Each slope is drawn in its own colour and dash
// (reference_slope_style), with its label: give one only where a theorem bounds the anchor.
// An empty log-log figure, and one column of a table against another as a series.
Figure log_log_figure(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                      const std::string& key);
Series table_series(const ConvergenceTable& table, const std::string& x, const std::string& y,
                    const std::string& title, const std::string& style);

void plot_contact_errors(const std::string& folder, const ConvergenceTable& table,
                         const std::string& title, const std::vector<ReferenceSlope>& slopes,
                         bool run);
void plot_contact_error_vs_time(const std::string& folder, const ConvergenceTable& table,
                                const std::string& title, bool run);
void plot_pressure(const std::string& folder, const BilateralLevel& level,
                   const ManufacturedContact& exact, const std::string& title, bool run);
void plot_jump(const std::string& folder, const BilateralLevel& level, const std::string& title,
               bool run);
// `integral_label` names the integral method's curves (chapter 6: "integral matching, dual basis").
void plot_patch_test(const std::string& folder, const PatchTestResult& pointwise,
                     const PatchTestResult& integral, bool run,
                     const std::string& integral_label = "integral matching");

}  // namespace mortar
