// One level of chapter 3: two bodies glued by pointwise matching, step by step.
#pragma once

#include "common/contact/bilateral_contact.hpp"

namespace chapter03 {

// The bodies are meshed and loaded (the study does that, common/study/bilateral_study.cpp);
// every step from K to (u_h, lambda_h) and what they say on Gamma_c is here, in the order of
// the lecture (README.md, "The program"). options.matching is not read: this chapter always
// glues at the nodes of the non-mortar side.
mortar::BilateralSolution solve_pointwise_matching(const mortar::TwoBodies& bodies, const mortar::SceneData& scene,
                                                   const mortar::BilateralOptions& options);

}  // namespace chapter03
