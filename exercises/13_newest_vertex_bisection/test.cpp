#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/fem/bisection.hpp"
#include "exercise.hpp"

namespace {
using Point = Eigen::Vector2d;
using Triangle = std::array<int, 3>;
// A triangle by its three vertices, in the order (v0, v1, v2): the order says which edge is the
// refinement edge, so it is part of the answer.
using Corners = std::array<Point, 3>;

struct TriangleMesh {
  std::vector<Point> nodes;
  std::vector<Triangle> triangles;
};

double signed_area(const Point& a, const Point& b, const Point& c) {
  const Point p = b - a, q = c - a;
  return 0.5 * (p.x() * q.y() - p.y() * q.x());
}

Corners corners(const TriangleMesh& m, int t) {
  return {m.nodes[m.triangles[t][0]], m.nodes[m.triangles[t][1]], m.nodes[m.triangles[t][2]]};
}

bool same(const Corners& a, const Corners& b) {
  for (int k = 0; k < 3; ++k)
    if ((a[k] - b[k]).norm() > 1e-12) return false;
  return true;
}

std::string print(const Corners& c) {
  std::ostringstream out;
  out << "(";
  for (int k = 0; k < 3; ++k) out << (k ? ", " : "") << "(" << c[k].x() << ", " << c[k].y() << ")";
  return out.str() + ")";
}

// The triangle with these corners in this order, or -1.
int find(const TriangleMesh& m, const Corners& c) {
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t)
    if (same(corners(m, t), c)) return t;
  return -1;
}

// The mesh's triangles are exactly these, each with its vertices in the order given, in any
// order in the list and whatever the numbers of the new nodes.
void expect_triangles(const TriangleMesh& m, const std::vector<Corners>& expected) {
  std::vector<char> matched(m.triangles.size(), 0);
  for (const Corners& c : expected) {
    bool found = false;
    for (int t = 0; t < static_cast<int>(m.triangles.size()) && !found; ++t)
      if (!matched[t] && same(corners(m, t), c)) matched[t] = found = true;
    EXPECT_TRUE(found) << "expected the triangle " << print(c) << ", not in the mesh";
  }
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t)
    EXPECT_TRUE(matched[t]) << "triangle " << t << " " << print(corners(m, t)) << " is not expected";
  EXPECT_EQ(m.triangles.size(), expected.size());
}

double area_of(const TriangleMesh& m, int t) {
  const Corners c = corners(m, t);
  return signed_area(c[0], c[1], c[2]);
}

double total_area(const TriangleMesh& m) {
  double area = 0;
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) area += area_of(m, t);
  return area;
}

// The length of the edges that belong to one triangle only: the domain's perimeter when every
// interior edge belongs to exactly two.
double boundary_length(const TriangleMesh& m) {
  std::map<std::pair<int, int>, int> count;
  for (const Triangle& tri : m.triangles)
    for (int k = 0; k < 3; ++k) ++count[{std::min(tri[k], tri[(k + 1) % 3]), std::max(tri[k], tri[(k + 1) % 3])}];
  double length = 0;
  for (const auto& [edge, n] : count)
    if (n == 1) length += (m.nodes[edge.first] - m.nodes[edge.second]).norm();
  return length;
}

