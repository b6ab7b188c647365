#include "designers/convert/occt_peer.h"

#include <GeomAPI_PointsToBSpline.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <optional>

#include "src/nurbs/knots.h"

namespace polarform {

namespace {

TColgp_Array1OfPnt contour_samples(const PolarFunction& R) {
  const std::vector<Eigen::Vector2d> samples = peer_contour_samples(R);
  TColgp_Array1OfPnt points(1, static_cast<int>(samples.size()));
  for (std::size_t k = 0; k < samples.size(); ++k)
    points.SetValue(static_cast<int>(k) + 1, gp_Pnt(samples[k].x(), samples[k].y(), 0.0));
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
  return verified_on_ladder(R, tol,
                            [&](double tol3d) { return fit(points, R, deg_min, deg_max, tol3d); });
}

}  // namespace polarform
