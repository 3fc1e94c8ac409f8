#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "common/study/two_body_pictures.hpp"
#include "common/study/vtu.hpp"

using namespace mortar;

namespace {
TwoBodies small_bodies() {
  TwoBodyGeometry g;
  g.n1 = 5;
  g.m1 = 2;
  g.n2 = 7;
  g.m2 = 3;
  g.jitter = 0.2;
  return make_two_bodies(g, Material(1, 0.3), Material(2, 0.25));
}

std::string read(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

int count(const std::string& text, const std::string& word) {
  int n = 0;
  for (auto p = text.find(word); p != std::string::npos; p = text.find(word, p + 1)) ++n;
  return n;
}
}  // namespace

TEST(TwoBodyPictures, the_meshes_figure_marks_every_node_of_both_traces_and_of_the_merged_grid) {
  const TwoBodies b = small_bodies();
  const ContactInterface g = make_interface(b, 0);
  const Figure f = two_body_meshes(b, g, true, "t");
  ASSERT_EQ(f.series.size(), 5u);  // two meshes, xi^1, xi^2, merged grid
  EXPECT_EQ(f.series[2].x, g.nonmortar_trace.x);
  EXPECT_EQ(f.series[3].x, g.mortar_trace.x);
  EXPECT_EQ(f.series[4].x, g.grid.breakpoints);
  EXPECT_GT(f.series[2].y[0], f.series[3].y[0]);  // body 1, the non-mortar side here, lifted
  EXPECT_EQ(two_body_meshes(b, make_interface(b, 1), false, "t").series.size(), 4u);
}

TEST(TwoBodyPictures, the_deformed_figure_states_a_magnification_that_makes_u_visible) {
  const TwoBodies b = small_bodies();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(b.num_dofs());
  u[1] = 1e-4;  // one node moves by 1e-4 m: magnified to 5% of L = 1, a factor 500
  const Figure f = deformed_two_bodies(b, u, "t");
  EXPECT_NE(f.title.find("x 500"), std::string::npos) << f.title;
  ASSERT_EQ(f.series.size(), 4u);  // two reference meshes, two deformed ones
}

TEST(TwoBodyPictures, vtu_files_hold_every_point_and_cell) {
  const TwoBodies b = small_bodies();
  const Eigen::VectorXd u = Eigen::VectorXd::Constant(b.num_dofs(), 1e-3);
  InterfaceCurve p;
  p.x = {0, 0.25, 0.5, 1};
  p.value = {1, 2, 3, 4};
  const std::string dir = ::testing::TempDir();
  write_two_body_vtu(dir, b, u, p);
  for (int l = 0; l < 2; ++l) {
    const Mesh& m = b.body(l).mesh;
    const std::string text = read(dir + "/body" + std::to_string(l + 1) + ".vtu");
    EXPECT_NE(text.find("NumberOfPoints=\"" + std::to_string(m.num_nodes()) + "\""), std::string::npos);
    EXPECT_NE(text.find("NumberOfCells=\"" + std::to_string(m.triangles.size()) + "\""), std::string::npos);
    EXPECT_EQ(count(text, "<DataArray"), count(text, "</DataArray>"));
  }
  const std::string contact = read(dir + "/contact.vtu");
  EXPECT_NE(contact.find("NumberOfPoints=\"4\" NumberOfCells=\"3\""), std::string::npos);
  EXPECT_NE(contact.find("Name=\"pressure\""), std::string::npos);
  EXPECT_THROW(write_curve_vtu(dir + "/bad.vtu", {0, 1}, {{"pressure", {1, 2, 3}}}), std::invalid_argument);
}
