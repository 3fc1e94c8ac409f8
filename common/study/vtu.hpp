// VTK unstructured-grid (.vtu) output for ParaView: nodal displacement, element stress.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "common/fem/mesh.hpp"

namespace mortar {

// u: 2 dofs per node; stress: (sigma_xx, sigma_yy, sigma_xy) per triangle.
void write_vtu(const std::string& path, const Mesh& mesh, const Eigen::VectorXd& u,
               const std::vector<Eigen::Vector3d>& stress);

}  // namespace mortar
