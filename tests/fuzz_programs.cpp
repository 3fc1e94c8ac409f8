// The chapter programs' command lines, fuzzed with a fixed seed against the sanitized build.
// Each program's options are read from its `--help`; 200 argument lists per program mix valid
// and invalid values: fractions, NaN, inf, huge and tiny numbers, missing values, unknown and
// duplicated options. Every run must end with status 0 or 2 (or 1 with a "<program>: error:"
// message), by no signal and with no sanitizer report; a refusal (2) leaves nothing behind,
// and an accepted run (0) writes no NaN or inf into any CSV or JSON. Some lists point --out at
// a user's own folder, a dangling symlink or a symlink loop: whatever the status, the user's
// files and links are still there afterwards. Sizes stay small (a
// coarsest mesh of 4 and 3 levels unless the list itself tries --n0 or --levels; chapter 10,
// which has no levels, 3 adaptive steps and at most 5000 unknowns unless the list tries
// --max-steps or --max-dofs), so each accepted run takes well under a second.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "program_run.hpp"

namespace {

namespace fs = std::filesystem;

constexpr int lists_per_program = 200;
constexpr unsigned seed = 20240601;
// A hang detector, not a time limit: most runs take well under a second, but the largest list
// the seed makes (ch05, --h-ratio 0.1: 52k dofs and the Hertz reference, under the sanitizers)
// took 40-60 s on a busy machine.
constexpr int seconds_per_run = 300;


std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

ProgramRun run(const std::string& program, const std::vector<std::string>& args) {
  std::string command = "timeout " + std::to_string(seconds_per_run) + " " + program;
  for (const std::string& a : args) command += " " + quoted(a);
  return run_command(command);
}

// One option as `--help` shows it: "  --name VALUE  text (a|b|c) [default: x]".
struct OptionSpec {
  std::string name;
  bool takes_value = false;
  std::vector<std::string> choices;
  std::string default_value;
};

std::vector<OptionSpec> options_from_help(const std::string& program) {
  const ProgramRun help = run(program, {"--help"});
  std::vector<OptionSpec> options;
  const std::regex line(R"(^  --([A-Za-z0-9-]+)( VALUE)?\s.*?(?:\(([^()]*\|[^()]*)\) )?(?:\[default: (.*)\])?$)");
  std::istringstream in(help.output);
  for (std::string l; std::getline(in, l);) {
    std::smatch m;
    if (!std::regex_match(l, m, line)) continue;
    OptionSpec o;
    o.name = m[1];
    o.takes_value = m[2].matched;
    if (m[3].matched) {
      std::stringstream choices(m[3].str());
      for (std::string c; std::getline(choices, c, '|');) o.choices.push_back(c);
    }
    o.default_value = m[4];
    options.push_back(o);
  }
  return options;
}

// Values no program may take silently: each is refused, or in range and then accepted.
const std::vector<std::string> odd_values = {
    "nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e400", "-1e400", "1e-400", "0", "-0", "-1",
    "abc", "", "1/0", "0/0", "3/0", "1/3", "3/2", "-3/2", "2/3/4", "0x10", "1e", "1.5.2", "+2", " 2",
    "2 ", "1,5", "1e300", "1e-300", "1e-160", "-1e300", "1e308", "4.9e-324", "2147483648",
    "-2147483649", "9999999999999999999", "--no-plot"};
// Modest values, in range for most options: with them a run is accepted and stays small.
const std::vector<std::string> modest_values = {"0.5", "1", "2", "3/2", "2/3", "0.3", "0.1", "1/3"};
// Sizes: small valid ones and clearly invalid ones only, so no accepted run is large.
const std::vector<std::string> n0_values = {"2", "3", "4", "0", "-4", "2.5", "1e400", "nan", "abc", "", "1/0", "99999999999"};
const std::vector<std::string> levels_values = {"3", "0", "-1", "2", "1000000", "nan", "3.5", "", "inf"};
// Chapter 10's sizes: adaptive steps and the unknowns at which both of its runs stop.
const std::vector<std::string> max_steps_values = {"3", "1", "2", "0", "-1", "201", "nan", "2.5", "", "inf"};
const std::vector<std::string> max_dofs_values = {"5000", "100", "2000", "99", "0", "-1", "nan", "1e400", "abc", ""};
// Young's moduli where the unit of E is tried to its limits.
const std::vector<std::string> modulus_values = {"1e6", "1e-6", "1e300", "1e-300", "1e-160", "1e-150"};
const std::vector<std::string> unknown_options = {"--bogus", "-n0", "--N0", "--n0=4", "---n0", "--", "-",
                                                  "--no-plot=1", "quick", "--help-me", "--E", "--e1"};

class ListMaker {
 public:
  ListMaker(std::vector<OptionSpec> options, unsigned s) : options_(std::move(options)), rng_(s) {
    has_levels_ = std::any_of(options_.begin(), options_.end(), [](const OptionSpec& o) { return o.name == "levels"; });
  }

