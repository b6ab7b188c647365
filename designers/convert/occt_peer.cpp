#include "designers/convert/occt_peer.h"

#include <GeomAPI_PointsToBSpline.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <cmath>
#include <optional>

#include "designers/convert/conversion_error.h"
#include "src/nurbs/knots.h"

namespace polarform {

namespace {

constexpr int kSamples = 1441;
constexpr double kTol3dLadder[] = {2.0, 1.4, 1.0, 0.7, 0.5, 0.35, 0.25};
constexpr int kMeasureSamples = 20000;

TColgp_Array1OfPnt contour_samples(const PolarFunction& R) {
  TColgp_Array1OfPnt points(1, kSamples);
  for (int k = 0; k < kSamples; ++k) {
    const double theta =
        k == kSamples - 1 ? R.end : R.start + (R.end - R.start) * k / (kSamples - 1);
    const double r = R(theta);
    points.SetValue(k + 1, gp_Pnt(r * std::cos(theta), r * std::sin(theta), 0.0));
  }
  return points;
}

// The OCCT curve as a NurbsCurve2d (poles, weights, flat knots), its parameter mapped linearly
// onto [R.start, R.end] so that it approximates the polar angle, as the measurement wants.
NurbsCurve2d to_nurbs(const Geom_BSplineCurve& g, const PolarFunction& R) {
  const TColStd_Array1OfReal& flat = g.KnotSequence();
  const double u0 = g.FirstParameter(), u1 = g.LastParameter();
  const double scale = (R.end - R.start) / (u1 - u0);
  Knots knots;
  for (int i = flat.Lower(); i <= flat.Upper(); ++i)
    knots.push_back(R.start + (flat(i) - u0) * scale);
  NurbsCurve2d::Points poles;
  std::vector<double> weights;
  for (int i = 1; i <= g.NbPoles(); ++i) {
    poles.emplace_back(g.Pole(i).X(), g.Pole(i).Y());
    if (g.IsRational()) weights.push_back(g.Weight(i));
  }
  return NurbsCurve2d(g.Degree(), std::move(knots), poles, weights);
}

// The fit at one Tol3D, or nothing if OCCT gives none.
std::optional<NurbsCurve2d> fit(const TColgp_Array1OfPnt& points, const PolarFunction& R,
                                int deg_min, int deg_max, double tol3d) {
  try {
    GeomAPI_PointsToBSpline approximation(points, deg_min, deg_max, GeomAbs_C2, tol3d);
    if (!approximation.IsDone()) return std::nullopt;
    return to_nurbs(*approximation.Curve(), R);
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
}

}  // namespace

// Peer baseline of issue 14: Open CASCADE GeomAPI_PointsToBSpline (AppDef least squares).
PeerCurve occt_points_to_bspline(const PolarFunction& R, int deg_min, int deg_max, double tol) {
  const TColgp_Array1OfPnt points = contour_samples(R);
  for (double factor : kTol3dLadder) {
    std::optional<NurbsCurve2d> c = fit(points, R, deg_min, deg_max, factor * tol);
    if (!c) continue;
    // Measured densely (OCCT places its knots for its samples, not for the error between them):
    // 20000 points over the curve, at least samples_per_span in each span, maxima refined.
    const double error = profile_error(*c, R, c->front(), c->back(), kMeasureSamples).max_radial;
    if (error <= tol) return {true, c->size(), c->degree(), error, factor * tol, std::move(*c)};
  }
  return {};
}

}  // namespace polarform
