// Least-squares fitting of a general quadric to a point cloud (Bae 2002, §4.3, eq. (4.1)) with
// Taubin's normalisation (Taubin 1991: minimise Σ q(x_k)² / Σ |∇q(x_k)|², a generalised
// eigenproblem) on data centred at its centroid and scaled to unit RMS radius, which makes the
// fit invariant to rigid motions and uniform scaling and keeps the 10 x 10 moments well
// conditioned. The fit is then classified by Table 4.1 with a noise-aware rank tolerance.
#pragma once

#include <Eigen/Core>

#include "src/fit/quadric.h"

namespace polarform {

struct QuadricFitOptions {
  // Rank tolerance of classify_quadric; <= 0 selects max(1e-6, 3 · the fit's normalised RMS
  // Sampson distance), so eigenvalues below the noise of the data count as zero.
  double rank_tolerance = 0.0;
  int threads = 2;
};

struct QuadricFit {
  Quadric quadric;                       // in the input coordinates, |q| = 1
  Quadric normalized;                    // in y = (x − centroid)/scale, |q| = 1
  QuadricClassification classification;  // made in the normalised coordinates (L = 1)
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double scale = 1.0;                    // RMS distance of the points from the centroid
  double rms_distance = 0.0;             // RMS Sampson distance |q|/|∇q| of the points (units of x)
};

// Needs at least 9 points not all on one plane; throws InputError otherwise.
QuadricFit fit_quadric(const Eigen::Matrix3Xd& points, const QuadricFitOptions& options = {});

}  // namespace polarform