  // The folder comes first so that a later --out in the list (valid or not) is the one tried.
  std::vector<std::string> next(const std::string& out, const std::string& elsewhere,
                                const std::vector<std::string>& users) {
    std::vector<std::string> args = {"--no-plot", "--out", out, "--n0", "4"};
    if (has_levels_) {
      args.insert(args.end(), {"--levels", "3"});
    } else {
      args.insert(args.end(), {"--max-steps", "3", "--max-dofs", "5000"});
    }
    const std::size_t base = args.size();
    const int changes = 1 + pick(4);
    for (int k = 0; k < changes; ++k) {
      const int kind = pick(10);
      if (kind == 0) {
        args.push_back(unknown_options[pick(unknown_options.size())]);
        if (pick(2) == 0) args.push_back(odd_values[pick(odd_values.size())]);
      } else if (kind == 1 && args.size() > base) {
        const std::size_t i = base + pick(args.size() - base);  // duplicate a generated argument
        args.push_back(args[i]);
        if (args[i].rfind("--", 0) == 0 && i + 1 < args.size()) args.push_back(args[i + 1]);
      } else {
        const OptionSpec& o = options_[pick(options_.size())];
        args.push_back("--" + o.name);
        if (!o.takes_value) {
          if (kind == 2) args.push_back(odd_values[pick(odd_values.size())]);  // a flag given a value
          continue;
        }
        if (kind == 3 && k + 1 == changes) continue;  // the value is missing at the end
        args.push_back(value_for(o, out, elsewhere, users));
      }
    }
    return args;
  }

 private:
  std::size_t pick(std::size_t n) { return static_cast<std::size_t>(rng_() % n); }

  std::string value_for(const OptionSpec& o, const std::string& out, const std::string& elsewhere,
                        const std::vector<std::string>& users) {
    const bool odd = pick(3) == 0;
    if (o.name == "out") {
      std::vector<std::string> folders = {out, elsewhere, "/proc/forbidden/x", ""};
      folders.insert(folders.end(), users.begin(), users.end());
      return folders[pick(folders.size())];
    }
    if (o.name == "n0") return n0_values[pick(n0_values.size())];
    if (o.name == "levels") return levels_values[pick(levels_values.size())];
    if (o.name == "max-steps") return max_steps_values[pick(max_steps_values.size())];
    if (o.name == "max-dofs") return max_dofs_values[pick(max_dofs_values.size())];
    if (odd) return odd_values[pick(odd_values.size())];
    if (!o.choices.empty()) return o.choices[pick(o.choices.size())];
    if (o.name.size() == 2 && o.name[0] == 'E' && pick(2) == 0) return modulus_values[pick(modulus_values.size())];
    if (pick(3) == 0) return o.default_value;
    return modest_values[pick(modest_values.size())];
  }

  std::vector<OptionSpec> options_;
  std::mt19937 rng_;
  bool has_levels_ = false;
};

std::string joined(const std::vector<std::string>& args) {
  std::string s;
  for (const std::string& a : args) s += " " + quoted(a);
  return s;
}

// The CSV and JSON files under a folder that hold a NaN or an inf as a value.
std::vector<std::string> files_with_nan_or_inf(const fs::path& folder) {
  const std::regex bad(R"((^|[,:\[ ])[-+]?(nan|inf|infinity)([\],} ]|$))", std::regex::icase);
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".csv" && ext != ".json") continue;
    std::ifstream f(entry.path());
    for (std::string line; std::getline(f, line);)
      if (std::regex_search(line, bad)) {
        found.push_back(entry.path().string() + ": " + line.substr(0, 200));
        break;
      }
  }
  return found;
}

// What a user may have where a run writes: a folder holding their own files (one named like
// the programs' write probe), a dangling symlink and a symlink loop. Returned: the --out values
// that point there.
struct UserFiles {
  fs::path root;
  std::vector<std::string> outs() const {
    return {(root / "mine").string(), (root / "dangling").string(), (root / "loop" / "sub").string()};
  }
  void make() const {
    fs::remove_all(root);
    fs::create_directories(root / "mine");
    std::ofstream(root / "mine" / "notes.txt") << "mine\n";
    std::ofstream(root / "mine" / ".write_probe") << "mine too\n";
    fs::create_symlink(root / "nowhere", root / "dangling");
    fs::create_symlink(root / "loop", root / "loop");
  }
  // "" when everything the user had is still there, unchanged; else what is missing.
  std::string missing() const {
    std::string m;
    for (const char* f : {"notes.txt", ".write_probe"}) {
      std::ifstream in(root / "mine" / f);
      std::string line;
      if (!std::getline(in, line) || line.rfind("mine", 0) != 0) m += std::string(" mine/") + f;
    }
    for (const char* link : {"dangling", "loop"})
      if (!fs::is_symlink(fs::symlink_status(root / link))) m += std::string(" the symlink ") + link;
    return m;
  }
  // the entries a refused run may find: the user's own, nothing more
  bool untouched_but_for_outputs(bool refused) const {
    if (!refused) return true;
    std::size_t entries = 0;
    for (auto it = fs::recursive_directory_iterator(root / "mine"); it != fs::recursive_directory_iterator(); ++it)
      ++entries;
    return entries == 2 && !fs::exists(root / "nowhere");
  }
};

