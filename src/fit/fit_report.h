// What every geometric fitter reports besides its geometry: the degrees and net of F, the
// fairness weight, the TRUE point-to-geometry error statistics (closest-point distances) with the
// per-point signed distances behind them (deviation maps), the parametric error along the rays,
// and the time spent per stage.
#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "src/fit/error_stats.h"
#include "src/fit/net_selection.h"
#include "src/fit/outliers.h"
#include "src/fit/revolution_test.h"
#include "src/fit/stage_times.h"

namespace polarform {

struct FitReport {
  int degree_u = 0, degree_v = 0;    // of F (0 where F came out constant)
  int size_u = 0, size_v = 0;        // F's fitted control net (distinct values when periodic)
  int nurbs_degree_u = 0, nurbs_degree_v = 0;  // of the NURBS product
  int nurbs_size_u = 0, nurbs_size_v = 0;
  double lambda = 0.0;               // fairness weight used
  double dof = -1.0;                 // effective parameters (gcv only)
  int refinements = 0;               // knot-refinement rounds for a tolerance
  ErrorStats error;                  // |closest-point distance| of the points fitted (not outliers)
  ErrorStats radial;                 // |ρ_k − F(u_k, v_k)| along the rays, likewise
  Eigen::VectorXd signed_distance;   // per input point, positive outside (away from centre/axis)
  OutlierReport outliers;            // the points left out under OutlierPolicy::reject
  // Closest-point searches (one per input point; none is dropped): those that hit the iteration
  // limit of ProductGeometry::foot_point from the synchronized start were restarted from the best
  // of a coarse parameter grid (point_distances.h); `restarted` converged then, `unconverged` hit
  // the limit from both starts and keep the closest distance they reached.
  std::size_t unconverged = 0;
  std::size_t restarted = 0;
  NetSelection net;                  // how F's net was chosen (net_selection.h)
  RevolutionTest revolution;         // whether F was made constant around the axis, and why
  StageTimes times;
};

}  // namespace polarform
