// The figures and the contact.csv of chapter 5.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "study.hpp"

namespace chapter05 {

void write_contact_csv(const std::string& path, const UnilateralLevel& r);
void plot_pressures(const std::string& folder, const Options& o, const Reference& ref,
                    const mortar::ExactContact& exact,
                    const std::vector<const UnilateralLevel*>& levels, bool run);
// Every title names the run's options (run_label), so that runs with other options never give
// figures with the same title.
void plot_contact_state(const std::string& folder, const Options& o, const UnilateralLevel& r, bool run);
void plot_errors(const std::string& folder, const Options& o, const mortar::ConvergenceTable& table, bool run);
// The Hertz scene: each error against the reference, the distance to Hertz, the model error
// and the reference's own error; no theorem bounds these, so no theorem's slope is drawn.
void plot_hertz_errors(const std::string& folder, const Options& o, const mortar::ConvergenceTable& table,
                       const HertzReference& ref, bool run);
// The exact scenes (signorini, hertz-exact): the energy error of both matchings (and of
// chapter 6's dual basis, from the solver comparison) against h with slopes 1/4 and 1, both
// through the coarsest point.
void plot_theorem_5_1(const std::string& folder, const Options& o, const mortar::ConvergenceTable& table,
                      const std::vector<SolverRun>& runs, bool run);
// One level's pressure on Gamma_c and its mesh sizes.
struct LevelPressure {
  mortar::InterfaceCurve pressure;
  double h1 = 0, h2 = 0;
};
// hertz-exact: the pressure of the three finest levels near the right edge of the contact zone,
// beside the exact square root.
void plot_edge_pressure(const std::string& folder, const Options& o, const mortar::ExactContact& exact,
                        const std::vector<LevelPressure>& levels, bool run);
void plot_solver_comparison(const std::string& folder, const Options& o, const std::vector<SolverRun>& runs,
                            const std::string& error_name, bool run);

}  // namespace chapter05
