// A scanned patch fitted by a parametric tensor-product B-spline (Piegl & Tiller 2001, §3.4, §4;
// spec P8): the bilinear Coons patch of the boundary parametrises the points through its quad
// blanket (P1, P4–P6); a bicubic or tensor-product base, when asked for, is fitted to a share of
// them and parametrises them again (P2–P3); optionally the points are thinned by the base's
// geometry (P7); the final surface is fitted with the boundary fixed (B2), with
// parameter-correction rounds; every point's true distance to it is measured.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "src/fit/base_surface.h"
#include "src/fit/error_stats.h"
#include "src/fit/max_area_plane.h"
#include "src/fit/parallel.h"
#include "src/fit/quad_projection.h"
#include "src/fit/surface_fit.h"
#include "src/fit/surface_net_selection.h"
#include "src/fit/thinning.h"
#include "src/nurbs/surface_decomposition.h"

namespace polarform {

struct PatchFitOptions {
  BaseSurfaceOptions base;
  DecompositionOptions decomposition;  // of the base surfaces (P&T: 0.5 %)
  PatchSearchOptions search;
  double thin = 0.0;  // > 0: thinning tolerance (relative, as the decomposition)
  int degree_u = 3, degree_v = 3;
  int control_u = 0, control_v = 0;  // 0: the boundary's counts (after degree elevation)
  double tolerance = 0.0;            // > 0: refine the net until every fitted point is this near
  int correction_rounds = 0;
  int threads = 2;
  ProgressFn progress;  // fraction done, increasing
};

struct PatchStageTimes {
  double base = 0.0, decomposition = 0.0, search = 0.0, thinning = 0.0, net = 0.0, fit = 0.0,
         error = 0.0;
};

struct PatchFit {
  NurbsSurface bilinear;               // the bilinear Coons patch (always built: it parametrises)
  BaseSurface base;                    // the base the final parameters come from
  SurfaceDecomposition decomposition;  // of the base
  MaxAreaPlane plane;                  // of the base's blanket (for the report and plane search)
  PatchParameters parameters;          // every point on the base
  std::optional<Thinning> thinning;
  std::optional<SurfaceNetSelection> net;  // when the data chose the net
  SurfaceFit fit;             // on the kept points
  Eigen::VectorXd u, v;       // every point's foot on the final surface
  Eigen::VectorXd distances;  // signed true distances (positive along S_u × S_v)
  ErrorStats error;           // of all points
  PatchStageTimes timings_s;
};

// Throws InputError for bad options or too few points (fewer than 16), NumericalError when a stage
// cannot complete.
PatchFit fit_patch(const Eigen::Matrix3Xd& points, const PatchBoundary& boundary,
                   const PatchFitOptions& options);

}  // namespace polarform
