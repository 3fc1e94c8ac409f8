#include "common/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace mortar {

const char* side_name(Side side) {
  switch (side) {
    case Side::bottom: return "bottom";
    case Side::right: return "right";
    case Side::top: return "top";
    case Side::left: return "left";
  }
  return "?";
}

double Mesh::area(int t) const {
  const auto& [a, b, c] = triangles[t];
  const Eigen::Vector2d e1 = nodes[b] - nodes[a], e2 = nodes[c] - nodes[a];
  return 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
}

double Mesh::max_edge_length() const {
  double h = 0;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) h = std::max(h, (nodes[t[k]] - nodes[t[(k + 1) % 3]]).norm());
  return h;
}

namespace {
void check_spec(const RectangleSpec& s) {
  if (!(s.x1 > s.x0) || !(s.y1 > s.y0))
    throw std::invalid_argument("rectangle_mesh: empty rectangle [" + std::to_string(s.x0) + ", " +
                                std::to_string(s.x1) + "] x [" + std::to_string(s.y0) + ", " +
                                std::to_string(s.y1) + "]");
  if (s.nx < 1 || s.ny < 1)
    throw std::invalid_argument("rectangle_mesh: need nx, ny >= 1, got " + std::to_string(s.nx) +
                                " x " + std::to_string(s.ny));
  // Each vertex moves by up to jitter * h / 2 per direction; a triangle keeps at least
  // (1 - 2 jitter) of its area, so 0.4 keeps 20% and the family stays shape-regular.
  if (!(s.jitter >= 0 && s.jitter <= 0.4))
    throw std::invalid_argument("rectangle_mesh: jitter must be in [0, 0.4], got " +
                                std::to_string(s.jitter));
  if (!(s.grading >= 1 && s.grading <= 10))
    throw std::invalid_argument("rectangle_mesh: grading must be in [1, 10], got " +
                                std::to_string(s.grading));
}

double row_coordinate(const RectangleSpec& s, int j) {
  const double t = static_cast<double>(j) / s.ny;
  const double g = s.grade_towards == Side::top ? 1.0 - std::pow(1.0 - t, s.grading)
                                                : std::pow(t, s.grading);
  return s.y0 + (s.y1 - s.y0) * g;
}
}  // namespace

Mesh rectangle_mesh(const RectangleSpec& s) {
  check_spec(s);
  Mesh mesh;
  const int nx = s.nx, ny = s.ny;
  auto id = [nx](int i, int j) { return j * (nx + 1) + i; };
  std::vector<double> ys(ny + 1);
  for (int j = 0; j <= ny; ++j) ys[j] = row_coordinate(s, j);
  const double hx = (s.x1 - s.x0) / nx;

  std::mt19937 rng(s.seed);
  std::uniform_real_distribution<double> shift(-0.5 * s.jitter, 0.5 * s.jitter);
  mesh.nodes.resize(static_cast<size_t>((nx + 1) * (ny + 1)));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      double x = s.x0 + i * hx, y = ys[j];
      const bool x_inside = i > 0 && i < nx, y_inside = j > 0 && j < ny;
      // Local row spacing keeps graded rows from crossing when jittered.
      const double hy = std::min(j > 0 ? ys[j] - ys[j - 1] : ys[1] - ys[0],
                                 j < ny ? ys[j + 1] - ys[j] : ys[ny] - ys[ny - 1]);
      if (s.jitter > 0) {
        const double dx = shift(rng) * hx, dy = shift(rng) * hy;
        if (x_inside) x += dx;
        if (y_inside) y += dy;
      }
      mesh.nodes[id(i, j)] = Eigen::Vector2d(x, y);
    }

  mesh.triangles.reserve(static_cast<size_t>(2 * nx * ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }

  for (int i = 0; i <= nx; ++i) {
    mesh.side_nodes[static_cast<int>(Side::bottom)].push_back(id(i, 0));
    mesh.side_nodes[static_cast<int>(Side::top)].push_back(id(i, ny));
  }
  for (int j = 0; j <= ny; ++j) {
    mesh.side_nodes[static_cast<int>(Side::left)].push_back(id(0, j));
    mesh.side_nodes[static_cast<int>(Side::right)].push_back(id(nx, j));
  }
  return mesh;
}

Mesh displaced(const Mesh& mesh, const Eigen::VectorXd& u, double scale) {
  if (u.size() != mesh.num_dofs())
    throw std::invalid_argument("displaced: field has " + std::to_string(u.size()) +
                                " entries, mesh has " + std::to_string(mesh.num_dofs()) + " dofs");
  Mesh out = mesh;
  for (int a = 0; a < mesh.num_nodes(); ++a)
    out.nodes[a] += scale * Eigen::Vector2d(u[2 * a], u[2 * a + 1]);
  return out;
}

}  // namespace mortar
