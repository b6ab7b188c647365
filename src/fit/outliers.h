// Outliers of scanned data: a few points far off the rest. Each radius is compared with the
// robust trend of its cell of ~32 points (a quadratic by least squares reweighted with Tukey's
// biweight), then with that of its neighbours centred on it; a point beyond kOutlierSigmas times
// the larger of the scan's σ (1.4826 · median |deviation|: the noise) and its neighbourhood's own
// is an outlier, unless it lines up with others (a narrow feature or a short second branch). The
// data decides, not a fit: a fit too coarse for the shape finds none. A fitter's OutlierPolicy
// says what it does with them.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "src/error.h"
#include "src/fit/single_valued_check.h"

namespace polarform {

// How far off (in robust σ) a point is an outlier: the distance the single-valuedness check takes
// for two branches, so that a point is either on the data's one branch or off it.
constexpr double kOutlierSigmas = 8.0;
// "A few": at most this fraction of the points. More is a structure of the data, not outliers.
constexpr double kMaxOutlierFraction = 0.05;

// What a fitter does with outliers.
enum class OutlierPolicy {
  keep,    // fit every point as given, look for none
  refuse,  // InputError "n outliers … at > 8 σ …: rerun with --reject-outliers" for a few
  reject,  // leave them out of the fit (trimmed least squares), report how many
};

struct OutlierScan {
  // Radius minus the robust trend: of its neighbours, centred, where its cell's trend made it a
  // candidate; else of its cell (0 in cells of fewer than 3 points).
  Eigen::VectorXd deviation;
  double scale = 0.0;      // σ: 1.4826 · median |deviation| over the cells' trends
  double threshold = 0.0;  // max(kOutlierSigmas · σ, floor): the least a point is off to be one
  std::vector<Eigen::Index> points;  // the outliers, increasing
};

// r over the coordinates s (and t) of check_single_valued; `floor` is the smallest threshold.
OutlierScan find_outliers(const Eigen::VectorXd& s, const Eigen::VectorXd& t,
                          const Eigen::VectorXd& r, double floor, int threads = 1);

// The smallest outlier threshold for data of radii r: 1e-4 of their median (the check's floor
// for two branches), so that round-off of exact data never makes outliers.
double outlier_floor(const Eigen::VectorXd& r);

// What a fit found and did.
struct OutlierReport {
  OutlierPolicy policy = OutlierPolicy::keep;
  std::size_t count = 0;   // outliers found (left out of the fit under reject)
  double scale = 0.0;      // the scan's σ, mm (OutlierScan)
  double threshold = 0.0;  // the least a point is off to be an outlier, mm
  double largest = 0.0;    // the largest |deviation| among them, mm
  Eigen::Index largest_point = -1;
  std::vector<Eigen::Index> points;  // the outliers, increasing
};

// Where a point lies, for messages ("theta 37.2 deg").
using PointPlace = std::function<std::string(Eigen::Index)>;

// The outliers of a fitter's data (radii r over the check's coordinates s, t) under `policy`,
// after check_single_valued gave `check` (when `checked`). A failed check is explained by a few
// outliers (at most kMaxOutlierFraction) without which the data is single-valued; otherwise
// `folds()` is thrown. Under refuse a few outliers are an InputError "<fit>: n outliers of N
// points at > 8 σ (σ = … mm, threshold … mm; largest d mm at <place>): rerun with
// --reject-outliers". The report's points are those to leave out of the fit (reject only).
OutlierReport settle_outliers(OutlierPolicy policy, const Eigen::VectorXd& s,
                              const Eigen::VectorXd& t, const Eigen::VectorXd& r,
                              const SingleValuedness& check, bool checked, const std::string& fit,
                              const PointPlace& place, const std::function<InputError()>& folds,
                              int threads);

}  // namespace polarform
