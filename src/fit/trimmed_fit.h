// Fitting F without some points (the outliers OutlierPolicy::reject leaves out): trimmed least
// squares (Rousseeuw & Leroy 1987, §1.2) — F is fitted to the points kept, and the true distance
// of every point, those left out included, is measured from the result. With no point left out it
// is the plain fit, unchanged.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <vector>

#include "src/fit/function_fit.h"
#include "src/fit/model_choice.h"
#include "src/fit/product_geometry.h"

namespace polarform {

// The geometry S = F·B of a fitted F (it refers to F, which must outlive it).
using GeometryOf = std::function<ProductGeometry(const BSplineSurface&)>;

struct TrimmedFit {
  FunctionFitResult fit;        // errors: every point's signed distance; stats: the kept points'
  Samples kept;                 // the samples fitted
  std::size_t unconverged = 0;  // foot points (of all points) that hit their iteration limit
  std::size_t restarted = 0;    // foot points (of all points) found only after a restart
  NetSelection net;             // the model chosen for F before the fit (model_choice.h)
  RevolutionTest revolution;
};

// Fits the samples (one per column of `local`, the points in the geometry's frame) but those
// listed in `leave_out` (increasing indices), with the model choose_model picks from the kept
// samples. The samples are taken by value: without outliers they become `kept` without a copy
// (240 MB at 10^7 points).
TrimmedFit fit_trimmed(Samples samples, const Eigen::Matrix3Xd& local, const FunctionSpace& space,
                       const FunctionFitOptions& options, const GeometryOf& geometry,
                       const std::vector<Eigen::Index>& leave_out,
                       const ModelChoiceOptions& model = {});

}  // namespace polarform
