// Figures: every plotted figure leaves name.png and name.pdf (vector) beside name.gp and
// name.dat, and the script alone makes both again.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>

#include "common/study/plot.hpp"

namespace {

namespace fs = std::filesystem;

bool have_gnuplot() {
  const std::string gnuplot = MORTAR_GNUPLOT;
  if (gnuplot.find('/') != std::string::npos) return fs::exists(gnuplot);
  return std::system(("command -v " + gnuplot + " > /dev/null 2>&1").c_str()) == 0;
}

std::string read(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

fs::path fresh_folder(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() / ("plot_outputs_" + name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

mortar::Figure loglog_figure() {
  mortar::Figure fig;
  fig.title = "errors against h";
  fig.xlabel = "h [m]";
  fig.ylabel = "error [-]";
  fig.log_x = fig.log_y = true;
  fig.series.push_back({"energy", {0.5, 0.25, 0.125}, {0.4, 0.2, 0.1}, "linespoints", "pt 7"});
  fig.series.push_back({"L^2", {0.5, 0.25, 0.125}, {0.1, 0.025, 0.00625}, "linespoints", "pt 5"});
  fig.slopes.push_back({1.0, 0, 0.4, "slope 1", ""});
  fig.slopes.push_back({2.0, 1, 0.4, "slope 2", ""});
  return fig;
}

void expect_png_and_pdf(const fs::path& folder, const std::string& name) {
  const std::string png = read(folder / (name + ".png")), pdf = read(folder / (name + ".pdf"));
  ASSERT_GT(png.size(), 8u) << name << ".png missing or empty";
  EXPECT_EQ(png.substr(1, 3), "PNG");
  ASSERT_GT(pdf.size(), 8u) << name << ".pdf missing or empty";
  EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
}

}  // namespace

TEST(PlotOutputs, the_script_names_the_png_and_the_pdf) {
  const fs::path folder = fresh_folder("script");
  mortar::write_figure(folder.string(), "errors", loglog_figure(), false);
  const std::string gp = read(folder / "errors.gp");
  EXPECT_NE(gp.find("pngcairo"), std::string::npos);
  EXPECT_NE(gp.find("pdfcairo"), std::string::npos);
  EXPECT_NE(gp.find("set output 'errors.png'"), std::string::npos) << gp;
  EXPECT_NE(gp.find("set output 'errors.pdf'"), std::string::npos) << gp;
  EXPECT_TRUE(fs::exists(folder / "errors.dat"));
  fs::remove_all(folder);
}

TEST(PlotOutputs, a_figure_leaves_both_png_and_pdf_and_the_script_makes_them_again) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot (" MORTAR_GNUPLOT ") not found";
  const fs::path folder = fresh_folder("both");
  mortar::write_figure(folder.string(), "errors", loglog_figure(), true);
  expect_png_and_pdf(folder, "errors");
  // "gnuplot errors.gp" alone, in the folder, writes both again
  fs::remove(folder / "errors.png");
  fs::remove(folder / "errors.pdf");
  const std::string command = "cd '" + folder.string() + "' && '" MORTAR_GNUPLOT "' errors.gp";
  ASSERT_EQ(std::system(command.c_str()), 0);
  expect_png_and_pdf(folder, "errors");
  fs::remove_all(folder);
}

TEST(PlotOutputs, panels_and_a_right_axis_make_one_png_and_one_pdf) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot (" MORTAR_GNUPLOT ") not found";
  const fs::path folder = fresh_folder("panels");
  mortar::Figure fig;
  fig.title = "pressure and gap";
  fig.xlabel = "x [m]";
  fig.ylabel = "p [Pa]";
  fig.y2label = "gap [m]";
  fig.series.push_back({"p", {0, 1, 2}, {1, 2, 1}, "lines", ""});
  mortar::Series gap{"gap", {0, 1, 2}, {1e-8, 0, 1e-8}, "lines", ""};
  gap.right_axis = true;
  fig.series.push_back(gap);
  mortar::Figure zoom = fig;
  zoom.title = "zoom";
  zoom.height = 300;
  fig.panels.push_back(zoom);
  mortar::write_figure(folder.string(), "state", fig, true);
  expect_png_and_pdf(folder, "state");
  const std::string gp = read(folder / "state.gp");
  EXPECT_NE(gp.find("set multiplot"), std::string::npos);
  EXPECT_NE(gp.find("axes x1y2"), std::string::npos);
  fs::remove_all(folder);
}

TEST(PlotOutputs, a_run_without_gnuplot_leaves_no_stale_figure) {
  const fs::path folder = fresh_folder("stale");
  std::ofstream(folder / "errors.png") << "old";
  std::ofstream(folder / "errors.pdf") << "old";
  mortar::write_figure(folder.string(), "errors", loglog_figure(), false);
  EXPECT_FALSE(fs::exists(folder / "errors.png"));
  EXPECT_FALSE(fs::exists(folder / "errors.pdf"));
  fs::remove_all(folder);
}

// A reference slope anchored to a series with no positive point (every error exactly 0) is left
// out of the script with a warning; the other slope is still drawn. Before, write_figure threw
// and the run that had solved its problem ended with status 1.
TEST(PlotOutputs, a_slope_with_nothing_to_anchor_to_is_left_out_not_fatal) {
  const fs::path folder = fresh_folder("zero_anchor");
  mortar::Figure fig = loglog_figure();
  fig.series[0].y = {0.0, 0.0, 0.0};
  testing::internal::CaptureStderr();
  ASSERT_NO_THROW(mortar::write_figure(folder.string(), "errors", fig, false));
  const std::string warning = testing::internal::GetCapturedStderr();
  EXPECT_NE(warning.find("slope 1 left out"), std::string::npos) << warning;
  const std::string gp = read(folder / "errors.gp");
  EXPECT_EQ(gp.find("'slope 1'"), std::string::npos) << gp;
  EXPECT_NE(gp.find("ref0(x) with lines"), std::string::npos) << gp;  // slope 2, renumbered
  EXPECT_NE(gp.find("'slope 2'"), std::string::npos) << gp;
  if (have_gnuplot()) {
    mortar::write_figure(folder.string(), "errors", fig, true);
    expect_png_and_pdf(folder, "errors");
  }
  fs::remove_all(folder);
}

TEST(PlotOutputs, reference_slopes_differ_in_colour_and_dash) {
  std::set<std::string> colours, dashes;
  for (std::size_t k = 0; k < 4; ++k) {
    const std::string s = mortar::reference_slope_style(k);
    colours.insert(s.substr(s.find("lc rgb")));
    dashes.insert(s.substr(0, s.find(" lw")));
  }
  EXPECT_EQ(colours.size(), 4u);
  EXPECT_EQ(dashes.size(), 4u);
}

TEST(PlotOutputs, the_same_figure_drawn_twice_gives_the_same_pdf) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot (" MORTAR_GNUPLOT ") not found";
  const fs::path folder = fresh_folder("twice");
  mortar::write_figure(folder.string(), "errors", loglog_figure(), true);
  const std::string first = read(folder / "errors.pdf");
  mortar::write_figure(folder.string(), "errors", loglog_figure(), true);
  EXPECT_EQ(read(folder / "errors.pdf"), first);  // no creation time left in it
  fs::remove_all(folder);
}

