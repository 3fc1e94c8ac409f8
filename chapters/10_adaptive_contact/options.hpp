// Chapter 10's options, checked before any work starts (status 2 with a message naming the
// option otherwise).
#pragma once

#include <string>

#include "adaptive_loop.hpp"
#include "scenes.hpp"
#include "common/study/options.hpp"

namespace chapter10 {

struct Options {
  SceneOptions scene;
  LoopOptions loop;
  std::string start = "nested";  // or "cold"
  std::string refine = "both";   // or "body1", "body2": the other body keeps its first mesh
  double uniform_target = 0.01;  // uniform refinement runs until this relative energy error
  bool no_uniform = false;
  std::string out = "results/ch10_adaptive_contact";
  bool no_plot = false, quick = false;
};

void parse_options(mortar::OptionParser& parser, Options& o, int argc, char** argv);

}  // namespace chapter10
