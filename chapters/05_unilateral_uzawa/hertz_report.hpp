// What the Hertz scene reports at the finest level, as two separate numbers: the
// discretization error (the level against the finite-body reference) and the model error
// (the reference against half-space Hertz at the reference's force), with the reference's
// own estimated error; in summary.json and on the console.
#pragma once

#include "common/study/json_writer.hpp"
#include "hertz_reference.hpp"

namespace chapter05 {

void add_hertz_results(mortar::JsonObject& results, const Options& o, const mortar::ConvergenceTable& table,
                       const UnilateralLevel& finest, const HertzReference& ref);
void print_hertz_errors(const Options& o, const mortar::ConvergenceTable& table,
                        const UnilateralLevel& finest, const HertzReference& ref);

}  // namespace chapter05
