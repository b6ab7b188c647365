// The control net of a parametric surface fit chosen by the data (the parametric counterpart of
// net_selection.h): nets grown one direction at a time from the starting net, each fitted by least
// squares at the given parameters and scored by generalized cross-validation GCV = (RSS/n)/(1 −
// m/n)² (Craven & Wahba 1979) over the n = 3N coordinates and the m = 3·(free control points)
// unknowns; the growth stops when GCV no longer improves by kGcvImprovement (the residual has
// reached the noise level), at one free control point per kSamplesPerCoefficient points, or at the
// size limit.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "src/fit/net_selection.h"
#include "src/fit/surface_fit.h"

namespace polarform {

struct SurfaceNetCandidate {
  int control_u = 0, control_v = 0;
  long free_points = 0;  // control points not fixed by the boundary
  double rms = 0.0;      // parametric residual |S(u_k, v_k) − Q_k|
  double gcv = 0.0;
};

struct SurfaceNetSelection {
  int control_u = 0, control_v = 0;  // the chosen net
  std::size_t samples = 0;           // points the choice used (a strided subsample of large clouds)
  double noise = 0.0;          // σ̂ = sqrt(RSS/(N − free points)) at the chosen net (normal)
  bool noise_reached = false;  // GCV stopped improving (else a limit stopped the growth)
  std::vector<SurfaceNetCandidate> candidates;  // in the order tried
  std::string stop;                             // why the growth stopped
};

// `options` gives the degrees, the boundary (fixed rows and columns), smoothing and threads; its
// control counts are the starting net (0: the boundary's, else 4). Correction rounds and the
// tolerance are ignored: every candidate is one least-squares solve at (u, v).
SurfaceNetSelection select_surface_net(const Eigen::Matrix3Xd& points, const Eigen::VectorXd& u,
                                       const Eigen::VectorXd& v, const SurfaceFitOptions& options);

}  // namespace polarform
