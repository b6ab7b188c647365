#include "src/nurbs/degree_elevation.h"

#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/periodic.h"
#include "src/nurbs/symbolic_product.h"

namespace polarform {

// NURBS Book §5.5: the Bezier elevation (5.36) is the Bezier product (Bae 2002, eq. (A.11)) with
// the constant 1 of degree t, so c times that constant is c elevated, on the knots (A.7): c's + t.
BSpline elevate_degree(const BSpline& c, int t) {
  if (t < 0) throw InputError("elevate_degree: t is " + std::to_string(t) + ", expected >= 0");
  const int p = c.degree();
  if (p + t > kMaxDegree)
    throw InputError("elevate_degree: degree " + std::to_string(p) + " + " + std::to_string(t) +
                     " exceeds " + std::to_string(kMaxDegree));
  for (const Breakpoint& b : breakpoints(c.knots()))
    if (b.value > c.front() && b.value < c.back() && b.multiplicity > p)
      throw InputError("elevate_degree: interior knot " + to_text(b.value) + " has multiplicity " +
                       std::to_string(b.multiplicity) + " > degree " + std::to_string(p) +
                       " (a discontinuity)");
  if (t == 0) return clip(c, c.front(), c.back());
  const BSpline one(t, clamped_knots(t, c.front(), c.back()), Eigen::MatrixXd::Ones(1, t + 1));
  return product(one, c);
}

BSplineSurface elevate_degree_u(const BSplineSurface& s, int t) {
  return BSplineSurface::from_along_u(elevate_degree(s.along_u(), t), s.degree_v(), s.knots_v(),
                                      s.dim());
}

BSplineSurface elevate_degree_v(const BSplineSurface& s, int t) {
  return BSplineSurface::from_along_v(elevate_degree(s.along_v(), t), s.degree_u(), s.knots_u(),
                                      s.dim());
}

}  // namespace polarform
