// Polar NURBS-curve fitting (Bae 2002, ch. 2): 2D points → polar coordinates about a centre (given,
// or by an algebraic circle fit) → a base circle of RQB (or quartic) arcs over the data's angle
// range → parameter synchronization (2.7)-(2.8) → a single-valued B-spline r = F(u) of degree p →
// C(u) = F(u)·B(u) by the symbolic product (2.10). Full-circle data gives a closed fit (periodic F,
// §3.3.1, clipped). Data that rays from the centre cross more than once is refused, naming the
// loops or the angle ranges, instead of being fitted; outliers are refused or left out.
#pragma once

#include <Eigen/Core>
#include <numbers>
#include <optional>
#include <string>

#include "src/base/base_circle.h"
#include "src/fit/fit_report.h"
#include "src/fit/function_fit.h"
#include "src/fit/local_frame.h"
#include "src/fit/model_choice.h"
#include "src/fit/orthogonal_coordinates.h"
#include "src/fit/outliers.h"
#include "src/fit/single_valued_check.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

struct PolarFitOptions {
  // F along v: degree_v = p (default 3), size_v / tolerance / fairness / threads / progress as in
  // FunctionFitOptions; the u fields are ignored (a curve is a 1 x n function).
  FunctionFitOptions function;
  ModelChoiceOptions model;  // net by GCV unless given; F(u) alone when θ adds nothing
  std::optional<Eigen::Vector2d> centre;
  ArcKind base_kind = ArcKind::rqb;
  AlphaRule alpha_rule = AlphaRule::minimax;
  double max_sweep = std::numbers::pi / 2;  // the square-based base circle
  Closure closure = Closure::automatic;
  double closed_gap = 0.0;  // largest angular gap (rad) still called closed; <= 0: automatic
  bool check_single_valued = true;
  OutlierPolicy outliers = OutlierPolicy::refuse;
};

struct PolarCurveFit {
  NurbsCurve2d curve;    // C(u) + centre, in the input coordinates
  BSplineFunction F;     // r = F(u) on the base circle's parameters
  BaseCircle base;
  Eigen::Vector2d centre;
  std::string centre_reason;
  bool closed = false;
  SingleValuedness check;
  FitReport report;
};

// Throws InputError for bad input or data that is not single-valued about the centre: two or more
// loops (a bore, a hole) are named with their radii, a few outliers (under refuse) with their
// count, else the message lists the angle ranges in degrees; NumericalError when the fit cannot
// reach its tolerance.
PolarCurveFit fit_polar_curve(const Eigen::Matrix2Xd& points, const PolarFitOptions& options = {});

// C(u) = F(u)·B(u) + centre (Bae 2002, eq. (2.10)), exactly by the symbolic product.
NurbsCurve2d polar_product_curve(const BSplineFunction& F, const BaseCircle& base,
                                 const Eigen::Vector2d& centre);

// A planar slice of a 3D cloud: the points within thickness/2 of the plane through `origin` with
// normal `normal`, in the plane's coordinates (x along `x_direction` made orthogonal to normal).
struct PlanarSlice {
  Eigen::Matrix2Xd points;
  LocalFrame plane;  // i = x direction, j, k = normal
};
PlanarSlice slice_points(const Eigen::Matrix3Xd& points, const Eigen::Vector3d& origin,
                         const Eigen::Vector3d& normal, const Eigen::Vector3d& x_direction,
                         double thickness);

// The fitted slice curve placed back in 3D.
NurbsCurve3d curve_in_space(const NurbsCurve2d& curve, const LocalFrame& plane);

}  // namespace polarform
