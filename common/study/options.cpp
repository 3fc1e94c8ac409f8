#include "common/study/options.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

namespace mortar {

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();

std::string format_number(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

bool parse_plain(const std::string& text, double& value) {
  // plain decimal only: strtod would also take hexadecimal ("0x10") and "infinity"
  if (text.empty() || text.find_first_not_of("0123456789+-.eE") != std::string::npos) return false;
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(begin, &end);
  if (end != begin + text.size() || errno == ERANGE || !std::isfinite(v)) return false;
  value = v;
  return true;
}
}  // namespace

Range Range::any() { return {-inf, inf, true, true}; }
Range Range::positive() { return {0.0, inf, true, true}; }
Range Range::non_negative() { return {0.0, inf, false, true}; }
Range Range::closed(double lo, double hi) { return {lo, hi, false, false}; }
Range Range::open(double lo, double hi) { return {lo, hi, true, true}; }
Range Range::half_open(double lo, double hi) { return {lo, hi, false, true}; }

bool Range::contains(double v) const {
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

std::string Range::describe() const {
  if (std::isinf(lo) && std::isinf(hi)) return "any finite number";
  if (std::isinf(hi)) return std::string(lo_open ? "> " : ">= ") + format_number(lo);
  if (std::isinf(lo)) return std::string(hi_open ? "< " : "<= ") + format_number(hi);
  return std::string("in ") + (lo_open ? "(" : "[") + format_number(lo) + ", " +
         format_number(hi) + (hi_open ? ")" : "]");
}

bool parse_number(const std::string& text, double& value) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return parse_plain(text, value);
  double p = 0, q = 0;
  if (!parse_plain(text.substr(0, slash), p) || !parse_plain(text.substr(slash + 1), q)) return false;
  if (q == 0.0) return false;
  value = p / q;
  return std::isfinite(value);
}

OptionParser::OptionParser(std::string program, std::string summary)
    : program_(std::move(program)), summary_(std::move(summary)) {
  add_flag("help", help_, "print this help and exit");
}

void OptionParser::add_int(const std::string& name, int& target, const std::string& help,
                           Range range) {
  Option o{name, help, false, true, nullptr, nullptr};
  o.set = [&target, range](const std::string& text) -> std::string {
    double v = 0;
    if (!parse_plain(text, v) || v != std::floor(v)) return "expects an integer, got '" + text + "'";
    // an integer beyond the range is out of range, whatever its size (2147483647 included)
    if (!range.contains(v) || std::fabs(v) > 1e9) return "must be " + range.describe() + ", got " + text;
    target = static_cast<int>(v);
    return "";
  };
  o.show = [&target] { return std::to_string(target); };
  options_.push_back(std::move(o));
}

void OptionParser::add_double(const std::string& name, double& target, const std::string& help,
                              Range range) {
  Option o{name, help, false, true, nullptr, nullptr};
  o.set = [&target, range](const std::string& text) -> std::string {
    double v = 0;
    if (!parse_number(text, v)) return "expects a finite number, got '" + text + "'";
    if (!range.contains(v)) return "must be " + range.describe() + ", got " + text;
    target = v;
    return "";
  };
  o.show = [&target] { return format_number(target); };
  options_.push_back(std::move(o));
}

void OptionParser::add_string(const std::string& name, std::string& target,
                              const std::string& help) {
  Option o{name, help, false, false, nullptr, nullptr};
  o.set = [&target](const std::string& text) -> std::string {
    if (text.empty()) return "expects a non-empty value";
    target = text;
    return "";
  };
  o.show = [&target] { return target; };
  options_.push_back(std::move(o));
}

void OptionParser::add_choice(const std::string& name, std::string& target,
                              std::vector<std::string> choices, const std::string& help) {
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : "|") + c;
  Option o{name, help + " (" + list + ")", false, false, nullptr, nullptr};
  o.set = [&target, choices, list](const std::string& text) -> std::string {
    for (const auto& c : choices)
      if (c == text) {
        target = text;
        return "";
      }
    return "expects one of " + list + ", got '" + text + "'";
  };
  o.show = [&target] { return target; };
  options_.push_back(std::move(o));
}