// Greek names in labels are set as the letters when no letter touches them: "Gamma_c" becomes
// "Γ_c" and "nu1" "ν1", while "alphabet" and "menu" stay as they are.
TEST(PlotOutputs, greek_names_are_set_as_letters) {
  const fs::path folder = fresh_folder("greek");
  mortar::Figure fig = loglog_figure();
  fig.title = "lambda_h on Gamma_c, nu1 = 0.3, alphabet, menu";
  fig.ylabel = "-sigma_N [Pa]";
  fig.series[0].title = "psi_i and phi_j";
  mortar::write_figure(folder.string(), "greek", fig, false);
  const std::string gp = read(folder / "greek.gp");
  EXPECT_NE(gp.find("set title 'λ_h on Γ_c, ν1 = 0.3, alphabet, menu'"), std::string::npos) << gp;
  EXPECT_NE(gp.find("set ylabel '-σ_N [Pa]'"), std::string::npos) << gp;
  EXPECT_NE(gp.find("title 'ψ_i and φ_j'"), std::string::npos) << gp;
  EXPECT_NE(gp.find("set encoding utf8"), std::string::npos) << gp;
  fs::remove_all(folder);
}

// A P1 triangle is drawn as its three vertices and back; a P2 triangle as three parabolas of
// 8 chords through its midpoint nodes: with the midpoint of edge 0 moved off the chord, the
// drawn edge passes through it at s = 1/2 and through 3/4 of it at s = 1/4.
TEST(PlotOutputs, p2_edges_are_drawn_through_their_midpoint_nodes) {
  mortar::Mesh p1;
  p1.nodes = {{0, 0}, {1, 0}, {0, 1}};
  p1.triangles = {{0, 1, 2}};
  const mortar::Series straight = mortar::mesh_edges(p1, "P1");
  ASSERT_EQ(straight.x.size(), 5u);  // a, b, c, a, then the break
  EXPECT_EQ(straight.x[3], 0.0);
  EXPECT_EQ(straight.y[2], 1.0);
  EXPECT_TRUE(std::isnan(straight.x[4]));

  mortar::Mesh p2 = p1;
  p2.nodes.push_back({0.5, 0.2});  // edge 0 (0 -> 1), bent
  p2.nodes.push_back({0.5, 0.5});  // edge 1 (1 -> 2)
  p2.nodes.push_back({0.0, 0.5});  // edge 2 (2 -> 0)
  p2.edge_nodes = {{3, 4, 5}};
  const mortar::Series curved = mortar::mesh_edges(p2, "P2");
  ASSERT_EQ(curved.x.size(), 3u * 8u + 1u + 1u);  // 25 points around, then the break
  EXPECT_NEAR(curved.x[4], 0.5, 1e-15);  // s = 1/2 on edge 0: the midpoint node
  EXPECT_NEAR(curved.y[4], 0.2, 1e-15);
  EXPECT_NEAR(curved.x[2], 0.25, 1e-15);  // s = 1/4: 4 s (1 - s) = 3/4 of the midpoint's lift
  EXPECT_NEAR(curved.y[2], 0.15, 1e-15);
  EXPECT_NEAR(curved.x[24], 0.0, 1e-15);  // closed: back at vertex 0
  EXPECT_NEAR(curved.y[24], 0.0, 1e-15);
}

