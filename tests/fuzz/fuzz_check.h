// What every harness requires of a parser: it returns a valid result or throws the documented
// InputError; anything else (another exception, a broken invariant) is a finding. A finding
// aborts, so libFuzzer saves the input and the replay test fails.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "src/error.h"

namespace polarform::fuzz {

// Reports a broken invariant and aborts.
[[noreturn]] inline void finding(const char* what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what);
  std::abort();
}

inline void require(bool condition, const char* what) {
  if (!condition) finding(what);
}

// Runs parse(); an InputError is the documented refusal and ends the input quietly. Returns
// whether parse() succeeded.
template <class F>
bool accepted(F&& parse) {
  try {
    parse();
    return true;
  } catch (const InputError&) {
    return false;
  }
}

inline std::string_view bytes_of(const unsigned char* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace polarform::fuzz
