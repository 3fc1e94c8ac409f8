// One level of chapter 7: two P2 bodies glued by pointwise or integral matching, step by step.
#pragma once

#include "common/contact/bilateral_contact.hpp"

namespace chapter07 {

// The bodies are meshed with P2 triangles and loaded (the study does that,
// common/study/bilateral_study.cpp, with degree 2); every step from K to (u_h, lambda_h) is here,
// in the order of the lecture (README.md, "The program"), for options.matching.
mortar::BilateralSolution solve_quadratic(const mortar::TwoBodies& bodies, const mortar::SceneData& scene,
                                          const mortar::BilateralOptions& options);

}  // namespace chapter07
