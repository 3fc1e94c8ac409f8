// Chapter 11's figures: the energy and pressure errors of every method against h, the pressure at
// the contact edge on the finest level, and with a sweep the errors against gamma0 or E1 / E2.
#pragma once

#include <string>
#include <vector>

#include "common/study/convergence_study.hpp"
#include "options.hpp"
#include "study.hpp"

namespace chapter11 {

void write_figures(const Options& o, const mortar::ConvergenceTable& table, const std::vector<Level>& levels,
                   const Scene& scene, const std::vector<SweepPoint>& sweep,
                   const std::vector<StiffnessPoint>& stiffness, bool run_gnuplot);

}  // namespace chapter11
