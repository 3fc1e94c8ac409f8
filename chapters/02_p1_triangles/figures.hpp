// The figures of chapter 2: error against h, error against time, the deformed mesh.
#pragma once

#include <string>

#include "common/study/convergence_study.hpp"
#include "common/fem/mesh.hpp"

namespace chapter02 {

void plot_error_vs_h(const std::string& folder, const mortar::ConvergenceTable& table, bool run);
void plot_error_vs_time(const std::string& folder, const mortar::ConvergenceTable& table, bool run);
void plot_deformed_mesh(const std::string& folder, const mortar::Mesh& mesh,
                        const Eigen::VectorXd& u, bool run);

}  // namespace chapter02
