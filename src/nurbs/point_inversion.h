// Point inversion: the closest point of a NURBS curve or surface to a given point (NURBS Book
// §6.1, Newton on the orthogonality conditions, with a robust start). Curves isolate every root of
// C'·(C − P) span by span (Bernstein sign changes) and refine it by safeguarded Newton, so no
// minimum is missed, at ends, kinks and seams included. Surfaces run Newton from the best local
// minima of a sample grid, clamp at open boundaries, wrap across seams and re-search the edges.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

struct CurveProjection {
  double u;
  Eigen::VectorXd point;
  double distance;
};

// The point of `c` closest to `p` (the first one found on ties).
template <int D>
CurveProjection closest_point(const NurbsCurve<D>& c, const Eigen::Matrix<double, D, 1>& p);

struct SurfaceProjection {
  double u, v;
  Eigen::Vector3d point;
  double distance;
};

// Projects many points onto one surface: the sample grid, the closed-seam flags and the boundary
// curves are computed once. project() is const and thread-safe.
class SurfaceProjector {
 public:
  // samples_per_span = 0 picks degree + 2 samples per knot span in each direction; the grid is
  // then refined until neighbouring samples are at most 1/32 of the control net's size apart
  // (at most 160 samples per direction).
  explicit SurfaceProjector(NurbsSurface surface, int samples_per_span = 0);

  const NurbsSurface& surface() const { return surface_; }
  // True when S(front_u, v) ≡ S(back_u, v) (the u-boundaries form a seam); likewise v.
  bool closed_u() const { return closed_u_; }
  bool closed_v() const { return closed_v_; }

  // Global search: Newton from the best local minima of the sample grid.
  SurfaceProjection project(const Eigen::Vector3d& p) const;
  // Local search from a caller-supplied start (e.g. synchronized base parameters), no grid scan.
  SurfaceProjection project(const Eigen::Vector3d& p, double u0, double v0) const;

 private:
  struct Edge {
    bool along_v;  // the edge is u = const (a curve in v); otherwise v = const (a curve in u)
    double at;     // the fixed parameter value
    NurbsCurve3d curve;
  };

  // An interior knot of full multiplicity (the surface only C0 across its iso-line) with the
  // lengths of the knot spans on either side.
  struct Crease {
    double at, left, right;
  };

  SurfaceProjection newton(const Eigen::Vector3d& p, double u, double v) const;
  SurfaceProjection with_crease_restarts(const Eigen::Vector3d& p, SurfaceProjection best) const;
  SurfaceProjection with_edge_fallback(const Eigen::Vector3d& p, SurfaceProjection best) const;

  NurbsSurface surface_;
  int samples_u_, samples_v_;     // grid size in u and v
  std::vector<double> grid_u_, grid_v_;
  Eigen::Matrix3Xd grid_;         // grid point (a, b) in column a·samples_v_ + b
  bool closed_u_ = false, closed_v_ = false;
  // Boundaries collapsed to a point (poles), in the order u = front, u = back, v = front, v = back.
  std::array<bool, 4> degenerate_{};
  double scale_ = 1.0;            // size of the control net, for tolerances
  std::vector<Edge> edges_;       // open boundaries only
  std::vector<Crease> creases_u_, creases_v_;
};

// One-off projection (builds a SurfaceProjector).
SurfaceProjection closest_point(const NurbsSurface& s, const Eigen::Vector3d& p,
                                int samples_per_span = 0);

}  // namespace polarform
