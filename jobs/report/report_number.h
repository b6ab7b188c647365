// Numbers as a report states them: rounded to 12 significant digits at the edge (report.json,
// the studio's report lines), so that 240° computed through radians reads 240 and not
// 239.99999999999997. The rounding is relative: a value changes by at most 5e-13 of itself, far
// below any measured error (an error of 1e-9 mm keeps 12 digits of its own).
#pragma once

#include <nlohmann/json.hpp>

namespace polarform {

// v rounded to 12 significant digits; 0, NaN and ±inf unchanged.
double report_number(double v);

// j with every floating-point number rounded by report_number.
nlohmann::ordered_json rounded_for_report(nlohmann::ordered_json j);

}  // namespace polarform