void OptionParser::add_flag(const std::string& name, bool& target, const std::string& help) {
  Option o{name, help, true, false, nullptr, nullptr};
  o.set = [&target](const std::string&) -> std::string {
    target = true;
    return "";
  };
  o.show = [&target] { return target ? std::string("true") : std::string("false"); };
  options_.push_back(std::move(o));
}

const OptionParser::Option* OptionParser::find(const std::string& name) const {
  for (const auto& o : options_)
    if (o.name == name) return &o;
  return nullptr;
}

void OptionParser::fail(const std::string& name, const std::string& message) const {
  std::cerr << program_ << ": --" << name << ": " << message << "\n"
            << "Run '" << program_ << " --help' for the list of options.\n";
  std::exit(2);
}

void OptionParser::parse(int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg.rfind("--", 0) != 0 || arg.size() == 2) {
      std::cerr << program_ << ": unexpected argument '" << arg << "' (options start with --)\n";
      std::exit(2);
    }
    std::string name = arg.substr(2), value;
    const bool inline_value = name.find('=') != std::string::npos;
    if (inline_value) {
      value = name.substr(name.find('=') + 1);
      name = name.substr(0, name.find('='));
      if (name.empty()) {
        std::cerr << program_ << ": '" << arg << "' has no option name before '=' (write --name=value)\n";
        std::exit(2);
      }
    }
    if (name == "help") {
      std::cout << usage();
      std::exit(0);
    }
    const Option* o = find(name);
    if (o == nullptr) fail(name, "unknown option");
    if (o->is_flag) {
      if (inline_value) fail(name, "is a flag and takes no value");
    } else if (!inline_value) {
      if (i + 1 >= argc || std::string(argv[i + 1]).rfind("--", 0) == 0) fail(name, "missing value");
      value = argv[++i];
    }
    const std::string error = o->set(value);
    if (!error.empty()) fail(name, error);
    given_.push_back(name);
  }
}

bool OptionParser::given(const std::string& name) const {
  return std::find(given_.begin(), given_.end(), name) != given_.end();
}

void OptionParser::apply_quick(bool quick, std::initializer_list<QuickSize> sizes) const {
  if (!quick) return;
  for (const QuickSize& s : sizes) {
    if (given(s.name)) fail(s.name, "cannot be combined with --quick, which sets it");
    s.target = s.value;
  }
}

std::vector<std::pair<std::string, std::string>> OptionParser::values() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& o : options_)
    if (o.name != "help") out.emplace_back(o.name, o.show());
  return out;
}

std::vector<bool> OptionParser::numeric() const {
  std::vector<bool> out;
  for (const auto& o : options_)
    if (o.name != "help") out.push_back(o.is_numeric);
  return out;
}

std::string OptionParser::usage() const {
  std::ostringstream s;
  s << "Usage: " << program_ << " [options]\n\n" << summary_ << "\n\nOptions:\n";
  for (const auto& o : options_) {
    std::string head = "  --" + o.name + (o.is_flag ? "" : " VALUE");
    s << head << std::string(head.size() < 24 ? 24 - head.size() : 1, ' ') << o.help;
    if (!o.is_flag && o.name != "help") s << " [default: " << o.show() << "]";
    s << "\n";
  }
  return s.str();
}

