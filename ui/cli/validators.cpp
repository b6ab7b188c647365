#include "ui/cli/validators.h"

#include <charconv>
#include <cmath>
#include <optional>

#include "jobs/project/cam_project.h"
#include "src/number_text.h"

namespace polarform::cli {

namespace {

std::optional<double> finite_number(const std::string& text) {
  double x = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, x);
  if (ec != std::errc() || ptr != end || text.empty() || !std::isfinite(x)) return std::nullopt;
  return x;
}

}  // namespace

CLI::Validator positive_mm() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto x = finite_number(text);
        return x && *x > 0 ? "" : "expected a length > 0 in mm, got '" + text + "'";
      },
      "MM > 0");
}

CLI::Validator tolerance_mm() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto x = finite_number(text);
        if (x && *x >= kMinTolerance) return "";
        return "expected a tolerance >= " + format_round_trip(kMinTolerance) + " mm, got '" + text +
               "'";
      },
      "MM >= " + format_round_trip(kMinTolerance));
}

}  // namespace polarform::cli