// The top of a log y axis two decades above the highest point's decade, and none with no data.
TEST(PlotOutputs, room_above_data_raises_the_top_of_the_axis) {
  mortar::Figure fig = loglog_figure();
  fig.series[0].y = {3.0, 1.6e4, std::numeric_limits<double>::quiet_NaN()};
  fig.series[0].x = {1.0, 2.0, 3.0};
  mortar::room_above_data(fig, 2);
  ASSERT_EQ(fig.settings.size(), 1u);
  EXPECT_EQ(fig.settings[0], "set yrange [:1e+07]");
  mortar::Figure empty;
  mortar::room_above_data(empty, 2);
  EXPECT_TRUE(empty.settings.empty());
}

// A title is set in lines that fit the figure's width, broken between words: none runs off
// the picture however many options it names.
TEST(PlotOutputs, a_title_that_fits_stays_on_one_line) {
  const std::string title = "relative errors against h: manufactured, coulomb F = 0.3";
  const std::vector<std::string> lines = mortar::title_lines(title, 900);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], title);
}

TEST(PlotOutputs, a_long_title_is_set_in_lines_that_fit_the_figure) {
  const std::string title =
      "the last load step on the finest mesh: manufactured, coulomb F = 0.3, h_2/h_1 = 1.5, non-mortar body 1, "
      "integral matching, the stick zone and the slip zone against the exact shear";
  for (const int width : {900, 600, 450}) {
    const std::vector<std::string> lines = mortar::title_lines(title, width);
    ASSERT_GE(lines.size(), 2u) << "at " << width << " pixels";
    // 8.5 pixels a character (DejaVu Sans 12), 60 pixels of margins; _ { } take no room
    const double room = (width - 60) / 8.5;
    std::string joined;
    for (const std::string& line : lines) {
      std::size_t drawn = 0;
      for (char c : line) drawn += c != '_' && c != '{' && c != '}';
      EXPECT_LE(drawn, room) << "line '" << line << "' at " << width << " pixels";
      EXPECT_FALSE(line.empty());
      EXPECT_NE(line.front(), ' ');
      EXPECT_NE(line.back(), ' ');
      joined += (joined.empty() ? "" : " ") + line;
    }
    EXPECT_EQ(joined, title) << "the lines hold every word, in order";
  }
  // a break falls after a comma or a colon, where the title's parts meet, when one is late
  // enough in the line
  const std::string first = mortar::title_lines(title, 900)[0];
  EXPECT_TRUE(first.back() == ',' || first.back() == ':') << first;
}

TEST(PlotOutputs, the_script_sets_a_long_title_on_two_lines) {
  const fs::path dir = fs::temp_directory_path() / "mortar_plot_long_title";
  fs::remove_all(dir);
  fs::create_directories(dir);
  mortar::Figure fig;
  fig.title = "a title much longer than a narrow figure can hold on one line: it must wrap";
  fig.width = 650;  // room for 69 characters: the 75 of the title do not fit
  fig.series.push_back({"data", {0, 1}, {0, 1}, "lines", ""});
  mortar::write_figure(dir.string(), "long", fig, false);
  const std::string gp = read(dir / "long.gp");
  EXPECT_NE(gp.find("set title 'a title much longer than a narrow figure can hold on one line:'.\"\\n\".'it must wrap'"),
            std::string::npos)
      << gp;
  fs::remove_all(dir);
}
