// The polar-function converter (Bae 2002, §5.1, improved): R(θ) → F(u) as a B-spline → a base
// circle of unequal quasi-uniform quartic (or RQB) arcs chosen so that the MEASURED radial error
// of C(u) = F(u)·B̃(u) meets the tolerance → one NURBS curve of degree deg F + 4 (or + 2), with
// the measurements that prove it; then made compact within the tolerance: refitted by a
// least-squares B-spline with knots by need (degree_limited.h) where that has fewer control
// points, or else the knots the remaining error budget allows removed (NURBS Book A5.8, each
// removal measured).
#pragma once

#include <string>
#include <vector>

#include "designers/convert/polar_function.h"
#include "src/base/base_circle.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

// The tightest conversion tolerance a project may ask for, mm. Below it double-precision evaluation
// of a profile of ordinary size (radii up to metres) cannot verify the error, and the converter
// would refine without end.
inline constexpr double kMinTolerance = 1e-9;

// How the conversion makes the product C = F·B compact within the tolerance: not at all (C is
// exactly F·B, e.g. when F and B are used apart, as for a cylindrical cam's track); by removing
// the knots of C but those at R's breakpoints (which stay exact arc junctions); by removing any
// knot; by a refit — the least-squares B-spline of degree 3 to 6 with knots by need and the
// fewest control points (degree_limited.h; periodic when R is closed; when R is open, fitted
// piece by piece between R's breakpoints with R's end points and end tangents and joined there,
// the piece across a mirror-symmetric R's middle as its own mirror image),
// measured against R, replacing C when it has fewer control points than C (any knot removed
// otherwise).
enum class Compaction { none, between_breakpoints, full, refit };

struct ConversionOptions {
  double tolerance = 1e-3;  // mm: bound on the measured max radial error of the result
  ArcKind base = ArcKind::quartic;
  AlphaRule alpha = AlphaRule::minimax;
  // Share of the tolerance for representing R as a B-spline (the rest is the arcs' budget).
  double function_share = 0.9;
  Compaction compaction = Compaction::refit;

  bool operator==(const ConversionOptions&) const = default;
};

struct ArcSummary {
  double start = 0.0, sweep = 0.0;  // rad
  double max_radial_error = 0.0;    // mm, measured on the final curve
};

// The control points after each step of the conversion, in order: "product", then "refit" or
// "knot removal".
struct ConversionStep {
  std::string name;
  int control_points = 0;
  double max_radial_error = 0.0;  // mm, measured after the step

  bool operator==(const ConversionStep&) const = default;
};

struct PolarConversion {
  NurbsCurve2d curve;
  BaseCircle base;
  // F(u), R as a B-spline in the base circle's parameter u ≈ θ (the curve's parameter too: a refit
  // is parametrized by the polar angle within a small slide).
  BSplineFunction function;
  std::vector<ArcSummary> arcs;
  double tolerance = 0.0;
  // Measured on the final curve against the exact R:
  double max_radial_error = 0.0;
  double max_normal_error = 0.0;
  double worst_angle = 0.0;  // polar angle of the max radial error, rad
  double max_tangent_jump = 0.0;  // rad, between one-sided tangents at arc junctions (G1 check)
  // The error budget split: R → F (0 when F is exact) and the arcs' synchronization.
  double function_error = 0.0;
  bool function_exact = false;
  double synchronization_error = 0.0;
  std::vector<ConversionStep> steps;
};

PolarConversion convert_polar_function(const PolarFunction& R, const ConversionOptions& options);

}  // namespace polarform