// The conditions a refined mesh of a domain of this area and perimeter meets: every triangle
// counter-clockwise; the areas sum to the domain's; every edge in one or two triangles, and the
// edges in one triangle only make up the perimeter (so every interior edge is in exactly two);
// no node inside an edge (no hanging node); every node a vertex of some triangle.
void expect_conforming(const TriangleMesh& m, double area, double perimeter, const std::string& where) {
  std::map<std::pair<int, int>, int> count;
  std::vector<char> used(m.nodes.size(), 0);
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) {
    ASSERT_GT(area_of(m, t), 0) << where << ": triangle " << t << " " << print(corners(m, t))
                                << " is not counter-clockwise";
    for (int k = 0; k < 3; ++k) {
      const int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      ++count[{std::min(a, b), std::max(a, b)}];
      used[a] = 1;
    }
  }
  EXPECT_NEAR(total_area(m), area, 1e-12 * area) << where << ": the areas do not add up to the domain's";
  for (const auto& [edge, n] : count)
    ASSERT_LE(n, 2) << where << ": edge " << edge.first << "-" << edge.second << " is in " << n << " triangles";
  EXPECT_NEAR(boundary_length(m), perimeter, 1e-12 * perimeter)
      << where << ": the edges in one triangle only are not the boundary: an interior edge is in one triangle";
  for (int a = 0; a < static_cast<int>(m.nodes.size()); ++a)
    EXPECT_TRUE(used[a]) << where << ": node " << a << " is in no triangle";
  for (const auto& [edge, n] : count) {
    const Point p = m.nodes[edge.first], q = m.nodes[edge.second], d = q - p;
    for (int a = 0; a < static_cast<int>(m.nodes.size()); ++a) {
      if (a == edge.first || a == edge.second) continue;
      const Point r = m.nodes[a] - p;
      const double along = r.dot(d) / d.squaredNorm();
      const double off = std::fabs(d.x() * r.y() - d.y() * r.x()) / d.squaredNorm();
      ASSERT_FALSE(along > 1e-12 && along < 1 - 1e-12 && off < 1e-12)
          << where << ": node " << a << " (" << m.nodes[a].transpose() << ") hangs inside edge " << edge.first << "-"
          << edge.second;
    }
  }
}

// Calls the exercise and checks what it must keep: the old nodes where they were, the
// triangles it did not bisect at their indices, and in every triangle it made, the newest vertex
// (the third) one of the nodes it made.
void refine(TriangleMesh& m, int t) {
  const TriangleMesh before = m;
  exercise::bisect_with_closure(m.nodes, m.triangles, t);
  ASSERT_GE(m.nodes.size(), before.nodes.size() + 1) << "bisecting triangle " << t << " made no node";
  for (std::size_t a = 0; a < before.nodes.size(); ++a)
    ASSERT_EQ(m.nodes[a], before.nodes[a]) << "node " << a << " moved or was renumbered";
  ASSERT_GE(m.triangles.size(), before.triangles.size() + 1) << "bisecting triangle " << t << " made no triangle";
  std::set<Triangle> old(before.triangles.begin(), before.triangles.end());
  std::set<Triangle> now(m.triangles.begin(), m.triangles.end());
  for (std::size_t s = 0; s < before.triangles.size(); ++s) {
    if (now.count(before.triangles[s])) {
      ASSERT_EQ(m.triangles[s], before.triangles[s]) << "triangle " << s << " was not bisected but moved";
    }
  }
  for (const Triangle& tri : m.triangles) {
    if (!old.count(tri)) {
      ASSERT_GE(tri[2], static_cast<int>(before.nodes.size()))
          << "a new triangle (" << tri[0] << ", " << tri[1] << ", " << tri[2] << ") whose newest vertex is an old node";
    }
  }
}

// The triangle whose centroid is nearest to p.
int nearest(const TriangleMesh& m, const Point& p) {
  int best = 0;
  double distance = 1e300;
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) {
    const Corners c = corners(m, t);
    const double d = ((c[0] + c[1] + c[2]) / 3 - p).norm();
    if (d < distance) distance = d, best = t;
  }
  return best;
}

// Newest-vertex bisection makes, from one triangle, triangles of at most four shapes (Sewell
// 1972, Mitchell 1989): the descendants of each triangle of the first mesh (the one containing
// their centroid) fall into at most four similarity classes. A wrong rule makes more.
void expect_four_shapes_at_most(const TriangleMesh& first, const TriangleMesh& m) {
  std::vector<std::set<std::array<long long, 2>>> shapes(first.triangles.size());
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) {
    const Corners c = corners(m, t);
    const Point g = (c[0] + c[1] + c[2]) / 3;
    std::array<double, 3> side{(c[1] - c[0]).norm(), (c[2] - c[1]).norm(), (c[0] - c[2]).norm()};
    std::sort(side.begin(), side.end());
    const std::array<long long, 2> shape{std::llround(1e8 * side[0] / side[2]), std::llround(1e8 * side[1] / side[2])};
    for (int s = 0; s < static_cast<int>(first.triangles.size()); ++s) {
      const Corners f = corners(first, s);
      if (signed_area(f[0], f[1], g) > 0 && signed_area(f[1], f[2], g) > 0 && signed_area(f[2], f[0], g) > 0)
        shapes[s].insert(shape);
    }
  }
  for (std::size_t s = 0; s < shapes.size(); ++s)
    EXPECT_LE(shapes[s].size(), 4u) << "the triangles inside first triangle " << s << " have " << shapes[s].size()
                                    << " shapes; newest-vertex bisection makes at most four";
}

