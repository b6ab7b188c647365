#include "jobs/report/report_number.h"

#include <charconv>
#include <cmath>

namespace polarform {

double report_number(double v) {
  if (v == 0.0 || !std::isfinite(v)) return v;
  char text[32];
  // Scientific with 11 decimals: 12 significant digits, independent of the C locale.
  const auto written =
      std::to_chars(text, text + sizeof text, v, std::chars_format::scientific, 11);
  double rounded = v;
  std::from_chars(text, written.ptr, rounded);
  return rounded;
}

nlohmann::ordered_json rounded_for_report(nlohmann::ordered_json j) {
  if (j.is_number_float()) return report_number(j.get<double>());
  if (j.is_structured())
    for (auto& child : j) child = rounded_for_report(std::move(child));
  return j;
}

}  // namespace polarform
