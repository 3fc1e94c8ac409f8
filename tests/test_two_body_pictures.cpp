// The pictures of the two-body problem and the .vtu writer: what the figures mark, and that
// the files are well-formed XML holding every point, cell and value.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/study/two_body_pictures.hpp"
#include "common/study/vtu.hpp"

using namespace mortar;

namespace {
// L = 1, H1 = H2 = 0.5; 5 x 2 cells above Gamma_c, 7 x 3 below, nodes jittered by 0.2 h
TwoBodies small_bodies() {
  return make_two_bodies(TwoBodyGeometry{1, 0.5, 0.5, 5, 2, 7, 3, 0.2}, Material(1, 0.3), Material(2, 0.25));
}

std::string read(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// Well-formed for the XML a .vtu uses: every element closed in order, one root, nothing but
// white space outside it, attributes quoted.
bool well_formed(const std::string& text) {
  std::vector<std::string> open;
  std::size_t p = 0;
  int roots = 0;
  while ((p = text.find('<', p)) != std::string::npos) {
    const std::size_t end = text.find('>', p);
    if (end == std::string::npos) return false;
    const std::string tag = text.substr(p + 1, end - p - 1);
    p = end + 1;
    if (tag.empty() || tag[0] == '?') continue;
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0) return false;
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return false;
      open.pop_back();
      continue;
    }
    if (open.empty() && ++roots > 1) return false;
    if (tag.back() != '/') open.push_back(tag.substr(0, tag.find(' ')));
  }
  return open.empty() && roots == 1;
}

std::vector<unsigned char> from_base64(const std::string& s) {
  const std::string table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> out;
  std::uint32_t buffer = 0;
  int bits = 0;
  for (char c : s) {
    const auto k = table.find(c);
    if (k == std::string::npos) continue;  // '=', new lines
    buffer = (buffer << 6) | static_cast<std::uint32_t>(k);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>((buffer >> bits) & 0xff));
    }
  }
  return out;
}

// The values of the binary Float64 array `name`, after its UInt32 byte count.
std::vector<double> binary_array(const std::string& text, const std::string& name) {
  const std::size_t at = text.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return {};
  const std::size_t begin = text.find('>', at) + 1, end = text.find("</DataArray>", begin);
  const std::vector<unsigned char> bytes = from_base64(text.substr(begin, end - begin));
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data(), sizeof count);
  EXPECT_EQ(bytes.size(), sizeof count + count) << name;
  std::vector<double> values(count / sizeof(double));
  std::memcpy(values.data(), bytes.data() + sizeof count, count);
  return values;
}
}  // namespace

TEST(TwoBodyPictures, the_meshes_figure_marks_every_node_of_both_traces_and_of_the_merged_grid) {
  const TwoBodies b = small_bodies();
  for (int nonmortar : {0, 1}) {
    const ContactInterface g = make_interface(b, nonmortar);
    const Figure f = two_body_meshes(b, g, Matching::integral, "t");
    ASSERT_EQ(f.series.size(), 7u);  // two meshes, xi^1 and xi^2 on the bodies and in the strip, merged grid
    EXPECT_EQ(f.series[2].x, g.nonmortar_trace.x);
    EXPECT_EQ(f.series[3].x, g.mortar_trace.x);
    // the strip's merged-grid line has a tick at every node of both traces
    const Series& merged = f.series[6];
    for (const InterfaceTrace* t : {&g.nonmortar_trace, &g.mortar_trace})
      for (double x : t->x) {
        bool ticked = false;
        for (std::size_t k = 0; k + 1 < merged.x.size(); ++k)
          ticked = ticked || (std::fabs(merged.x[k] - x) < 1e-12 && merged.x[k + 1] == merged.x[k] &&
                              merged.y[k] < merged.y[k + 1]);
        EXPECT_TRUE(ticked) << "x = " << x;
      }
    // the strip lies below body 2 (y <= -H2), the lifted body 1 above Gamma_c
    for (std::size_t s = 4; s < 7; ++s)
      for (double y : f.series[s].y)
        if (!std::isnan(y)) {
          EXPECT_LT(y, -0.5);
        }
    EXPECT_GT(f.series[nonmortar == 0 ? 2 : 3].y[0], 0.0);
  }
  // pointwise: no merged grid, but a link from each node a of xi^1 to the mortar trace
  const Figure p = two_body_meshes(b, make_interface(b, 0), Matching::pointwise, "t");
  ASSERT_EQ(p.series.size(), 7u);
  EXPECT_EQ(p.series[4].x.size(), 3 * make_interface(b, 0).nonmortar_trace.x.size());
}

TEST(TwoBodyPictures, the_deformed_figure_states_a_magnification_that_makes_u_visible) {
  const TwoBodies b = small_bodies();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(b.num_dofs());
  u[1] = 1e-4;  // one node moves by 1e-4 m: magnified to 5% of L = 1, a factor 500
  const Figure f = deformed_two_bodies(b, u, "t");
  EXPECT_NE(f.title.find("x 500"), std::string::npos) << f.title;
  ASSERT_EQ(f.series.size(), 4u);  // two reference meshes, two deformed ones
  // node 0 of body 1 drawn at its place + 500 u
  EXPECT_NEAR(f.series[2].y[0] - f.series[0].y[0], 500 * 1e-4, 1e-12);
}