// A hexagon around the origin, six triangles (p_k, p_{k+1}, c) with newest vertex the centre c:
// every refinement edge on the boundary. Integer corners, so every midpoint is exact.
TriangleMesh hexagon() {
  TriangleMesh m;
  m.nodes = {{0, 0}, {2, 0}, {1, 2}, {-1, 2}, {-2, 0}, {-1, -2}, {1, -2}};
  for (int k = 0; k < 6; ++k) m.triangles.push_back({1 + k, 1 + (k + 1) % 6, 0});
  return m;
}
const double hexagon_area = 12, hexagon_perimeter = 4 + 4 * std::sqrt(5.0);  // two sides of 2, four of sqrt(5)

// The L-shaped domain [0, 2]^2 without (1, 2) x (1, 2): three unit squares, each cut along the
// diagonal through the re-entrant corner (1, 1), which is every triangle's newest vertex.
TriangleMesh l_shape() {
  TriangleMesh m;
  m.nodes = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}, {0, 2}, {1, 2}};
  m.triangles = {{0, 1, 4}, {3, 0, 4}, {1, 2, 4}, {2, 5, 4}, {6, 3, 4}, {7, 6, 4}};
  return m;
}
}  // namespace

TEST(NewestVertexBisection, one_triangle_alone) {
  TriangleMesh m{{{0, 0}, {2, 0}, {1, 1}}, {{0, 1, 2}}};
  refine(m, 0);
  expect_triangles(m, {{Point(1, 1), Point(0, 0), Point(1, 0)}, {Point(2, 0), Point(1, 1), Point(1, 0)}});
  EXPECT_EQ(m.nodes.size(), 4u);
  // its first child again: the refinement edge (1, 1)-(0, 0) is on the boundary
  refine(m, find(m, {Point(1, 1), Point(0, 0), Point(1, 0)}));
  expect_triangles(m, {{Point(1, 0), Point(1, 1), Point(0.5, 0.5)},
                       {Point(0, 0), Point(1, 0), Point(0.5, 0.5)},
                       {Point(2, 0), Point(1, 1), Point(1, 0)}});
  EXPECT_EQ(m.nodes.size(), 5u);
}

TEST(NewestVertexBisection, two_triangles_sharing_their_refinement_edge) {
  // the unit square cut along (0, 0)-(1, 1), which is both triangles' refinement edge
  const TriangleMesh square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{2, 0, 1}, {0, 2, 3}}};
  const std::vector<Corners> expected = {{Point(1, 0), Point(1, 1), Point(0.5, 0.5)},
                                         {Point(0, 0), Point(1, 0), Point(0.5, 0.5)},
                                         {Point(0, 1), Point(0, 0), Point(0.5, 0.5)},
                                         {Point(1, 1), Point(0, 1), Point(0.5, 0.5)}};
  for (int t : {0, 1}) {  // either triangle: both are bisected at one new node
    TriangleMesh m = square;
    refine(m, t);
    SCOPED_TRACE("bisecting triangle " + std::to_string(t));
    expect_triangles(m, expected);
    EXPECT_EQ(m.nodes.size(), 5u);
    expect_conforming(m, 1, 4, "the square");
  }
}

