// The polar-function converter (Bae 2002, §5.1, improved): R(θ) → F(u) as a B-spline → a base
// circle of unequal quasi-uniform quartic (or RQB) arcs chosen so that the MEASURED radial error
// of C(u) = F(u)·B̃(u) meets the tolerance → one NURBS curve of degree deg F + 4 (or + 2), with
// the measurements that prove it.
#pragma once

#include <vector>

#include "designers/convert/polar_function.h"
#include "src/base/base_circle.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

// The tightest conversion tolerance a project may ask for, mm. Below it double-precision evaluation
// of a profile of ordinary size (radii up to metres) cannot verify the error, and the converter
// would refine without end.
inline constexpr double kMinTolerance = 1e-9;

struct ConversionOptions {
  double tolerance = 1e-3;  // mm: bound on the measured max radial error of the result
  ArcKind base = ArcKind::quartic;
  AlphaRule alpha = AlphaRule::minimax;
  // Share of the tolerance for representing R as a B-spline (the rest is the arcs' budget).
  double function_share = 0.9;

  bool operator==(const ConversionOptions&) const = default;
};

struct ArcSummary {
  double start = 0.0, sweep = 0.0;  // rad
  double max_radial_error = 0.0;    // mm, measured on the final curve
};

struct PolarConversion {
  NurbsCurve2d curve;
  BaseCircle base;
  BSplineFunction function;  // F(u), R as a B-spline in the base circle's parameter (u ≈ θ)
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
};

PolarConversion convert_polar_function(const PolarFunction& R, const ConversionOptions& options);

}  // namespace polarform
