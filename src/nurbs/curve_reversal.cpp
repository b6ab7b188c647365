#include "src/nurbs/curve_reversal.h"

namespace polarform {

BSpline reversed(const BSpline& h) {
  Knots k(h.knots().rbegin(), h.knots().rend());
  const double sum = h.front() + h.back();
  for (double& x : k) x = sum - x;
  return BSpline(h.degree(), std::move(k), h.coefs().rowwise().reverse());
}

NurbsCurve2d reversed(const NurbsCurve2d& curve) {
  return NurbsCurve2d(reversed(curve.homogeneous()));
}

NurbsCurve3d reversed(const NurbsCurve3d& curve) {
  return NurbsCurve3d(reversed(curve.homogeneous()));
}

}  // namespace polarform
