// Open CASCADE as the peer converter: GeomAPI_PointsToBSpline fitted to dense samples of a contour,
// with the smallest curve that the caller's measurement verifies within the tolerance (the fit's
// Tol3D is tried from 2ε down, since OCCT checks its tolerance at the samples only). Only
// compiled with POLARFORM_HAVE_OCCT.
#pragma once

#include <Eigen/Core>
#include <GeomAPI_PointsToBSpline.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <functional>
#include <vector>

namespace polarform::exchange_test {

struct PeerFit {
  int control_points = 0;  // 0 when no tried Tol3D gave a verified curve
  double distance = 0.0;   // the caller's measured max distance, mm
  double tol3d = 0.0;      // the Tol3D that gave it
};

// The fewest poles of a verified GeomAPI_PointsToBSpline(points, deg_min, deg_max, C2, Tol3D)
// over Tol3D = ε·{2, 1.4, 1, 0.7, 0.5, 0.35, 0.25}; `distance` measures a curve against the
// exact contour.
inline PeerFit occt_points_to_bspline(
    const std::vector<Eigen::Vector2d>& points, int deg_min, int deg_max, double eps,
    const std::function<double(const Handle(Geom_BSplineCurve) &)>& distance) {
  TColgp_Array1OfPnt array(1, static_cast<int>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    array.SetValue(static_cast<int>(i) + 1, gp_Pnt(points[i].x(), points[i].y(), 0.0));
  for (double factor : {2.0, 1.4, 1.0, 0.7, 0.5, 0.35, 0.25}) {
    GeomAPI_PointsToBSpline fit(array, deg_min, deg_max, GeomAbs_C2, factor * eps);
    if (!fit.IsDone()) continue;
    const Handle(Geom_BSplineCurve) c = fit.Curve();
    const double d = distance(c);
    if (d <= eps) return {c->NbPoles(), d, factor * eps};
  }
  return {};
}

}  // namespace polarform::exchange_test
