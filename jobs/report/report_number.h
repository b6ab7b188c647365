// Numbers as a report states them: rounded to 12 significant digits at the edge (report.json,
// the studio's report lines), so that 240° computed through radians reads 240 and not
// 239.99999999999997. Twelve digits keep every measured figure: an error of 1e-9 mm beside a
// 1000 mm part needs 13 orders but only 1 digit of its own.
#pragma once

#include <nlohmann/json.hpp>

namespace polarform {

// v rounded to 12 significant digits; 0, NaN and ±inf unchanged.
double report_number(double v);

// j with every floating-point number rounded by report_number.
nlohmann::ordered_json rounded_for_report(nlohmann::ordered_json j);

}  // namespace polarform
