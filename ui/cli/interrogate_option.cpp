#include "ui/cli/interrogate_option.h"

#include "ui/cli/fit_arguments.h"

namespace polarform::cli {

void add_interrogate_option(CLI::App& command, std::string& value) {
  command
      .add_option("--interrogate", value,
                  "[gauss|mean|absolute]: write curvature.x3d/.ply (the surface coloured by that "
                  "curvature, default gauss) and reflection.x3d")
      ->expected(0, 1);
}

std::optional<CurvatureQuantity> interrogate_option(const std::string& value) {
  if (value.empty()) return std::nullopt;
  if (value == "true") return CurvatureQuantity::gaussian;  // CLI11's value of a bare option
  constexpr CurvatureQuantity q[] = {CurvatureQuantity::gaussian, CurvatureQuantity::mean,
                                     CurvatureQuantity::absolute};
  return q[parse_choice("--interrogate", value, {"gauss", "mean", "absolute"})];
}

}  // namespace polarform::cli
