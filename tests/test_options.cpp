#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/study/options.hpp"

using namespace mortar;

namespace {
struct Demo {
  int n = 3;
  double nu = 0.3, r = 1;
  std::string mode = "a";
  bool flag = false;
};

void parse(Demo& d, std::vector<const char*> args) {
  args.insert(args.begin(), "demo");
  OptionParser p("demo", "a demo");
  p.add_int("n", d.n, "count", Range::positive());
  p.add_double("nu", d.nu, "ratio", Range::open(-1, 0.5));
  p.add_double("h-ratio", d.r, "mesh ratio", Range::positive());
  p.add_choice("mode", d.mode, {"a", "b"}, "mode");
  p.add_flag("flag", d.flag, "flag");
  p.parse(static_cast<int>(args.size()), args.data());
}
}  // namespace

TEST(Options, parses_values_fractions_and_flags) {
  Demo d;
  parse(d, {"--n", "7", "--nu=0.25", "--h-ratio", "3/2", "--mode", "b", "--flag"});
  EXPECT_EQ(d.n, 7);
  EXPECT_DOUBLE_EQ(d.nu, 0.25);
  EXPECT_DOUBLE_EQ(d.r, 1.5);
  EXPECT_EQ(d.mode, "b");
  EXPECT_TRUE(d.flag);
}

TEST(Options, given_tells_set_options_from_defaults) {
  Demo d;
  OptionParser p("demo", "a demo");
  p.add_int("n", d.n, "count", Range::positive());
  p.add_double("nu", d.nu, "ratio", Range::open(-1, 0.5));
  p.add_flag("flag", d.flag, "flag");
  const char* args[] = {"demo", "--n", "3", "--flag"};
  p.parse(4, args);
  EXPECT_TRUE(p.given("n")) << "set to its default value, but set";
  EXPECT_TRUE(p.given("flag"));
  EXPECT_FALSE(p.given("nu"));
  EXPECT_FALSE(p.given("unknown"));
}

TEST(Options, quick_sets_small_sizes_and_refuses_them_given_as_well) {
  const auto run = [](std::vector<const char*> args, int& n, int& levels) {
    args.insert(args.begin(), "demo");
    bool quick = false;
    OptionParser p("demo", "a demo");
    p.add_int("n0", n, "count", Range::positive());
    p.add_int("levels", levels, "count", Range::positive());
    p.add_flag("quick", quick, "small");
    p.parse(static_cast<int>(args.size()), args.data());
    p.apply_quick(quick, {{"n0", n, 4}, {"levels", levels, 3}});
  };
  int n = 12, levels = 6;
  run({"--n0", "7"}, n, levels);
  EXPECT_EQ(n, 7);
  EXPECT_EQ(levels, 6);
  run({"--quick"}, n, levels);
  EXPECT_EQ(n, 4);
  EXPECT_EQ(levels, 3);
  EXPECT_EXIT(run({"--quick", "--levels", "5"}, n, levels), ::testing::ExitedWithCode(2),
              ::testing::HasSubstr("--levels: cannot be combined with --quick"));
}

TEST(Options, parse_number_rejects_junk_nan_and_inf) {
  double v = 0;
  EXPECT_TRUE(parse_number("1e-3", v));
  EXPECT_TRUE(parse_number("-2/8", v));
  EXPECT_DOUBLE_EQ(v, -0.25);
  for (const char* bad : {"", "abc", "1.5x", "nan", "inf", "-inf", "1/0", "1e400", "2/", "/3", "0x10", "infinity"})
    EXPECT_FALSE(parse_number(bad, v)) << bad;
}

using OptionsDeathTest = ::testing::Test;

TEST_F(OptionsDeathTest, each_bad_input_exits_2_naming_the_option) {
  const std::vector<std::pair<std::vector<const char*>, std::string>> cases = {
      {{"--bogus"}, "--bogus: unknown option"},
      {{"--n", "0"}, "--n: must be > 0"},
      {{"--n", "-4"}, "--n: must be > 0"},
      {{"--n", "2.5"}, "--n: expects an integer"},
      {{"--n", "ten"}, "--n: expects an integer"},
      {{"--nu", "0.5"}, "--nu: must be in (-1, 0.5)"},
      {{"--nu", "nan"}, "--nu: expects a finite number"},
      {{"--h-ratio", "-1"}, "--h-ratio: must be > 0"},
      {{"--mode", "c"}, "--mode: expects one of a|b"},
      {{"--n"}, "--n: missing value"},
      {{"--mode", "--flag"}, "--mode: missing value"},
      {{"--flag=1"}, "--flag: is a flag"},
      {{"n"}, "unexpected argument 'n'"},
  };
  for (const auto& [args, message] : cases) {
    Demo d;
    EXPECT_EXIT(parse(d, args), ::testing::ExitedWithCode(2), ::testing::HasSubstr(message))
        << "input " << args.front();
  }
}

TEST_F(OptionsDeathTest, help_lists_every_option_with_its_default_and_exits_0) {
  Demo d;
  EXPECT_EXIT({
    parse(d, {"--help"});
  }, ::testing::ExitedWithCode(0), "");
  OptionParser p("demo", "a demo");
  p.add_double("nu", d.nu, "ratio", Range::open(-1, 0.5));
  EXPECT_NE(p.usage().find("--nu VALUE"), std::string::npos);
  EXPECT_NE(p.usage().find("[default: 0.3]"), std::string::npos);
}

