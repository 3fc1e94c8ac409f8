// VTK unstructured-grid (.vtu) output for ParaView: one piece of points, cells of one kind,
// and data on the points and on the cells, written as XML with each array either as text
// (ascii) or as base64 of the raw little-endian bytes (binary: VTK's inline binary format,
// a UInt32 byte count, then the data), which is about half the size and writes much faster.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "common/fem/mesh.hpp"
#include "common/fem/p1_elasticity.hpp"

namespace mortar {

enum class VtuFormat { ascii, binary };

// One named array: `components` values per point (or per cell), interleaved.
struct VtuArray {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

struct VtuGrid {
  std::vector<Eigen::Vector2d> points;  // written with z = 0
  int cell_type = 5;                    // VTK_TRIANGLE = 5, VTK_LINE = 3
  int points_per_cell = 3;
  std::vector<int> connectivity;        // points_per_cell point indices per cell
  std::vector<VtuArray> point_data, cell_data;
  int num_cells() const { return points_per_cell > 0 ? static_cast<int>(connectivity.size()) / points_per_cell : 0; }
};

// Throws std::invalid_argument when an array's length does not match the points or cells.
void write_vtu(const std::string& path, const VtuGrid& grid, VtuFormat format);

// The von Mises stress of plane strain, where sigma_zz = nu (sigma_xx + sigma_yy):
// sqrt(((s_xx - s_yy)^2 + (s_yy - s_zz)^2 + (s_zz - s_xx)^2) / 2 + 3 s_xy^2).
double von_mises_plane_strain(const Eigen::Vector3d& stress, double nu);

// One elastic body: the displacement u (2 dofs per node) as point data; sigma_xx, sigma_yy,
// sigma_xy and von Mises, constant per P1 triangle, as cell data.
VtuGrid body_grid(const Mesh& mesh, const Material& material, const Eigen::VectorXd& u);

// u: 2 dofs per node; stress: (sigma_xx, sigma_yy, sigma_xy) per triangle (chapter 2).
void write_vtu(const std::string& path, const Mesh& mesh, const Eigen::VectorXd& u,
               const std::vector<Eigen::Vector3d>& stress);

// A curve on Gamma_c = (0, L) x {0} as VTK line cells between consecutive points x (sorted),
// each field one value per point (for example the contact pressure lambda_h).
struct CurveField {
  std::string name;
  std::vector<double> value;
};
void write_curve_vtu(const std::string& path, const std::vector<double>& x, const std::vector<CurveField>& fields,
                     VtuFormat format = VtuFormat::ascii);

}  // namespace mortar