// Three triangles: A = (2,2) (2,0) (4,0) has its refinement edge on B = (2,2) (0,0) (2,0), whose
// refinement edge, the diagonal, is on C = (0,2) (0,0) (2,2), whose refinement edge (0,2)-(0,0)
// is on the boundary. Bisecting A bisects C, then B with C's child across the diagonal, then A
// with B's child across their common edge: three new nodes, (0,1), (1,1), (2,1).
TEST(NewestVertexBisection, a_closure_three_triangles_deep) {
  const TriangleMesh first{{{0, 0}, {2, 0}, {2, 2}, {0, 2}, {4, 0}}, {{2, 1, 4}, {2, 0, 1}, {3, 0, 2}}};
  TriangleMesh m = first;
  refine(m, 0);
  expect_triangles(m, {{Point(2, 2), Point(0, 2), Point(0, 1)},
                       {Point(0, 1), Point(0, 0), Point(1, 1)},
                       {Point(2, 2), Point(0, 1), Point(1, 1)},
                       {Point(0, 0), Point(2, 0), Point(1, 1)},
                       {Point(1, 1), Point(2, 0), Point(2, 1)},
                       {Point(2, 2), Point(1, 1), Point(2, 1)},
                       {Point(4, 0), Point(2, 2), Point(2, 1)},
                       {Point(2, 0), Point(4, 0), Point(2, 1)}});
  EXPECT_EQ(m.nodes.size(), 8u);
  expect_conforming(m, 6, 8 + std::sqrt(8.0), "three deep");

  // B instead: two deep, and A is left as it was (at its index, refine checks)
  m = first;
  refine(m, 1);
  expect_triangles(m, {{Point(2, 2), Point(2, 0), Point(4, 0)},
                       {Point(2, 2), Point(0, 2), Point(0, 1)},
                       {Point(0, 1), Point(0, 0), Point(1, 1)},
                       {Point(2, 2), Point(0, 1), Point(1, 1)},
                       {Point(2, 0), Point(2, 2), Point(1, 1)},
                       {Point(0, 0), Point(2, 0), Point(1, 1)}});
  EXPECT_EQ(m.nodes.size(), 7u);
  expect_conforming(m, 6, 8 + std::sqrt(8.0), "two deep");
}

// The library's BisectionMesh starts from rectangle meshes only: this hexagon is not one.
// Bisecting (p_0, p_1, c) puts m = (1.5, 1) on the boundary; its child (c, p_0, m) then has its
// refinement edge c-p_0 on (p_5, p_0, c), whose refinement edge is on the boundary: that one is
// bisected first, at m' = (1.5, -1), then both at m'' = (1, 0).
TEST(NewestVertexBisection, a_hexagon_worked_by_hand) {
  TriangleMesh m = hexagon();
  refine(m, 0);
  const Point c(0, 0), p0(2, 0), p1(1, 2), p2(-1, 2), p3(-2, 0), p4(-1, -2), p5(1, -2), mid(1.5, 1);
  refine(m, find(m, {c, p0, mid}));
  const Point mid2(1.5, -1), mid3(1, 0);
  expect_triangles(m, {{p1, p2, c}, {p2, p3, c}, {p3, p4, c}, {p4, p5, c}, {p1, c, mid}, {c, p5, mid2}, {mid, c, mid3},
                       {p0, mid, mid3}, {mid2, p0, mid3}, {c, mid2, mid3}});
  EXPECT_EQ(m.nodes.size(), 10u);
  expect_conforming(m, hexagon_area, hexagon_perimeter, "the hexagon");
}

TEST(NewestVertexBisection, the_hexagon_refined_anywhere_stays_conforming) {
  const TriangleMesh first = hexagon();
  TriangleMesh m = first;
  // a fixed sequence of points spread over the hexagon (a Weyl sequence), each time bisecting
  // the triangle whose centroid is nearest
  for (int step = 0; step < 120; ++step) {
    const double u = std::fmod(0.618034 * step, 1.0), v = std::fmod(0.414214 * step + 0.3, 1.0);
    const Point p(-1.6 + 3.2 * u, -1.6 + 3.2 * v);
    refine(m, nearest(m, p));
    if (HasFatalFailure()) return;
    expect_conforming(m, hexagon_area, hexagon_perimeter, "step " + std::to_string(step));
    if (HasFatalFailure()) return;
  }
  expect_four_shapes_at_most(first, m);
}

