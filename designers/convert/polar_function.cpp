#include "designers/convert/polar_function.h"

#include <cmath>
#include <numbers>

namespace polarform {

bool PolarFunction::closed() const {
  return std::abs((end - start) - 2 * std::numbers::pi) <= 1e-12;
}

}  // namespace polarform
