// Checks for numeric CLI options with messages a user can act on (CLI11's own range checks print
// the whole range of a double): positive lengths in mm and conversion tolerances in mm.
#pragma once

#include <CLI/CLI.hpp>

namespace polarform::cli {

// A finite number > 0 (a length in mm).
CLI::Validator positive_mm();

// A conversion tolerance in mm: a finite number >= kMinTolerance
// (designers/convert/polar_conversion.h).
CLI::Validator tolerance_mm();

}  // namespace polarform::cli