// Refined again and again at the re-entrant corner, as an adaptive loop does at a singularity:
// the closure runs from square to square.
TEST(NewestVertexBisection, the_l_shape_refined_at_its_corner) {
  const TriangleMesh first = l_shape();
  TriangleMesh m = first;
  int steps = 0;
  for (bool again = true; again;) {
    again = false;
    for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) {
      const Triangle& tri = m.triangles[t];
      const bool at_corner = std::find(tri.begin(), tri.end(), 4) != tri.end();
      if (at_corner && area_of(m, t) > 1.0 / 2048) {
        refine(m, t);
        if (HasFatalFailure()) return;
        expect_conforming(m, 3, 8, "step " + std::to_string(steps++));
        if (HasFatalFailure()) return;
        again = true;
        break;
      }
    }
  }
  EXPECT_GT(steps, 20);
  double smallest = 1;
  for (int t = 0; t < static_cast<int>(m.triangles.size()); ++t) smallest = std::min(smallest, area_of(m, t));
  EXPECT_LE(smallest, 1.0 / 2048) << "the corner was not refined";
  expect_four_shapes_at_most(first, m);
}

// On a rectangle mesh, where the library can start, one triangle marked and refined by
// mortar::BisectionMesh gives the same triangles, with the same refinement edges.
TEST(NewestVertexBisection, is_the_librarys_refinement_on_a_rectangle) {
  mortar::RectangleSpec spec;
  spec.x1 = 2;
  spec.nx = 4;
  spec.ny = 2;
  mortar::BisectionMesh library(spec);
  TriangleMesh m{library.mesh().nodes, library.mesh().triangles};
  for (int step = 0; step < 40; ++step) {
    const int marked = (7 * step + 3) % static_cast<int>(library.mesh().triangles.size());
    const auto& tri = library.mesh().triangles[marked];
    const auto& at = library.mesh().nodes;
    const Point centroid = (at[tri[0]] + at[tri[1]] + at[tri[2]]) / 3;
    std::vector<bool> marks(library.mesh().triangles.size(), false);
    marks[marked] = true;
    library.refine(marks);
    refine(m, nearest(m, centroid));
    if (HasFatalFailure()) return;
    SCOPED_TRACE("step " + std::to_string(step));
    std::vector<Corners> expected;
    for (const auto& t : library.mesh().triangles)
      expected.push_back({library.mesh().nodes[t[0]], library.mesh().nodes[t[1]], library.mesh().nodes[t[2]]});
    expect_triangles(m, expected);
    if (HasFailure()) return;
  }
}

// The hexagon with every refinement edge a spoke, each on the next triangle round the centre:
// bisecting any triangle waits for its neighbour, which waits for the next, and so round.
TEST(NewestVertexBisection, refuses_refinement_edges_that_go_round_in_a_circle) {
  TriangleMesh m = hexagon();
  for (int k = 0; k < 6; ++k) m.triangles[k] = {0, 1 + k, 1 + (k + 1) % 6};  // (c, p_k, p_{k+1})
  const TriangleMesh before = m;
  EXPECT_THROW(exercise::bisect_with_closure(m.nodes, m.triangles, 2), std::invalid_argument);
  EXPECT_EQ(m.nodes, before.nodes) << "the mesh changed before the refusal";
  EXPECT_EQ(m.triangles, before.triangles) << "the mesh changed before the refusal";
}

TEST(NewestVertexBisection, refuses_a_triangle_that_is_not_there) {
  TriangleMesh m = hexagon();
  EXPECT_THROW(exercise::bisect_with_closure(m.nodes, m.triangles, 6), std::invalid_argument);
  EXPECT_THROW(exercise::bisect_with_closure(m.nodes, m.triangles, -1), std::invalid_argument);
  EXPECT_EQ(m.nodes.size(), 7u);
  EXPECT_EQ(m.triangles.size(), 6u);
}
