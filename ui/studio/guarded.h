// The app's one rule for calling the libraries: a call that can throw (InputError for bad input,
// NumericalError for an unreachable goal, anything else for a bug or an I/O failure) runs inside
// guarded(), which turns the exception into a message in the log and lets the session go on.
#pragma once

#include <exception>
#include <string>
#include <string_view>

#include "src/error.h"
#include "ui/studio/message_log.h"

namespace polarform::studio {

// The exception's message prefixed with `what` ("Open project: …"). Non-std exceptions are named.
std::string failure_text(std::string_view what, std::exception_ptr error);

// Runs f(); on an exception logs "what: message" as an error and returns false.
template <class F>
bool guarded(MessageLog& log, std::string_view what, F&& f) {
  try {
    f();
    return true;
  } catch (...) {
    log.error(failure_text(what, std::current_exception()));
    return false;
  }
}

}  // namespace polarform::studio
