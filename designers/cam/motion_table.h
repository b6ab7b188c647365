// The user motion table law: normalised rows (x_i, S_i) — x the fraction of the segment's angle,
// strictly increasing from 0 to 1, S the fraction of the lift travelled, 0 at x = 0 and 1 at
// x = 1 — interpolated by a quintic B-spline with a simple knot at every row (C⁴ inside).
// Ends: `Rest` imposes S' = S'' = 0 at both ends (the complete quintic spline, a C² join with
// dwells and rest-to-rest laws); `Free` leaves them to the data (knots by averaging instead). The
// join with the neighbouring segments is whatever these ends give: CamProgram's continuity
// diagnostics (continuity.h) report every jump of s, v, a, j.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "src/nurbs/bspline.h"

namespace polarform {

enum class TableEnds { Rest, Free };

struct MotionTable {
  std::string file;       // as the project names it (relative to the project file)
  std::vector<double> x;  // fraction of the segment angle
  std::vector<double> s;  // fraction of the lift
  TableEnds ends = TableEnds::Rest;

  bool operator==(const MotionTable&) const = default;
};

// A quintic needs six conditions: six rows at least (input limit also bounds the sparse solve).
constexpr std::size_t kMinTableRows = 6;
constexpr std::size_t kMaxTableRows = 100000;

// The first rule a table breaks: row (0-based, rows count when there are too few or too many),
// the field ("x", "S" or "rows") and what was expected.
struct TableFault {
  std::size_t row = 0;
  std::string field;
  std::string expected;
};
std::optional<TableFault> motion_table_fault(const MotionTable& table);

// S on [0, 1] as a quintic B-spline through every row; throws InputError naming the table's file
// and row on a fault, or when rows so close that the interpolation is singular (the error measured
// at the rows exceeds 1e-9).
BSplineFunction interpolate_motion_table(const MotionTable& table);

}  // namespace polarform
