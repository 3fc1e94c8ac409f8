// What every program says about its time: the timing keys of summary.json, and --profile.
#pragma once

#include <string>

#include "common/linalg/physical_limit.hpp"
#include "common/study/json_writer.hpp"

namespace mortar {

// time_s, limit_s, limit_ratio (minima of interleaved repetitions), time_spread and
// limit_spread ((max - min) / min), repeats, peak_memory_mb and limit_peak_memory_mb (the
// resident-set peak during the level and during its limit) and memory_ratio.
void add_timing(JsonObject& results, const TimedLevel& t);

// --profile: prints the phases of the level beside the limit's, and writes them to
// <out_dir>/profile.csv.
void report_profile(const TimedLevel& t, const std::string& out_dir);

}  // namespace mortar
