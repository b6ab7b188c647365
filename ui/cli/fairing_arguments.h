// The fairing options `fit` and `scan-cam` share: --fair kjellander|farin, --fair-tol MM and
// --fair-passes N (MIT 13.472J §8.2.3), parsed into the fairing asked for.
#pragma once

#include <optional>
#include <string>

#include "src/fit/profile_fairing.h"

namespace polarform::cli {

// None without --fair; InputError for a bad value, or --fair-tol / --fair-passes without --fair.
std::optional<ProfileFairingOptions> fairing_options(const std::string& fair,
                                                     const std::string& fair_tol,
                                                     const std::string& fair_passes);

}  // namespace polarform::cli
