// Least-squares fitting of a single-valued tensor-product B-spline function F(u, v) (a curve F(v)
// is the 1 x n case) to scattered samples: knots placed from the data, sparse normal equations,
// fairness regularisation, periodicity (Bae 2002, eqs. (3.9)-(3.10)) and pole conditions (3.14) by
// elimination, clipping of closed fits (§3.3.1), adaptive knot refinement until a measured error
// meets a tolerance, and reduction to degree 0 along a direction in which F is constant.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

#include "src/fit/error_stats.h"
#include "src/fit/knot_placement.h"
#include "src/fit/parallel.h"
#include "src/fit/regularised_solve.h"
#include "src/fit/samples.h"
#include "src/fit/stage_times.h"
#include "src/nurbs/bspline_surface.h"

namespace polarform {

// The statistic of |error| a tolerance applies to.
enum class ToleranceMeasure { max, p99, p95, rms };

// The most coefficients F may have (size_u · size_v, given or refined to): the sparse solve and
// the NURBS outputs stay within about a GB and half a minute (input limit, checked before any
// allocation; measured: 200 x 200 takes 0.3 GB, 300 x 300 0.6 GB and 28 s with every output).
constexpr long kMaxFitCoefficients = 65536;

struct FunctionFitOptions {
  int degree_u = 3, degree_v = 3;
  // Control net (coefficients per direction; for a periodic v the distinct ones, i.e. the spans).
  // 0 means: refine adaptively to `tolerance` if it is > 0, else 12.
  int size_u = 0, size_v = 0;
  double tolerance = 0.0;
  ToleranceMeasure measure = ToleranceMeasure::max;
  int max_size_u = 120, max_size_v = 120;  // refinement limits
  KnotPlacement placement = KnotPlacement::uniform;
  FairnessOptions fairness;
  // Replace a direction by degree 0 when every row (column) of coefficients is constant within
  // constant_tolerance · max|f| (a true circle, sphere, cylinder or surface of revolution).
  bool reduce_constant = true;
  double constant_tolerance = 1e-9;
  int threads = 2;
  ProgressFn progress;
};

// Throws InputError "<what> n x m: N coefficients, above the limit …" when size_u · size_v exceeds
// kMaxFitCoefficients.
void check_control_net_size(int size_u, int size_v, const std::string& what);

// The domain and the structure the caller imposes on F.
struct FunctionSpace {
  double u0 = 0.0, u1 = 1.0, v0 = 0.0, v1 = 1.0;
  bool periodic_v = false;                   // closed in v (3.9)-(3.10), then clipped to [v0, v1]
  bool symmetric_v = false;                  // v breaks repeat after half the period (3.15)
  int pole_start = 0, pole_end = 0;  // rows tied at u0 / u1: 1 = G0 (3.14a), 2 = G1 (3.14)
  // Equal base arcs along u / v: the synchronized parameter (2.7) is only C0 in the angle at their
  // joints, so a chosen net keeps its uniform spans a multiple of them (net_selection.h).
  int arcs_u = 1, arcs_v = 1;
};

// A single-valued curve F(u) fitted to samples (u_k, g_k) on [u0, u1], periodic when asked: the
// 1 x n case of fit_function (degree_v, size_v and max_size_v of the options apply).
struct CurveFunctionFit {
  BSplineFunction F;
  int size = 0;
  double lambda = 0.0;
  Eigen::VectorXd errors;  // F(u_k) − g_k
  ErrorStats stats;
  int refinements = 0;
  StageTimes times;
};
CurveFunctionFit fit_curve_function(const Eigen::VectorXd& u, const Eigen::VectorXd& values, double u0,
                                    double u1, bool periodic, const FunctionFitOptions& options = {});

struct FunctionFitResult {
  BSplineSurface F;         // scalar, clamped on [u0, u1] x [v0, v1]
  int size_u = 0, size_v = 0;       // the fitted net (before any reduction to degree 0)
  bool reduced_u = false, reduced_v = false;
  double lambda = 0.0;
  double dof = -1.0;        // effective parameters (gcv mode only)
  Eigen::VectorXd errors;   // the measure's per-sample errors for F
  ErrorStats stats;
  int refinements = 0;
  StageTimes times;         // knots, assembly, solve, product (clipping), error
};

// Per-sample signed errors of a candidate F (the geometric fitters pass true distances); it may
// report its own progress in [0, 1].
using ErrorMeasure = std::function<Eigen::VectorXd(const BSplineSurface& F, ProgressRange progress)>;

// The parametric residuals F(u_k, v_k) − g_k.
Eigen::VectorXd parametric_residuals(const BSplineSurface& F, const Samples& samples, int threads = 1);

// Fits F; `measure` defaults to parametric_residuals. Progress: each round reports its assembly
// in [0, 0.4] and its error measure in [0.4, 1] of options.progress. Throws InputError for bad options or samples,
// NumericalError when the normal equations are singular or the tolerance is not met within the
// size limits (stating the error reached).
FunctionFitResult fit_function(const Samples& samples, const FunctionSpace& space,
                               const FunctionFitOptions& options, const ErrorMeasure& measure = {});

}  // namespace polarform
