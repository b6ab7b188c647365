#include "src/base/arc_curves.h"

#include <cmath>
#include <numbers>
#include <string>

#include "src/error.h"

namespace polarform {

Eigen::MatrixXd arc_homogeneous_points(ArcKind kind, double start, double end, double alpha) {
  const double sweep = end - start;
  const bool rqb = kind == ArcKind::rqb;
  if (!std::isfinite(start) || !std::isfinite(end) || !(sweep > 0.0) ||
      (rqb ? sweep >= std::numbers::pi : sweep > std::numbers::pi + 2.0 * kAngleSlack))
    throw InputError("arc sweep " + std::to_string(sweep) + ": expected 0 < sweep " +
                     (rqb ? "< pi for an RQB arc" : "<= pi for a quartic arc"));
  const double phi = sweep / 2.0, mid = start + phi, w = std::cos(phi);
  const Eigen::Vector2d b0(std::cos(start), std::sin(start)), b2(std::cos(end), std::sin(end));
  const Eigen::Vector2d wb1(std::cos(mid), std::sin(mid));  // w·b1, finite for every sweep
  if (rqb) {
    // Bae 2002, eq. (2.4): weights 1, cos φ, 1.
    Eigen::MatrixXd h(3, 3);
    h.col(0) << b0, 1.0;
    h.col(1) << wb1, w;
    h.col(2) << b2, 1.0;
    return h;
  }
  if (!(alpha > 0.0 && std::isfinite(alpha)))
    throw InputError("quartic arc alpha " + std::to_string(alpha) + ": expected a finite alpha > 0");
  // Bae 2002, eq. (5.2), each point multiplied by its weight.
  const double a2 = alpha * alpha;
  Eigen::MatrixXd h(3, 5);
  h.col(0) << b0, 1.0;
  h.col(1) << alpha / 2.0 * (b0 + wb1), (1.0 + w) * alpha / 2.0;
  h.col(2) << (a2 * (b0 + b2) + 2.0 * (1.0 + a2) * wb1) / 6.0, (a2 + a2 * w + w) / 3.0;
  h.col(3) << alpha / 2.0 * (b2 + wb1), (1.0 + w) * alpha / 2.0;
  h.col(4) << b2, 1.0;
  return h;
}

namespace {

NurbsCurve2d bezier_arc(ArcKind kind, double start, double sweep, double alpha) {
  Eigen::MatrixXd h = arc_homogeneous_points(kind, start, start + sweep, alpha);
  const int degree = static_cast<int>(h.cols()) - 1;
  return NurbsCurve2d(BSpline(degree, clamped_knots(degree, 0.0, 1.0), std::move(h)));
}

}  // namespace

NurbsCurve2d rqb_arc(double start, double sweep) { return bezier_arc(ArcKind::rqb, start, sweep, 1.0); }

NurbsCurve2d quartic_arc(double start, double sweep, double alpha) {
  return bezier_arc(ArcKind::quartic, start, sweep, alpha);
}

}  // namespace polarform
