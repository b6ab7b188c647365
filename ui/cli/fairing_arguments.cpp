#include "ui/cli/fairing_arguments.h"

#include "src/error.h"
#include "ui/cli/fit_arguments.h"

namespace polarform::cli {

std::optional<ProfileFairingOptions> fairing_options(const std::string& fair,
                                                     const std::string& fair_tol,
                                                     const std::string& fair_passes) {
  if (fair.empty()) {
    if (!fair_tol.empty() || !fair_passes.empty())
      throw InputError("--fair-tol and --fair-passes need --fair kjellander|farin");
    return std::nullopt;
  }
  ProfileFairingOptions f;
  f.method = parse_choice("--fair", fair, {"kjellander", "farin"}) == 0 ? FairingMethod::kjellander
                                                                        : FairingMethod::farin;
  if (!fair_tol.empty()) {
    f.tolerance = parse_numbers("--fair-tol", fair_tol, 1, 1)[0];
    if (!(f.tolerance > 0))
      throw InputError("--fair-tol '" + fair_tol + "': expected a positive number of mm");
  }
  if (!fair_passes.empty())
    f.max_passes = parse_int_pair("--fair-passes", fair_passes, 1, 100000).first;
  return f;
}

}  // namespace polarform::cli
