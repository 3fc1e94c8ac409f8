#include "common/study/timing_report.hpp"

#include <cstdio>

namespace mortar {

void add_timing(JsonObject& results, const TimedLevel& t) {
  constexpr double megabyte = 1e6;
  results.set("time_s", t.time_s)
      .set("limit_s", t.limit_s)
      .set("limit_ratio", t.ratio())
      .set("time_spread", t.time_spread)
      .set("limit_spread", t.limit_spread)
      .set("repeats", t.repeats)
      .set("peak_memory_mb", t.peak_bytes / megabyte)
      .set("limit_peak_memory_mb", t.limit_peak_bytes / megabyte)
      .set("memory_ratio", t.limit_peak_bytes > 0 ? t.peak_bytes / t.limit_peak_bytes : 0.0);
}

void report_profile(const TimedLevel& t, const std::string& out_dir) {
  std::printf("\nwhere the finest level's time goes (seconds, the fastest of %d runs of each;\n"
              "spread %.0f%% for the level, %.0f%% for the limit):\n%s",
              t.repeats, 100 * t.time_spread, 100 * t.limit_spread,
              format_profile({t.profile, t.limit_profile}).c_str());
  write_profile_csv(out_dir + "/profile.csv", {t.profile, t.limit_profile});
}

}  // namespace mortar
