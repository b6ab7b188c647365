#include "designers/cam/base_radius.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

// Bracketing by doubling, then bisection on feasibility (Norton, Cam Design and Manufacturing Handbook, sizes Rb the
// same way by hand).
BaseRadiusResult minimum_base_radius(const CamProgram& program, const Follower& follower, Rotation rotation,
                                     const BaseRadiusRequirements& req, std::span<const double> thetas) {
  if (is_oscillating(follower.kind))
    throw InputError(
        "minimum base radius: translating followers only (an oscillating arm's reach bounds Rb "
        "from above; adjust Rb, the pivot and the arm together)");
  const bool flat = follower.kind == FollowerKind::FlatFaced;
  if (!flat && !(req.max_pressure_angle > 0 && req.max_pressure_angle < std::numbers::pi / 2))
    throw InputError("minimum base radius: max_pressure_angle must be in (0°, 90°)");
  if (!(req.min_convex_radius >= 0) || !std::isfinite(req.min_convex_radius))
    throw InputError("minimum base radius: min_convex_radius must be >= 0 mm");

  BaseRadiusResult result;
  const auto feasible = [&](double rb, BaseRadiusResult* out) {
    const CamAnalysis a = analyse(PlateCam(program, follower, rb, rotation), thetas);
    ++result.analyses;
    const bool ok = (flat || a.max_pressure_angle.value <= req.max_pressure_angle) && a.min_contour_speed.value > 0 &&
                    a.min_convex_contour_radius.value >= req.min_convex_radius;
    if (ok && out) {
      out->base_radius = rb;
      out->max_pressure_angle = a.max_pressure_angle;
      out->min_convex_contour_radius = a.min_convex_contour_radius;
      out->min_contour_speed = a.min_contour_speed.value;
    }
    return ok;
  };

  // Below `lo` the follower does not fit (|e| >= Rp) or Rb <= 0.
  double lo = flat ? 0.0
                   : std::max(0.0, std::abs(follower.offset) -
                                       (has_roller(follower.kind) ? follower.roller_radius : 0.0));
  const double scale = std::max({program.stroke(), std::abs(follower.offset), follower.roller_radius, 1.0});
  double hi = std::max(2 * lo, scale);
  while (!feasible(hi, &result)) {
    lo = hi;
    hi *= 2;
    if (hi > 1e6 * scale)
      throw NumericalError("minimum base radius: no base radius up to " + number_text(hi) +
                           " mm meets the requirements");
  }
  while (hi - lo > 1e-9 * hi) {
    const double mid = 0.5 * (lo + hi);
    (feasible(mid, &result) ? hi : lo) = mid;
  }
  return result;
}

}  // namespace polarform
