// polarform's error type: bad input (a malformed knot vector, a broken file, an infeasible design)
// raises InputError with a message that names the field, file or line and what was expected.
#pragma once

#include <stdexcept>
#include <string>

namespace polarform {

class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A numerical procedure that could not reach its goal (no convergence, tolerance unreachable).
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace polarform
