// The figures of chapter 6 that chapters 3-5 do not draw.
#pragma once

#include <string>

#include "common/study/bilateral_study.hpp"
#include "hertz_study.hpp"

namespace chapter06 {

// dual_basis.png: on a 6-element trace, the hats of M_h^1 (top) and the dual functions on the
// same nodes (bottom), each psi_i in its own colour, jumps drawn.
void plot_dual_basis(const std::string& folder, bool run);

// standard_vs_dual.png: energy error and pressure errors against h for both bases;
// error_vs_time.png: energy error against wall time for both, beside the limit.
// `standard` may be null (--no-compare); `mesh` is the run's mesh options for the titles.
void plot_bases_against_h(const std::string& folder, const mortar::ConvergenceTable& dual,
                          const mortar::ConvergenceTable* standard, const std::string& mesh, bool run);
void plot_bases_against_time(const std::string& folder, const mortar::ConvergenceTable& dual,
                             const mortar::ConvergenceTable* standard, const std::string& mesh, bool run);

// dual_pressure.png: the manufactured pressure, the coefficients lambda_i at their nodes and the
// function sum_i lambda_i psi_i with its jumps (top: all of Gamma_c; bottom: near x = L/2).
void plot_dual_pressure(const std::string& folder, const mortar::BilateralLevel& level,
                        const mortar::ManufacturedContact& exact, const std::string& mesh, bool run);

// hertz_pressure.png: the Hertz contact pressure of both bases on the finest level, zoomed on
// the contact zone: the coefficients of both, and the dual function with its negative parts.
void plot_hertz_pressure(const std::string& folder, const HertzStudy& study, const HertzOptions& o, bool run);

}  // namespace chapter06
