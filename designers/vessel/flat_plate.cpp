#include "designers/vessel/flat_plate.h"

#include <cmath>
#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"

namespace polarform {

namespace {

void require_positive(double value, const char* name, const char* unit) {
  if (!(value > 0.0 && std::isfinite(value)))
    throw InputError(std::string("flat plate: ") + name + " " + to_text(value) + " " + unit +
                     ", expected > 0");
}

}  // namespace

FlatPlateBending flat_plate_bending(double plate_radius, double thickness, double pressure,
                                    double poisson) {
  require_positive(plate_radius, "radius a", "mm");
  require_positive(thickness, "thickness t", "mm");
  require_positive(pressure, "pressure p", "MPa");
  if (!(poisson >= 0.0 && poisson < 0.5))
    throw InputError("flat plate: Poisson's ratio " + to_text(poisson) + ", expected in [0, 0.5)");
  const double a2 = plate_radius * plate_radius, t2 = thickness * thickness, nu = poisson;
  FlatPlateBending out;
  out.plate_radius = plate_radius;
  out.simply_supported_centre = 3 * (3 + nu) * pressure * a2 / (8 * t2);
  out.clamped_edge = 3 * pressure * a2 / (4 * t2);
  out.clamped_centre = 3 * (1 + nu) * pressure * a2 / (8 * t2);
  return out;
}

}  // namespace polarform
