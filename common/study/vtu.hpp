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

// A curve on Gamma_c = (0, L) x {0} as VTK line cells between consecutive points x (sorted),
// each field one value per point (for example the contact pressure lambda_h).
struct CurveField {
  std::string name;
  std::vector<double> value;
};
void write_curve_vtu(const std::string& path, const std::vector<double>& x, const std::vector<CurveField>& fields);

}  // namespace mortar