// A refused --out leaves no folder behind: here the last component is longer than a file
// name may be, after two folders that do not exist yet.
TEST_F(OptionsDeathTest, a_refused_out_folder_leaves_nothing_behind) {
  const std::filesystem::path base = std::filesystem::temp_directory_path() / "options_refused_out";
  std::filesystem::remove_all(base);
  const std::string folder = (base / "a" / std::string(300, 'x')).string();
  OptionParser p("demo", "a demo");
  EXPECT_EXIT(prepare_output_folder(p, folder), ::testing::ExitedWithCode(2), ::testing::HasSubstr("--out: cannot create"));
  EXPECT_FALSE(std::filesystem::exists(base));
}

// A refused --out touches only what this call created: a dangling symbolic link, or a link to
// itself, given as the folder stays where the user put it.
TEST_F(OptionsDeathTest, a_refused_out_keeps_the_users_dangling_or_looping_link) {
  const std::filesystem::path base = std::filesystem::temp_directory_path() / "options_links";
  std::filesystem::remove_all(base);
  std::filesystem::create_directories(base);
  std::filesystem::create_symlink(base / "nowhere" / "at_all", base / "dangling");
  std::filesystem::create_symlink(base / "loop", base / "loop");
  for (const std::filesystem::path& link : {base / "dangling", base / "loop" / "sub"}) {
    OptionParser p("demo", "a demo");
    EXPECT_EXIT(prepare_output_folder(p, link.string()), ::testing::ExitedWithCode(2), ::testing::HasSubstr("--out"));
  }
  EXPECT_TRUE(std::filesystem::is_symlink(base / "dangling"));
  EXPECT_TRUE(std::filesystem::is_symlink(base / "loop"));
  std::filesystem::remove_all(base);
}

// A file of the user's named like the write probe survives the probe.
TEST(Options, preparing_the_output_folder_keeps_a_file_named_like_its_probe) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "options_probe_name";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  std::ofstream(folder / ".write_probe") << "mine";
  OptionParser p("demo", "a demo");
  prepare_output_folder(p, folder.string());
  std::ifstream kept(folder / ".write_probe");
  std::string content;
  kept >> content;
  EXPECT_EQ(content, "mine");
  EXPECT_FALSE(std::filesystem::exists(folder / ".write_probe.1"));  // the probe is gone
  std::filesystem::remove_all(folder);
}

TEST(Options, preparing_the_output_folder_removes_the_previous_results) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "options_stale_results";
  std::filesystem::create_directories(folder);
  for (const char* name : {"convergence.csv", "summary.json", "figure.png"}) std::ofstream(folder / name) << "old";
  OptionParser p("demo", "a demo");
  prepare_output_folder(p, folder.string());
  EXPECT_FALSE(std::filesystem::exists(folder / "convergence.csv"));
  EXPECT_FALSE(std::filesystem::exists(folder / "summary.json"));
  EXPECT_TRUE(std::filesystem::exists(folder / "figure.png"));  // only the files that claim a result
  std::filesystem::remove_all(folder);
}

// A rerun removes exactly what the previous run wrote (.outputs), so a part it skips leaves no
// stale file, and a user's own file in the folder stays. The list is written when the program
// ends: here by a child process that prepares the folder, writes two files and exits.
TEST(PrepareOutputFolder, a_rerun_removes_the_previous_runs_files_and_nothing_else) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "options_outputs";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "mine.txt") << "the user's";
  EXPECT_EXIT(
      {
        OptionParser p("demo", "a demo");
        prepare_output_folder(p, dir.string());
        std::ofstream(dir / "hertz.csv") << "1\n";
        fs::create_directories(dir / "sub");
        std::ofstream(dir / "sub" / "deep.dat") << "2\n";
        std::exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  ASSERT_TRUE(fs::exists(dir / ".outputs"));
  EXPECT_TRUE(fs::exists(dir / "hertz.csv"));
  // the rerun writes nothing: the previous run's files go, the user's stays
  OptionParser p("demo", "a demo");
  prepare_output_folder(p, dir.string());
  EXPECT_FALSE(fs::exists(dir / "hertz.csv"));
  EXPECT_FALSE(fs::exists(dir / "sub" / "deep.dat"));
  EXPECT_TRUE(fs::exists(dir / "mine.txt"));
  EXPECT_FALSE(fs::exists(dir / ".outputs"));
  fs::remove_all(dir);
}

// A list that names something outside the folder, or a link, removes nothing there.
TEST(PrepareOutputFolder, the_list_never_reaches_outside_the_folder_or_through_a_link) {
  namespace fs = std::filesystem;
  const fs::path base = fs::temp_directory_path() / "options_outside";
  fs::remove_all(base);
  fs::create_directories(base / "out");
  std::ofstream(base / "precious.txt") << "keep";
  fs::create_symlink(base / "precious.txt", base / "out" / "link.csv");
  std::ofstream(base / "out" / ".outputs") << "../precious.txt\n" << (base / "precious.txt").string() << "\nlink.csv\n";
  remove_previous_outputs((base / "out").string());
  EXPECT_TRUE(fs::exists(base / "precious.txt"));
  EXPECT_TRUE(fs::is_symlink(base / "out" / "link.csv"));
  fs::remove_all(base);
}
