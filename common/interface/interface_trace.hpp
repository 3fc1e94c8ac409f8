// The trace of one body on the contact line Gamma_c: the 1D mesh T_c^l (paper section 3), its
// nodes xi^l in increasing x, and the Lagrange functions phi^l_j they carry: P1 hats, or for a
// P2 body (chapter 7) the quadratic functions of the element end points and midpoints.
//
// Numbering: the elements are [x_e, x_{e+1}], e = 0 .. N-1. A P1 trace has the N + 1 nodes x_e.
// A P2 trace has 2N + 1 nodes: node 2e is x_e and node 2e + 1 the midpoint of element e. So
// in both, local function l of element e (common/fem/lagrange_1d.hpp) belongs to node q e + l.
#pragma once

#include <Eigen/Sparse>
#include <vector>

#include "common/fem/mesh.hpp"

namespace mortar {

struct InterfaceTrace {
  std::vector<double> x;   // the element end points along Gamma_c, strictly increasing
  std::vector<int> nodes;  // the body's mesh node behind each trace node (-1 for a bare 1D grid)
  int degree = 1;          // q: 1 (P1 traces) or 2 (P2)

  // The element end points (for P1 these are all the nodes).
  int num_nodes() const { return static_cast<int>(x.size()); }
  int num_elements() const { return num_nodes() - 1; }
  // The trace nodes, q N + 1: the columns of D and M, the rows of pointwise matching.
  int num_dofs() const { return degree * num_elements() + 1; }
  double node_x(int j) const { return j % degree == 0 ? x[j / degree] : 0.5 * (x[j / degree] + x[j / degree + 1]); }
  std::vector<double> node_positions() const;  // node_x of every node
  double length() const { return x.back() - x.front(); }
  double max_element_length() const;
  // Index e of the element [x_e, x_{e+1}] holding the point (the last one for the end point).
  int element_containing(double point) const;
  // Value at a point of Gamma_c of the function with the given values at the trace nodes.
  double evaluate(const std::vector<double>& values, double point) const;
  // The mass matrix (int phi_i phi_j)_{ij} of the trace: h/3 and h/6 per element for P1,
  // h/30 (4 2 -1; 2 16 2; -1 2 4) for P2.
  Eigen::SparseMatrix<double> mass_matrix() const;
  // int_{Gamma_c} phi_j for every node: half the two element lengths at a P1 node; h/6 at an
  // end point and 2h/3 at the midpoint of each P2 element (Simpson).
  std::vector<double> node_integrals() const;
};

// Trace of a 2D mesh on one of its sides, of the mesh's degree; x is the coordinate along
// Gamma_c (horizontal).
InterfaceTrace trace_on_side(const Mesh& mesh, Side side);

// The triangle of each element of a trace on its mesh: the one triangle with both end points of
// the element among its vertices (-1 where there is none: the trace is not that mesh's).
std::vector<int> trace_triangles(const Mesh& mesh, const InterfaceTrace& trace);

// A bare 1D grid of n elements on [0, L], with interior end points moved by up to
// jitter * h / 2 (jitter in [0, 0.4]), of degree 1 or 2.
InterfaceTrace uniform_trace(double L, int n, double jitter = 0, unsigned seed = 1, int degree = 1);

}  // namespace mortar
