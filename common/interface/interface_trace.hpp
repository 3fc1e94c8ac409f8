// The trace of one body on the contact line Gamma_c: its nodes xi^l in increasing x, and the
// P1 hat functions phi^l_j they carry (paper section 3, the 1D mesh T_c^l).
#pragma once

#include <Eigen/Sparse>
#include <vector>

#include "common/fem/mesh.hpp"

namespace mortar {

struct InterfaceTrace {
  std::vector<double> x;   // node coordinates along Gamma_c, strictly increasing
  std::vector<int> nodes;  // the body's mesh node behind each trace node (-1 for a bare 1D grid)

  int num_nodes() const { return static_cast<int>(x.size()); }
  int num_elements() const { return num_nodes() - 1; }
  double length() const { return x.back() - x.front(); }
  double max_element_length() const;
  // Index e of the element [x_e, x_{e+1}] holding the point (the last one for the end point).
  int element_containing(double point) const;
  // Value of a nodal P1 function at a point of Gamma_c.
  double evaluate(const std::vector<double>& values, double point) const;
  // The P1 mass matrix (int phi_i phi_j)_{ij} of the trace: h/3 and h/6 per element.
  Eigen::SparseMatrix<double> mass_matrix() const;
};

// Trace of a 2D mesh on one of its sides; x is the coordinate along Gamma_c (horizontal).
InterfaceTrace trace_on_side(const Mesh& mesh, Side side);

// A bare 1D grid of n elements on [0, L], with interior nodes moved by up to jitter * h / 2
// (jitter in [0, 0.4]).
InterfaceTrace uniform_trace(double L, int n, double jitter = 0, unsigned seed = 1);

}  // namespace mortar
