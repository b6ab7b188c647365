// Making a 2D band of points thin by moving least squares (Kantz 2003, §4.4–4.5; Lee 2000): every
// point moves to the weighted quadratic of its neighbourhood, in the frame of the neighbourhood's
// weighted total-least-squares line (rotation invariant, unlike the seed's y-regression), with the
// weight 2(h/r)³ − 3(h/r)² + 1 of the distance h (not h², a unit error in the seed) and a radius
// grown until the neighbourhood is nearly linear (spec K5).
#pragma once

#include <Eigen/Core>

namespace polarform {

struct MlsOptions {
  double radius = 0.0;      // start radius; <= 0: twice the grid index's cell size
  int min_neighbours = 8;   // grow the radius until at least this many neighbours
  int max_neighbours = 96;  // ... and stop growing at this many
  double linearity = 0.1;   // nearly linear: weighted PCA λ_min / λ_max <= this
  int growth_steps = 4;     // radius × 1.5 at most this often
  int iterations = 2;       // re-centre and refit this often (Lee 2000)
  int threads = 2;
};

struct MlsThinning {
  Eigen::Matrix2Xd points;  // the moved points, in input order
  Eigen::VectorXd radius;   // the radius each point used
  double start_radius = 0.0;
};

// Points must be finite (InputError otherwise); fewer than 3 points are returned unmoved.
MlsThinning mls_thin(const Eigen::Matrix2Xd& points, const MlsOptions& options = {});

}  // namespace polarform
