#include "common/fem/mesh.hpp"

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

double min_angle_degrees(const Mesh& mesh) {
  double smallest = M_PI;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d p = mesh.nodes[t[(k + 1) % 3]] - mesh.nodes[t[k]];
      const Eigen::Vector2d q = mesh.nodes[t[(k + 2) % 3]] - mesh.nodes[t[k]];
      // atan2 of |cross| and dot: accurate for small angles too, unlike acos
      smallest = std::min(smallest, std::atan2(std::fabs(p.x() * q.y() - p.y() * q.x()), p.dot(q)));
    }
  return smallest * 180 / M_PI;
}

double Mesh::max_edge_length() const {
  double h = 0;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) h = std::max(h, (nodes[t[k]] - nodes[t[(k + 1) % 3]]).norm());
  return h;
}

namespace {
void check_nodes(const std::vector<double>& t, double t0, double t1, const char* axis) {
  if (t.empty()) return;
  if (t.size() < 2 || t.front() != t0 || t.back() != t1)
    throw std::invalid_argument(std::string("rectangle_mesh: ") + axis + "_nodes must run from " +
                                std::to_string(t0) + " to " + std::to_string(t1) + " (" +
                                std::to_string(t.size()) + " nodes given)");
  for (std::size_t k = 1; k < t.size(); ++k)
    if (!(t[k] > t[k - 1]))
      throw std::invalid_argument(std::string("rectangle_mesh: ") + axis + "_nodes not increasing at " +
                                  std::to_string(k) + " (" + std::to_string(t[k - 1]) + ", " +
                                  std::to_string(t[k]) + ")");
}

void check_spec(const RectangleSpec& s) {
  if (!(s.x1 > s.x0) || !(s.y1 > s.y0))
    throw std::invalid_argument("rectangle_mesh: empty rectangle [" + std::to_string(s.x0) + ", " +
                                std::to_string(s.x1) + "] x [" + std::to_string(s.y0) + ", " +
                                std::to_string(s.y1) + "]");
  if ((s.x_nodes.empty() && s.nx < 1) || (s.y_nodes.empty() && s.ny < 1))
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
  check_nodes(s.x_nodes, s.x0, s.x1, "x");
  check_nodes(s.y_nodes, s.y0, s.y1, "y");
}

std::vector<double> columns(const RectangleSpec& s) {
  if (!s.x_nodes.empty()) return s.x_nodes;
  std::vector<double> xs(s.nx + 1);
  for (int i = 0; i <= s.nx; ++i) xs[i] = s.x0 + (s.x1 - s.x0) * i / s.nx;
  xs.back() = s.x1;
  return xs;
}

std::vector<double> rows(const RectangleSpec& s) {
  if (!s.y_nodes.empty()) return s.y_nodes;
  std::vector<double> ys(s.ny + 1);
  for (int j = 0; j <= s.ny; ++j) {
    const double t = static_cast<double>(j) / s.ny;
    const double g = s.grade_towards == Side::top ? 1.0 - std::pow(1.0 - t, s.grading)
                                                  : std::pow(t, s.grading);
    ys[j] = s.y0 + (s.y1 - s.y0) * g;
  }
  return ys;
}

// The shorter of the two cells next to node k: jitter is scaled by it so that graded
// columns or rows never cross.
double local_spacing(const std::vector<double>& t, int k) {
  const int n = static_cast<int>(t.size()) - 1;
  return std::min(k > 0 ? t[k] - t[k - 1] : t[1] - t[0], k < n ? t[k + 1] - t[k] : t[n] - t[n - 1]);
}
}  // namespace

Mesh rectangle_mesh(const RectangleSpec& s) {
  check_spec(s);
  return rectangle_band(s, 0, static_cast<int>(rows(s).size()) - 1);
}

