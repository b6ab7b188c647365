#include "designers/vessel/nlopt_stop_reason.h"

namespace polarform {

const char* nlopt_stop_reason(nlopt::result result) {
  switch (result) {
    case nlopt::SUCCESS:
      return "success";
    case nlopt::FTOL_REACHED:
      return "objective tolerance reached";
    case nlopt::XTOL_REACHED:
      return "step tolerance reached";
    case nlopt::ROUNDOFF_LIMITED:
      return "round-off limited";
    default:
      return nullptr;
  }
}

}  // namespace polarform
