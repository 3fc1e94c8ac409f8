#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/study/convergence_study.hpp"

using namespace mortar;

TEST(ConvergenceStudy, slope_of_an_exact_power_law) {
  EXPECT_NEAR(log_log_slope({0.1, 0.05, 0.025}, {3e-2, 7.5e-3, 1.875e-3}), 2.0, 1e-12);
  EXPECT_TRUE(std::isnan(log_log_slope({0.1}, {1.0})));
}

TEST(ConvergenceStudy, rates_use_the_three_finest_levels) {
  ConvergenceTable t;
  // a pre-asymptotic first level that must not enter the fit
  const double h[] = {0.4, 0.2, 0.1, 0.05};
  const double e[] = {10.0, 0.2 * 0.2, 0.1 * 0.1, 0.05 * 0.05};
  for (int i = 0; i < 4; ++i) t.add({{"h", h[i]}, {"dofs", 10.0 * i}, {"time_s", 0.1}, {"err_x", e[i]}});
  EXPECT_NEAR(t.rates().at("err_x"), 2.0, 1e-12);
  EXPECT_EQ(t.rates().count("dofs"), 0u);
}

TEST(ConvergenceStudy, local_rates_are_level_to_level_slopes) {
  ConvergenceTable t;
  // error 3 h^2 on the first three levels, then 5 h: the local rates show the change
  const double hs[] = {0.4, 0.2, 0.1, 0.05, 0.025};
  for (int k = 0; k < 5; ++k) {
    const double h = hs[k];
    const double e = k <= 2 ? 3 * h * h : 0.3 * h;  // both 0.03 at h = 0.1
    t.add({{"h", h}, {"dofs", 1.0 / (h * h)}, {"err_a", e}});
  }
  const ConvergenceTable local = t.local_rates();
  ASSERT_EQ(local.size(), 4u);
  EXPECT_EQ(local.columns(), (std::vector<std::string>{"h", "err_a"}));
  const std::vector<double> r = local.column("err_a");
  EXPECT_NEAR(r[0], 2.0, 1e-12);
  EXPECT_NEAR(r[1], 2.0, 1e-12);
  EXPECT_NEAR(r[2], 1.0, 1e-12);
  EXPECT_NEAR(r[3], 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(local.column("h")[3], 0.025);
}

TEST(ConvergenceStudy, local_rates_between_zero_errors_are_written_blank) {
  ConvergenceTable t;
  for (double h : {0.2, 0.1, 0.05}) t.add({{"h", h}, {"err_zero", 0.0}, {"err_a", h}});
  const std::string path = (std::filesystem::temp_directory_path() / "local_rates_blank.csv").string();
  t.local_rates().write_csv(path, true);
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  EXPECT_EQ(s.str().find("nan"), std::string::npos) << s.str();
  EXPECT_NE(s.str().find(",,1"), std::string::npos) << "an undefined rate is an empty field:\n" << s.str();
}

TEST(ConvergenceStudy, rows_must_repeat_the_columns) {
  ConvergenceTable t;
  t.add({{"h", 1.0}, {"err_a", 1.0}});
  EXPECT_THROW(t.add({{"h", 1.0}}), std::invalid_argument);
  EXPECT_THROW(t.add({{"h", 1.0}, {"err_b", 1.0}}), std::invalid_argument);
}

TEST(ConvergenceStudy, writes_csv_and_summary_in_the_contract_shape) {
  const auto dir = std::filesystem::temp_directory_path() / "convergence_study_test";
  std::filesystem::create_directories(dir);
  ConvergenceTable t;
  t.add({{"h", 0.5}, {"dofs", 8}, {"time_s", 0.01}, {"err_energy", 0.5}});
  t.add({{"h", 0.25}, {"dofs", 32}, {"time_s", 0.02}, {"err_energy", 0.25}});
  t.write_csv((dir / "convergence.csv").string());
  std::ifstream csv(dir / "convergence.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "h,dofs,time_s,err_energy");

  OptionParser parser("demo", "demo");
  int n = 4;
  parser.add_int("n0", n, "n", Range::positive());
  JsonObject results;
  results.set("limit_ratio", 1.2).set("limit_s", 0.5);
  write_summary((dir / "summary.json").string(), parser, t.rates(), results);
  std::ifstream f(dir / "summary.json");
  std::stringstream s;
  s << f.rdbuf();
  const std::string json = s.str();
  for (const char* key : {"\"program\": \"demo\"", "\"options\"", "\"n0\": 4", "\"rates\"",
                          "\"err_energy\": 1", "\"results\"", "\"limit_ratio\": 1.2"})
    EXPECT_NE(json.find(key), std::string::npos) << key << " missing in\n" << json;
}

TEST(ConvergenceStudy, json_writes_nan_as_null) {
  JsonObject o;
  o.set("a", std::nan("")).set("b", "x\"y");
  EXPECT_EQ(o.dump(), "{\n  \"a\": null,\n  \"b\": \"x\\\"y\"\n}");
}

TEST(ConvergenceStudy, json_writes_lists_of_numbers) {
  JsonObject o;
  o.set("steps", std::vector<int>{7, 1, 2}).set("empty", std::vector<double>{}).set("k", std::vector<double>{1.5, std::nan("")});
  EXPECT_EQ(o.dump(), "{\n  \"steps\": [7, 1, 2],\n  \"empty\": [],\n  \"k\": [1.5, null]\n}");
}
