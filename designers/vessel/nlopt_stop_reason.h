// NLopt's reasons for stopping a converged run, in the words the vessel reports use; the callers
// decide what an evaluation limit or a failure code means for them.
#pragma once

#include <nlopt.hpp>

namespace polarform {

// "success", "objective tolerance reached", "step tolerance reached", "round-off limited", or
// nullptr for any other result (an evaluation limit, a failure).
const char* nlopt_stop_reason(nlopt::result result);

}  // namespace polarform