TEST(TwoBodyPictures, a_curve_is_evaluated_between_its_points_and_at_its_ends) {
  const InterfaceCurve c{{0, 0.5, 1}, {1, 3, 2}};
  const std::vector<double> v = curve_at(c, {0, 0.25, 0.5, 0.75, 1});
  const std::vector<double> expected{1, 2, 3, 2.5, 2};
  for (std::size_t k = 0; k < v.size(); ++k) EXPECT_NEAR(v[k], expected[k], 1e-15);
  EXPECT_THROW(curve_at({{0}, {1}}, {0}), std::invalid_argument);
}

TEST(TwoBodyPictures, vtu_files_are_xml_with_every_point_cell_and_value) {
  const TwoBodies b = small_bodies();
  Eigen::VectorXd u(b.num_dofs());
  for (Eigen::Index k = 0; k < u.size(); ++k) u[k] = 1e-3 * std::sin(0.7 * k);
  const InterfaceCurve p{{0, 0.25, 0.5, 1}, {1, 2, 3, 4}};
  const InterfaceCurve jump{{0, 0.25, 0.4, 0.5, 1}, {0, 1e-6, -1e-6, 0, 2e-6}};
  const std::string dir = ::testing::TempDir();
  write_two_body_vtu(dir, b, u, p, jump);
  for (int l = 0; l < 2; ++l) {
    const Mesh& m = b.body(l).mesh;
    const std::string text = read(dir + "/body" + std::to_string(l + 1) + ".vtu");
    EXPECT_TRUE(well_formed(text));
    EXPECT_NE(text.find("NumberOfPoints=\"" + std::to_string(m.num_nodes()) + "\""), std::string::npos);
    EXPECT_NE(text.find("NumberOfCells=\"" + std::to_string(m.triangles.size()) + "\""), std::string::npos);
    const Eigen::VectorXd ul = b.part(u, l);
    const std::vector<double> d = binary_array(text, "displacement");
    ASSERT_EQ(d.size(), 3u * m.num_nodes());
    for (int a = 0; a < m.num_nodes(); ++a) {
      EXPECT_EQ(d[3 * a], ul[2 * a]);
      EXPECT_EQ(d[3 * a + 1], ul[2 * a + 1]);
    }
    const auto stress = element_stresses(m, b.body(l).material, ul);
    const std::vector<double> sxy = binary_array(text, "sigma_xy"), mises = binary_array(text, "von_mises");
    ASSERT_EQ(sxy.size(), m.triangles.size());
    ASSERT_EQ(mises.size(), m.triangles.size());
    for (std::size_t t = 0; t < stress.size(); ++t) {
      EXPECT_EQ(sxy[t], stress[t][2]);
      EXPECT_GE(mises[t], std::fabs(stress[t][2]) * std::sqrt(3.0) * (1 - 1e-12));  // von Mises >= sqrt(3)|s_xy|
    }
  }
  const std::string contact = read(dir + "/contact.vtu");
  EXPECT_TRUE(well_formed(contact));
  EXPECT_NE(contact.find("NumberOfPoints=\"5\" NumberOfCells=\"4\""), std::string::npos);
  const std::vector<double> pressure = binary_array(contact, "pressure");
  const std::vector<double> expected{1, 2, 2.6, 3, 4};  // the P1 pressure at the jump's points
  ASSERT_EQ(pressure.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_NEAR(pressure[k], expected[k], 1e-14);
  EXPECT_EQ(binary_array(contact, "normal_jump"), jump.value);
  EXPECT_THROW(write_curve_vtu(dir + "/bad.vtu", {0, 1}, {{"pressure", {1, 2, 3}}}), std::invalid_argument);
}

TEST(Vtu, von_mises_of_plane_strain_matches_the_hand_values) {
  // pure shear s_xy = 1: sqrt(3); uniaxial s_xx = 1 with nu = 0: 1; hydrostatic s_xx = s_yy =
  // 1 with nu = 0.5 gives s_zz = 1 and no deviator: 0.
  EXPECT_NEAR(von_mises_plane_strain({0, 0, 1}, 0.3), std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(von_mises_plane_strain({1, 0, 0}, 0.0), 1.0, 1e-15);
  EXPECT_NEAR(von_mises_plane_strain({1, 1, 0}, 0.5), 0.0, 1e-15);
}

TEST(Vtu, ascii_and_binary_hold_the_same_grid_and_bad_grids_are_refused) {
  VtuGrid g;
  g.points = {{0, 0}, {1, 0}, {0, 1}};
  g.connectivity = {0, 1, 2};
  g.cell_data.push_back({"a", 1, {7.5}});
  const std::string dir = ::testing::TempDir();
  write_vtu(dir + "/a.vtu", g, VtuFormat::ascii);
  write_vtu(dir + "/b.vtu", g, VtuFormat::binary);
  const std::string a = read(dir + "/a.vtu"), b = read(dir + "/b.vtu");
  EXPECT_TRUE(well_formed(a));
  EXPECT_TRUE(well_formed(b));
  EXPECT_NE(a.find(">\n7.5\n</DataArray>"), std::string::npos);
  EXPECT_EQ(binary_array(b, "a"), std::vector<double>{7.5});
  g.connectivity = {0, 1, 3};
  EXPECT_THROW(write_vtu(dir + "/c.vtu", g, VtuFormat::ascii), std::invalid_argument);
  g.connectivity = {0, 1, 2};
  g.cell_data[0].values = {1, 2};
  EXPECT_THROW(write_vtu(dir + "/c.vtu", g, VtuFormat::binary), std::invalid_argument);
}
