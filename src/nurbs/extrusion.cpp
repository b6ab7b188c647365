// The translational sweep of a curve along a straight direction (Kantz 2003, (3.10)–(3.11)).
#include "src/nurbs/extrusion.h"

#include <cmath>
#include <string>

#include "src/error.h"

namespace polarform {

// Kantz 2003, eq. (3.11) with the linear trajectory T(v) = v·d (NURBS Book §8.3).
NurbsSurface extrude(const NurbsCurve3d& curve, const Eigen::Vector3d& d, double v0, double v1) {
  if (!(std::isfinite(v0) && std::isfinite(v1) && v0 < v1))
    throw InputError("extrusion range [" + std::to_string(v0) + ", " + std::to_string(v1) +
                     "]: expected finite v0 < v1");
  if (!d.allFinite() || !(d.norm() > 0.0))
    throw InputError("extrusion direction: expected a finite, non-zero vector");
  NurbsSurface::Points points;
  std::vector<double> weights;
  for (int i = 0; i < curve.size(); ++i)
    for (double v : {v0, v1}) {
      points.push_back(curve.control_point(i) + v * d);
      weights.push_back(curve.weight(i));
    }
  return NurbsSurface(curve.degree(), 1, curve.knots(), {v0, v0, v1, v1}, points, weights);
}

}  // namespace polarform
