#include "src/nurbs/pipe_self_intersection.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "src/error.h"
#include "src/nurbs/double_normals.h"
#include "src/nurbs/end_circle_contacts.h"
#include "src/nurbs/pipe_surface.h"
#include "src/nurbs/spine_table.h"

namespace polarform {

// MIT 13.472J §8.4, the theorem after (8.46): δ = min{1/κ_max, r_ee, r_bb, r_eb}.
PipeBounds pipe_bounds(const NurbsCurve3d& spine, bool closed) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const SpineTable table(spine, 256);
  if (closed &&
      !((spine.point(spine.front()) - spine.point(spine.back())).norm() <= 1e-9 * table.extent()))
    throw InputError(
        "pipe spine: marked closed but its ends are " +
        std::to_string((spine.point(spine.front()) - spine.point(spine.back())).norm()) +
        " apart, expected them to coincide");
  PipeBounds out;
  // Lead: switch to max_curvature (pipe_surface.h, exact, spec M7) at merge; this scan stands in.
  const SpineCurvature kappa = max_curvature(spine);
  // A curvature at rounding level (κ·extent < 1e-10) is a straight spine.
  const bool straight = !(kappa.kappa_max * table.extent() >= 1e-10);
  out.local = straight ? inf : 1.0 / kappa.kappa_max;
  // Feet closer than π/(2κ_max) are left out of the global modes: no contact there can come
  // before the local bound (double_normals.cpp, end_circle_contacts.cpp).
  const double separation = straight ? inf : std::numbers::pi / 2.0 * out.local;
  const DoubleNormal bb = shortest_double_normal(table, closed, separation);
  out.body_body = 0.5 * bb.length;
  const EndContact ee = closed ? EndContact{inf, 0.0, 0.0} : end_end_contact(spine);
  const EndContact eb = closed ? EndContact{inf, 0.0, 0.0} : end_body_contact(table, separation);
  out.end_end = ee.radius;
  out.end_body = eb.radius;
  // The theorem's order decides ties: a later mode limits only when smaller by more than 1e-10
  // relative (the modes of a circle-arc spine all equal its radius up to rounding).
  out.delta = out.local;
  out.limiting_mode = "local";
  out.t1 = out.t2 = kappa.t_at;
  const auto consider = [&](double r, const char* mode, double t1, double t2) {
    if (r < out.delta * (1.0 - 1e-10))
      out.delta = r, out.limiting_mode = mode, out.t1 = t1, out.t2 = t2;
  };
  consider(out.end_end, "end-end", ee.t_end, ee.t_other);
  consider(out.body_body, "body-body", bb.t1, bb.t2);
  consider(out.end_body, "end-body", eb.t_end, eb.t_other);
  return out;
}

}  // namespace polarform
