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

// Runs f() and returns its result; an InputError or NumericalError it throws is thrown again with
// "<source>: " before its message (unless it already starts so), so that every message about the
// data names the file it came from.
template <class F>
decltype(auto) naming_input(const std::string& source, F&& f) {
  const auto named = [&](const char* what) {
    const std::string m = what;
    return m.compare(0, source.size() + 1, source + ":") == 0 ? m : source + ": " + m;
  };
  try {
    return f();
  } catch (const InputError& e) {
    throw InputError(named(e.what()));
  } catch (const NumericalError& e) {
    throw NumericalError(named(e.what()));
  }
}

}  // namespace polarform