void fuzz(const std::string& program) {
  const std::string name = fs::path(program).filename().string();
  const std::vector<OptionSpec> options = options_from_help(program);
  ASSERT_GE(options.size(), 8u) << "could not read the options of " << name << " from --help";
  const fs::path root = fs::path(WORK_DIR) / name;
  const std::string out = (root / "run").string(), elsewhere = (root / "run" / "nested" / "deeper").string();
  const UserFiles user{fs::path(WORK_DIR) / (name + ".user")};
  ListMaker lists(options, seed);
  std::map<int, int> count;  // exit status -> runs
  std::map<std::string, int> errors;  // the message of each status-1 run
  for (int i = 0; i < lists_per_program; ++i) {
    fs::remove_all(root);
    user.make();
    const std::vector<std::string> args = lists.next(out, elsewhere, user.outs());
    const ProgramRun r = run(program, args);
    ++count[r.status];
    const std::string what = name + joined(args) + "\n" + r.output;
    EXPECT_EQ(r.output.find("runtime error:"), std::string::npos) << what;
    EXPECT_EQ(r.output.find("Sanitizer"), std::string::npos) << what;
    const std::string error_line = name + ": error: ";
    const auto at = r.output.find(error_line);
    if (r.status == 1 && at != std::string::npos)
      ++errors[r.output.substr(at, r.output.find('\n', at) - at).substr(0, 120)];
    else
      EXPECT_TRUE(r.status == 0 || r.status == 2) << "status " << r.status << ": " << what;
    if (r.status == 2) {
      EXPECT_FALSE(fs::exists(root)) << "a refused run left output behind: " << what;
      EXPECT_TRUE(user.untouched_but_for_outputs(true)) << "a refused run wrote beside the user's files: " << what;
    }
    const std::string lost = user.missing();
    EXPECT_TRUE(lost.empty()) << "the run removed or changed the user's" << lost << ": " << what;
    if (r.status == 0 && fs::exists(root))
      for (const std::string& f : files_with_nan_or_inf(root)) ADD_FAILURE() << "NaN or inf in " << f << "\n" << what;
  }
  fs::remove_all(root);
  fs::remove_all(user.root);
  std::ostringstream tally;
  tally << name << ": " << lists_per_program << " argument lists (seed " << seed << "): " << count[0]
        << " accepted, " << count[2] << " refused with status 2, " << count[1] << " status 1";
  for (const auto& [status, n] : count)
    if (status != 0 && status != 1 && status != 2) tally << ", " << n << " status " << status;
  tally << "\n";
  for (const auto& [message, n] : errors) tally << "  status 1 (" << n << "x): " << message << "\n";
  std::cout << tally.str();
  fs::create_directories(WORK_DIR);
  std::ofstream(fs::path(WORK_DIR) / (name + ".counts")) << tally.str();
}

}  // namespace

TEST(FuzzPrograms, ch01_command_lines_end_in_status_0_or_2) { fuzz(CH01); }
TEST(FuzzPrograms, ch02_command_lines_end_in_status_0_or_2) { fuzz(CH02); }
TEST(FuzzPrograms, ch03_command_lines_end_in_status_0_or_2) { fuzz(CH03); }
TEST(FuzzPrograms, ch04_command_lines_end_in_status_0_or_2) { fuzz(CH04); }
TEST(FuzzPrograms, ch05_command_lines_end_in_status_0_or_2) { fuzz(CH05); }
TEST(FuzzPrograms, ch06_command_lines_end_in_status_0_or_2) { fuzz(CH06); }
TEST(FuzzPrograms, ch07_command_lines_end_in_status_0_or_2) { fuzz(CH07); }
TEST(FuzzPrograms, ch08_command_lines_end_in_status_0_or_2) { fuzz(CH08); }
TEST(FuzzPrograms, ch10_command_lines_end_in_status_0_or_2) { fuzz(CH10); }
TEST(FuzzPrograms, ch11_command_lines_end_in_status_0_or_2) { fuzz(CH11); }
