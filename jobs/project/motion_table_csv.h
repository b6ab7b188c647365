// Reading a user motion table file (law="table" file="…"): comma-separated values under a header
// that names the columns — `x,S` (normalised: x the fraction of the segment angle from 0 to 1, S
// the fraction of the lift from 0 to 1) or `theta,s` (the cam angle in degrees and the follower
// displacement in the project's length unit; the first and last rows must be the segment's start
// and end angles and differ in s by its lift, and are normalised to x, S). '#' starts a comment,
// blank lines are skipped. Every error names the file, the line and the field; the parser reads
// only the bytes it is given (fuzzed: tests/fuzz/motion_table_fuzz.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "designers/cam/motion_table.h"

namespace polarform {

// What an absolute (theta, s) table is checked against.
struct TableSegment {
  double start = 0.0;  // rad
  double end = 0.0;    // rad
  double lift = 0.0;   // in the project's length unit
  bool rise = true;    // s climbs by the lift (a rise) or falls by it (a return)
};

// The largest table file read (input limit; 100000 rows take about 5 MB).
constexpr std::uintmax_t kMaxTableBytes = 64u << 20;

// `file` names the table in messages and is stored in the result's `file`.
MotionTable parse_motion_table(std::string_view text, const std::string& file,
                               const TableSegment& segment, TableEnds ends);

// Reads `name` relative to the folder of `project_file`; InputError naming the file when it is
// missing, not a regular file or larger than kMaxTableBytes. The result's `file` is `name`.
MotionTable read_motion_table(const std::string& project_file, const std::string& name,
                              const TableSegment& segment, TableEnds ends);

}  // namespace polarform
