// The phase profile behind --profile: exclusive times that add up to the run, phases in the
// order they first appeared, and the printed and CSV breakdowns with "other" and "total".
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "common/timing/profile.hpp"
#include "common/timing/stopwatch.hpp"

using namespace mortar;

namespace {
void sleep_ms(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

std::vector<std::string> names(const Profile& p) {
  std::vector<std::string> n;
  for (const auto& [name, s] : p.phases()) n.push_back(name);
  return n;
}
}  // namespace

// A phase opened inside another pauses it: 20 ms in the outer phase on its own and 20 ms in
// the inner one give outer ~ 20 ms, not 40. Inclusive times would count the inner 20 ms twice,
// so the phases would add up to more than the wall clock around them.
TEST(Profile, an_inner_phase_pauses_the_outer_one) {
  Profile& p = Profile::current();
  p.clear();
  const Stopwatch wall;
  {
    const ProfilePhase outer("outer");
    sleep_ms(20);
    {
      const ProfilePhase inner("inner");
      sleep_ms(20);
    }
  }
  const double elapsed = wall.seconds();
  EXPECT_GE(p.seconds("outer"), 0.015);
  EXPECT_LT(p.seconds("outer"), 0.200);
  EXPECT_GE(p.seconds("inner"), 0.015);
  EXPECT_LT(p.seconds("inner"), 0.200);
  EXPECT_LE(p.total(), elapsed) << "outer " << p.seconds("outer") << " s, inner " << p.seconds("inner") << " s";
  p.clear();
}

// Phases are listed in the order they first appeared; a name opened again adds to its entry
// (10 ms twice: at least 20 ms, one entry); time outside every phase is charged to none.
TEST(Profile, phases_keep_first_seen_order_and_accumulate) {
  Profile& p = Profile::current();
  p.clear();
  const Stopwatch wall;
  { const ProfilePhase a("assembly"); sleep_ms(10); }
  { const ProfilePhase b("factorization"); sleep_ms(1); }
  sleep_ms(30);  // outside every phase
  { const ProfilePhase a("assembly"); sleep_ms(10); }
  { const ProfilePhase c("solves"); sleep_ms(1); }
  const double elapsed = wall.seconds();
  EXPECT_EQ(names(p), (std::vector<std::string>{"assembly", "factorization", "solves"}));
  EXPECT_GE(p.seconds("assembly"), 0.0199);
  EXPECT_EQ(p.seconds("never opened"), 0.0);
  EXPECT_LE(p.total(), elapsed - 0.0299) << "the 30 ms outside every phase were charged";
  p.clear();
  EXPECT_TRUE(p.phases().empty());
  EXPECT_EQ(p.total(), 0.0);
  EXPECT_EQ(p.seconds("assembly"), 0.0);
}

namespace {
// A level and its limit with phases of their own and one in common.
std::vector<ProfileColumn> two_columns() {
  return {{"level", {{"assembly", 1.0}, {"solves", 0.5}}, 2.0},
          {"limit", {{"assembly", 0.75}, {"factorization", 0.25}}, 1.25}};
}

// The rows of a printed or CSV table: first field, then the numbers.
struct Row {
  std::string name;
  std::vector<double> values;
};
std::vector<Row> rows(const std::string& text, char separator) {
  std::vector<Row> out;
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);  // header
  while (std::getline(lines, line)) {
    if (separator != ' ')
      for (char& ch : line)
        if (ch == separator) ch = ' ';
    std::istringstream fields(line);
    Row r;
    fields >> r.name;
    for (double v; fields >> v;) r.values.push_back(v);
    out.push_back(r);
  }
  return out;
}

void expect_table(const std::vector<Row>& r) {
  // every phase of either column in first-seen order, then other and total
  ASSERT_EQ(r.size(), 5u);
  const std::vector<std::string> order{"assembly", "solves", "factorization", "other", "total"};
  const std::vector<std::vector<double>> values{{1.0, 0.75}, {0.5, 0.0}, {0.0, 0.25}, {0.5, 0.25}, {2.0, 1.25}};
  for (std::size_t i = 0; i < r.size(); ++i) {
    EXPECT_EQ(r[i].name, order[i]);
    ASSERT_EQ(r[i].values.size(), 2u) << r[i].name;
    for (int c = 0; c < 2; ++c) EXPECT_NEAR(r[i].values[c], values[i][c], 1e-4) << r[i].name << ", column " << c;
  }
}
}  // namespace

// One line per phase, a phase missing from a column printed as 0, "other" = total minus the
// phases, and the totals last.
TEST(Profile, format_profile_prints_phases_other_and_total) {
  const std::string text = format_profile(two_columns());
  const std::string header = text.substr(0, text.find('\n'));
  EXPECT_NE(header.find("level"), std::string::npos) << header;
  EXPECT_NE(header.find("limit"), std::string::npos) << header;
  expect_table(rows(text, ' '));
}

// The CSV: header phase,<title>_s,... and the same rows as the printed table.
TEST(Profile, write_profile_csv_writes_other_as_total_minus_phases) {
  const std::string path = ::testing::TempDir() + "profile_test.csv";
  write_profile_csv(path, two_columns());
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text.substr(0, text.find('\n')), "phase,level_s,limit_s");
  expect_table(rows(text, ','));
  std::remove(path.c_str());
}
