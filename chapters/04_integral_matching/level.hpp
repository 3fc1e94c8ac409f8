// One level of chapter 4: two bodies glued by integral (mortar) matching, step by step.
#pragma once

#include "common/contact/bilateral_contact.hpp"

namespace chapter04 {

// The bodies are meshed and loaded (the study does that, common/study/bilateral_study.cpp);
// every step from K to (u_h, lambda_h) and what they say on Gamma_c is here, in the order of
// the lecture (README.md, "The program"). options.matching is not read: this chapter always
// glues by integral matching.
mortar::BilateralSolution solve_integral_matching(const mortar::TwoBodies& bodies, const mortar::SceneData& scene,
                                                  const mortar::BilateralOptions& options);

}  // namespace chapter04
