// True point-to-geometry distances for a whole cloud: the foot point of every point on S = F·B by
// ProductGeometry::foot_point, started from its synchronized parameters, in parallel; a search
// that does not converge is restarted from the best of a coarse parameter grid around it, so only
// points that fail from every start are counted. The fitters' error reports and the adaptive
// refinement are built on these.
#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "src/fit/parallel.h"
#include "src/fit/product_geometry.h"

namespace polarform {

struct PointDistances {
  Eigen::VectorXd signed_distance;  // per point, positive away from the centre / axis
  std::size_t unconverged = 0;  // foot points not found from the synchronized start nor the restart
  std::size_t restarted = 0;    // foot points found only after the restart
};

// local: points in the geometry's local frame (3 x n; z = 0 for curves); u, v: their synchronized
// parameters, the start of each foot-point search.
PointDistances point_distances(const ProductGeometry& geometry, const Eigen::Matrix3Xd& local,
                               const Eigen::VectorXd& u, const Eigen::VectorXd& v, int threads = 1,
                               ProgressRange progress = {});

}  // namespace polarform
