#include "ui/cli/interrogate_option.h"

#include "ui/cli/fit_arguments.h"

namespace polarform::cli {

void add_interrogate_option(CLI::App& command, std::string& value) {
  command
      .add_option(
          "--interrogate", value,
          "[gauss|mean|absolute]: write curvature.x3d/.ply (the surface coloured by that "
          "curvature, default gauss) and reflection.x3d; after SCAN, or as --interrogate=mean")
      ->expected(0, 1)
      ->default_str("gauss");  // what a bare --interrogate gives
}

std::optional<CurvatureQuantity> interrogate_option(const std::string& value) {
  if (value.empty()) return std::nullopt;
  constexpr CurvatureQuantity q[] = {CurvatureQuantity::gaussian, CurvatureQuantity::mean,
                                     CurvatureQuantity::absolute};
  return q[parse_choice("--interrogate", value, {"gauss", "mean", "absolute"})];
}

}  // namespace polarform::cli
