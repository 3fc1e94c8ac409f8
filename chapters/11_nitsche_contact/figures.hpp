// Chapter 11's figures: the energy error of every method against h on one plot, the pressure at
// the contact edge on the finest level, and (with --sweep gamma0) the errors against gamma0.
#pragma once

#include <string>
#include <vector>

#include "common/study/convergence_study.hpp"
#include "options.hpp"
#include "study.hpp"

namespace chapter11 {

void write_figures(const Options& o, const mortar::ConvergenceTable& table, const std::vector<Level>& levels,
                   const Scene& scene, const std::vector<SweepPoint>& sweep, bool run_gnuplot);

}  // namespace chapter11
