// Chapter 10's figures: both meshes after 0, 3 and 6 steps with a zoom on the contact zone, the
// indicator map, error and estimator against N (adaptive and uniform), error against time, the
// effectivity against N, and the pressure at the edge of the zone on the last mesh.
#pragma once

#include "adaptive_loop.hpp"
#include "options.hpp"

namespace chapter10 {

void write_figures(const Options& o, const LoopResult& adaptive, const LoopResult* uniform, const Scene& scene,
                   bool run_gnuplot);

}  // namespace chapter10
