// Structured triangle meshes of rectangles, with boundary tags, optional jitter and grading.
//
// An nx x ny grid of cells, each split along its (i,j)-(i+1,j+1) diagonal into two
// counter-clockwise triangles. Nodes on each side are kept in order along that side, so the
// trace of a body on the contact line Gamma_c is read off directly (interface_trace).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <functional>
#include <vector>

namespace mortar {

enum class Side { bottom = 0, right = 1, top = 2, left = 3 };
const char* side_name(Side side);

struct RectangleSpec {
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  int nx = 1, ny = 1;
  // Interior nodes move by up to jitter * h / 2 in each direction (jitter in [0, 0.4]); nodes
  // on a side (not the corners) move along that side only, so traces on Gamma_c become
  // nonuniform too.
  double jitter = 0;
  // Node rows at y0 + (y1 - y0) * t^grading (t uniform in [0,1]): grading > 1 clusters the
  // rows towards y0 (grade_towards = Side::bottom) or, mirrored, towards y1 (Side::top).
  double grading = 1;
  Side grade_towards = Side::bottom;
  // Explicit node columns and rows, increasing from x0 to x1 (y0 to y1), for instance from
  // graded_nodes. When given, they replace nx (ny and grading): the grid is a tensor product.
  std::vector<double> x_nodes, y_nodes;
  unsigned seed = 1;  // jitter is pseudo-random but reproducible
};

// A P1 mesh, or a P2 one (p2_mesh, common/fem/p2_elasticity.hpp): then every edge also has a
// node at its midpoint, `nodes` holds the vertices first and the midpoints after them,
// `edge_nodes[t]` the midpoints of triangle t's edges 0-1, 1-2, 2-0, and each side lists its
// vertices and midpoints in order along it. `triangles` are the vertex triangles either way,
// so the geometry (areas, h, pictures) reads the same.
struct Mesh {
  std::vector<Eigen::Vector2d> nodes;
  std::vector<std::array<int, 3>> triangles;
  std::array<std::vector<int>, 4> side_nodes;  // indexed by Side, ordered by increasing x or y
  std::vector<std::array<int, 3>> edge_nodes;  // P2 only: empty for a P1 mesh

  int degree() const { return edge_nodes.empty() ? 1 : 2; }

  const std::vector<int>& nodes_on(Side side) const { return side_nodes[static_cast<int>(side)]; }
  int num_nodes() const { return static_cast<int>(nodes.size()); }
  int num_dofs() const { return 2 * num_nodes(); }
  double area(int triangle) const;
  double max_edge_length() const;  // the "h" reported in convergence tables
};

Mesh rectangle_mesh(const RectangleSpec& spec);

// Where a point lies in the cell grid of rectangle_mesh(spec) without jitter or grading: cell
// (i, j) (clamped to the grid) and the point's coordinates (s, t) in it, each in [0, 1] inside.
struct GridPoint {
  int i = 0, j = 0;
  double s = 0, t = 0;
  // The P1 interpolant of values at the cell's corners (i, j), (i+1, j), (i+1, j+1), (i, j+1):
  // in the triangle below the (i,j)-(i+1,j+1) diagonal (t <= s) or the one above it.
  template <class V>
  V interpolate(const V& v00, const V& v10, const V& v11, const V& v01) const {
    return t <= s ? V(v00 + s * (v10 - v00) + t * (v11 - v10)) : V(v00 + s * (v11 - v01) + t * (v01 - v00));
  }
};
GridPoint locate_in_grid(const RectangleSpec& spec, const Eigen::Vector2d& p);
// A nodal field (2 values per node) of rectangle_mesh(coarse), without jitter, at the nodes of
// another mesh of the same rectangle: the P1 interpolant, read in the cell and the triangle
// (below or above the diagonal) each node falls in. Uniform levels are nested, so this is the
// exact prolongation there (chapter 10's uniform levels, chapter 11's nested start).
Eigen::VectorXd interpolate_from_rectangle(const RectangleSpec& coarse, const Eigen::VectorXd& u, const Mesh& fine);

// The smallest interior angle of the mesh's triangles, in degrees (the shape regularity that
// error estimates and local refinement depend on).
double min_angle_degrees(const Mesh& mesh);

// The cell rows [row0, row1) of rectangle_mesh(spec) (node rows row0 to row1), with the whole
// mesh's coordinates, jitter included: band node k is the whole mesh's node k + row0 (nx + 1).
// Its bottom and top sides are listed only where the band reaches the rectangle's, its left and
// right sides are the band's part of them. Empty when row0 = row1. One rank's part of a mesh
// (chapter 9) is built this way without the rest.
Mesh rectangle_band(const RectangleSpec& spec, int row0, int row1);

// Nodes x0 = t_0 < ... < t_N = x1 whose cells follow a target size: every cell holds the same
// share of int dx / cell_size(x), rounded up to a whole number of cells, so a cell is about
// as long as cell_size where it lies and never much longer. A size that grows linearly with
// the distance to a point gives cells growing geometrically away from it.
std::vector<double> graded_nodes(double x0, double x1, const std::function<double(double)>& cell_size);

// Displaces a mesh by a nodal field u (2 dofs per node: 2 a + component) times a scale.
Mesh displaced(const Mesh& mesh, const Eigen::VectorXd& u, double scale);

}  // namespace mortar
