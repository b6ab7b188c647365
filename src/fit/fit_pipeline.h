// Steps shared by the polar, spherical and cylindrical fitters around the single-valued fit: the
// options of F with the caller's progress mapped into a sub-range, the error measure built on true
// closest-point distances, and the report assembled from the fit and the timings.
#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "src/base/base_circle.h"
#include "src/fit/fit_report.h"
#include "src/fit/function_fit.h"
#include "src/fit/product_geometry.h"

namespace polarform {

// u_k = circle.parameter(angle_k) for every k (Bae 2002, eqs. (2.7)-(2.8)), in parallel.
Eigen::VectorXd synchronize(const BaseCircle& circle, const Eigen::VectorXd& angle, int threads);

// opt with its progress (if any) reported into [from, to] of the same callback.
FunctionFitOptions with_progress_range(const FunctionFitOptions& opt, double from, double to);

// An ErrorMeasure of true distances from `local` points (3 x n, synchronized parameters u, v) to
// the geometry `make(F)` builds; the count of unconverged foot points lands in *unconverged, that
// of the foot points found only after a restart in *restarted (when given).
template <class MakeGeometry>
ErrorMeasure distance_measure(MakeGeometry make, const Eigen::Matrix3Xd& local,
                              const Samples& samples, int threads, std::size_t* unconverged,
                              std::size_t* restarted = nullptr);

// The report of a fit: F's degrees and net, the NURBS's, λ, errors (geometric moved out of
// fit.errors, radial recomputed), timings (the fit's stages added to `times`; total left to the
// caller).
FitReport make_report(FunctionFitResult& fit, int nurbs_degree_u, int nurbs_degree_v, int nurbs_size_u,
                      int nurbs_size_v, const Samples& samples, int threads, std::size_t unconverged,
                      StageTimes times);

}  // namespace polarform

#include "src/fit/point_distances.h"

namespace polarform {

template <class MakeGeometry>
ErrorMeasure distance_measure(MakeGeometry make, const Eigen::Matrix3Xd& local,
                              const Samples& samples, int threads, std::size_t* unconverged,
                              std::size_t* restarted) {
  return [make, &local, &samples, threads, unconverged, restarted](const BSplineSurface& F,
                                                                   ProgressRange progress) {
    const PointDistances d = point_distances(make(F), local, samples.u, samples.v, threads, progress);
    *unconverged = d.unconverged;
    if (restarted) *restarted = d.restarted;
    return d.signed_distance;
  };
}

}  // namespace polarform
