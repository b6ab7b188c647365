#include "ui/studio/guarded.h"

namespace polarform::studio {

std::string failure_text(std::string_view what, std::exception_ptr error) {
  std::string prefix(what);
  if (!prefix.empty()) prefix += ": ";
  try {
    std::rethrow_exception(error);
  } catch (const InputError& e) {
    return prefix + e.what();
  } catch (const NumericalError& e) {
    return prefix + "could not be computed: " + e.what();
  } catch (const std::bad_alloc&) {
    return prefix + "out of memory";
  } catch (const std::exception& e) {
    return prefix + e.what();
  } catch (...) {
    return prefix + "unknown error";
  }
}

}  // namespace polarform::studio