void prepare_output_folder(const OptionParser& parser, const std::string& folder) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // The topmost folder this call creates: removed again if the folder turns out unusable, so
  // that a refused --out leaves nothing behind.
  // A path counts as new only when nothing is there, not even a link: a dangling symbolic link
  // or a loop of links is the user's, and stays (exists() would follow it and say false).
  fs::path first_new;
  const auto nothing_at = [&](const fs::path& p) {
    return fs::symlink_status(p, ec).type() == fs::file_type::not_found;
  };
  for (fs::path p = fs::absolute(folder, ec); !p.empty() && nothing_at(p); p = p.parent_path()) {
    first_new = p;
    if (p == p.parent_path()) break;
  }
  const auto refuse = [&](const std::string& message) {
    if (!first_new.empty()) fs::remove_all(first_new, ec);
    parser.fail("out", message);
  };
  fs::create_directories(folder, ec);
  if (ec) refuse("cannot create folder '" + folder + "': " + ec.message());
  if (!fs::is_directory(folder)) refuse("'" + folder + "' is not a folder");
  // The write probe gets a name no file in the folder has, so that only this call's file is removed.
  fs::path probe = fs::path(folder) / ".write_probe";
  for (int k = 1; !nothing_at(probe); ++k) probe = fs::path(folder) / (".write_probe." + std::to_string(k));
  {
    std::ofstream f(probe);
    if (!f) refuse("folder '" + folder + "' is not writable");
  }
  fs::remove(probe, ec);
  // A previous run's results must not pass for this run's if this one fails before writing.
  for (const char* name : {"convergence.csv", "summary.json"}) {
    fs::remove(fs::path(folder) / name, ec);
    if (fs::exists(fs::path(folder) / name)) refuse("cannot remove the previous run's " + std::string(name) + " in '" + folder + "'");
  }
  // Nor may the files of a part this run skips (chapter 6's hertz.csv after --no-hertz): remove
  // what the previous run listed as its own, and list this run's at its end.
  remove_previous_outputs(folder);
  record_outputs_at_exit(folder);
}

namespace {
constexpr const char* manifest_name = ".outputs";

// Regular files below folder (links not followed), as paths relative to it.
std::vector<std::string> regular_files(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec) && !it->is_symlink(ec) && it->path().filename() != manifest_name)
      out.push_back(fs::relative(it->path(), folder, ec).generic_string());
  return out;
}

// The folder and what was in it when the run began (each file's modification time), for the
// list written when the program ends: new files, and files written since. (Not "written after
// the start time": the kernel stamps files with a coarse clock that can lag the one a program
// reads by milliseconds.)
struct RunOutputs {
  std::filesystem::path folder;
  std::map<std::string, std::filesystem::file_time_type> before;
};
RunOutputs& run_outputs() {
  static RunOutputs outputs;
  return outputs;
}
}  // namespace

void remove_previous_outputs(const std::string& folder) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path manifest = fs::path(folder) / manifest_name;
  if (fs::symlink_status(manifest, ec).type() != fs::file_type::regular) return;
  std::ifstream in(manifest);
  for (std::string name; std::getline(in, name);) {
    // only plain relative paths inside the folder, and only regular files: never a link, never
    // anything outside
    const fs::path relative(name);
    if (name.empty() || relative.is_absolute() || name.find("..") != std::string::npos) continue;
    const fs::path p = fs::path(folder) / relative;
    if (fs::symlink_status(p, ec).type() == fs::file_type::regular) fs::remove(p, ec);
  }
  in.close();
  fs::remove(manifest, ec);
}

void record_outputs_at_exit(const std::string& folder) {
  namespace fs = std::filesystem;
  RunOutputs& r = run_outputs();
  std::error_code ec;
  r.folder = fs::absolute(folder);
  r.before.clear();
  for (const std::string& name : regular_files(r.folder)) r.before[name] = fs::last_write_time(r.folder / name, ec);
  static bool registered = false;
  if (registered) return;
  registered = true;
  std::atexit([] {
    const RunOutputs& o = run_outputs();
    std::error_code ec;
    std::vector<std::string> ours;
    for (const std::string& name : regular_files(o.folder)) {
      const auto written = fs::last_write_time(o.folder / name, ec);
      const auto it = o.before.find(name);
      if (!ec && (it == o.before.end() || it->second != written)) ours.push_back(name);
    }
    if (ours.empty()) return;
    std::ofstream out(o.folder / manifest_name);
    for (const std::string& name : ours) out << name << "\n";
  });
}

}  // namespace mortar