Mesh rectangle_band(const RectangleSpec& s, int row0, int row1) {
  check_spec(s);
  const std::vector<double> xs = columns(s), ys = rows(s);
  const int nx = static_cast<int>(xs.size()) - 1, ny = static_cast<int>(ys.size()) - 1;
  if (row0 < 0 || row1 < row0 || row1 > ny)
    throw std::invalid_argument("rectangle_band: cell rows [" + std::to_string(row0) + ", " + std::to_string(row1) +
                                ") outside [0, " + std::to_string(ny) + ")");
  Mesh mesh;
  if (row0 == row1) return mesh;
  // band node (i, j - row0) is the whole mesh's node (i, j): ids shifted by row0 (nx + 1)
  auto id = [nx, row0](int i, int j) { return (j - row0) * (nx + 1) + i; };

  // The jitter of node (i, j) is the (j (nx + 1) + i)-th pair of draws of one sequence: the
  // earlier rows' draws are made and dropped, so a band has the whole mesh's coordinates.
  std::mt19937 rng(s.seed);
  std::uniform_real_distribution<double> shift(-0.5 * s.jitter, 0.5 * s.jitter);
  if (s.jitter > 0)
    for (long k = 0; k < 2L * row0 * (nx + 1); ++k) shift(rng);
  mesh.nodes.resize(static_cast<size_t>((nx + 1) * (row1 - row0 + 1)));
  for (int j = row0; j <= row1; ++j)
    for (int i = 0; i <= nx; ++i) {
      double x = xs[i], y = ys[j];
      const bool x_inside = i > 0 && i < nx, y_inside = j > 0 && j < ny;
      if (s.jitter > 0) {
        const double dx = shift(rng) * local_spacing(xs, i), dy = shift(rng) * local_spacing(ys, j);
        if (x_inside) x += dx;
        if (y_inside) y += dy;
      }
      mesh.nodes[id(i, j)] = Eigen::Vector2d(x, y);
    }

  mesh.triangles.reserve(static_cast<size_t>(2 * nx * (row1 - row0)));
  for (int j = row0; j < row1; ++j)
    for (int i = 0; i < nx; ++i) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }

  // the rectangle's sides: bottom and top only where the band reaches them
  for (int i = 0; i <= nx; ++i) {
    if (row0 == 0) mesh.side_nodes[static_cast<int>(Side::bottom)].push_back(id(i, 0));
    if (row1 == ny) mesh.side_nodes[static_cast<int>(Side::top)].push_back(id(i, ny));
  }
  for (int j = row0; j <= row1; ++j) {
    mesh.side_nodes[static_cast<int>(Side::left)].push_back(id(0, j));
    mesh.side_nodes[static_cast<int>(Side::right)].push_back(id(nx, j));
  }
  return mesh;
}

std::vector<double> graded_nodes(double x0, double x1, const std::function<double(double)>& cell_size) {
  if (!(x1 > x0))
    throw std::invalid_argument("graded_nodes: empty interval [" + std::to_string(x0) + ", " +
                                std::to_string(x1) + "]");
  // Tabulate F(x) = int_x0^x dt / cell_size(t) by the midpoint rule, 16 steps per cell.
  std::vector<double> x{x0}, F{0.0};
  while (x.back() < x1) {
    const double s = cell_size(x.back());
    if (!(s > 0) || !std::isfinite(s))
      throw std::invalid_argument("graded_nodes: cell size " + std::to_string(s) + " at x = " +
                                  std::to_string(x.back()));
    const double step = std::min(s / 16, x1 - x.back());
    const double mid = cell_size(x.back() + step / 2);
    if (!(mid > 0) || !std::isfinite(mid))
      throw std::invalid_argument("graded_nodes: cell size " + std::to_string(mid) + " at x = " +
                                  std::to_string(x.back() + step / 2));
    F.push_back(F.back() + step / mid);
    x.push_back(x.back() + step < x1 ? x.back() + step : x1);
  }
  // Node k sits where F = k F(x1) / N: equal shares, found by linear interpolation in the table.
  const int n = std::max(1, static_cast<int>(std::ceil(F.back() - 1e-9)));
  std::vector<double> nodes(n + 1);
  std::size_t m = 0;
  for (int k = 0; k <= n; ++k) {
    const double target = F.back() * k / n;
    while (m + 2 < F.size() && F[m + 1] < target) ++m;
    const double t = std::clamp((target - F[m]) / (F[m + 1] - F[m]), 0.0, 1.0);
    nodes[k] = x[m] + t * (x[m + 1] - x[m]);
  }
  nodes.front() = x0;
  nodes.back() = x1;
  return nodes;
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

GridPoint locate_in_grid(const RectangleSpec& spec, const Eigen::Vector2d& p) {
  const double X = (p.x() - spec.x0) / (spec.x1 - spec.x0) * spec.nx, Y = (p.y() - spec.y0) / (spec.y1 - spec.y0) * spec.ny;
  GridPoint g;
  g.i = std::clamp(static_cast<int>(std::floor(X)), 0, spec.nx - 1);
  g.j = std::clamp(static_cast<int>(std::floor(Y)), 0, spec.ny - 1);
  g.s = X - g.i;
  g.t = Y - g.j;
  return g;
}

Eigen::VectorXd interpolate_from_rectangle(const RectangleSpec& coarse, const Eigen::VectorXd& u, const Mesh& fine) {
  const auto at = [&](int i, int j) { return Eigen::Vector2d(u.segment<2>(2 * (j * (coarse.nx + 1) + i))); };
  Eigen::VectorXd v(fine.num_dofs());
  for (int a = 0; a < fine.num_nodes(); ++a) {
    const GridPoint p = locate_in_grid(coarse, fine.nodes[a]);
    v.segment<2>(2 * a) = p.interpolate(at(p.i, p.j), at(p.i + 1, p.j), at(p.i + 1, p.j + 1), at(p.i, p.j + 1));
  }
  return v;
}

}  // namespace mortar
