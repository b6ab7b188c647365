// The base surface that parametrises a scanned patch (Piegl & Tiller 2001, §2; spec P3): the
// bilinearly blended Coons patch of the boundary (§2.1), the bicubically blended one with
// cross-boundary derivatives fitted to a share of the points (§2.2), or a tensor-product
// least-squares surface on a share with the boundary fixed (§2.3). Each is measured by the true
// distances of all points (Newton from their current parameters).
#pragma once

#include <Eigen/Core>
#include <string>

#include "src/nurbs/nurbs_surface.h"
#include "src/nurbs/patch_boundary.h"

namespace polarform {

enum class BaseKind { bilinear, bicubic, tensor };
// The bicubic base's scaling of its fitted derivatives against overshoot: automatic builds both
// and keeps the one nearer to the points.
enum class CrossScale { automatic, yes, no };

struct BaseSurfaceOptions {
  BaseKind kind = BaseKind::bilinear;
  double share = 0.3;                // fraction of the points the bicubic/tensor base is fitted to
  int control_u = 0, control_v = 0;  // tensor base net (0: the boundary's counts)
  int degree_u = 0, degree_v = 0;    // tensor base degrees (0: max(2, the boundary's degrees))
  CrossScale cross_scale = CrossScale::automatic;
  int threads = 2;
};

struct BaseSurface {
  BaseKind kind = BaseKind::bilinear;
  NurbsSurface surface;
  int fitted_points = 0;      // bicubic/tensor: the share's size
  bool cross_scaled = false;  // bicubic: the scaled derivatives were kept
  double unscaled_max_distance = -1.0, scaled_max_distance = -1.0;  // bicubic automatic: both
  double twist_mismatch = 0.0;                                      // bicubic
  Eigen::VectorXd u, v, distances;  // every point's foot on the surface and its distance
  double max_distance = 0.0, rms_distance = 0.0;
};

std::string base_kind_name(BaseKind kind);

// The points with their feet (u, v) on the bilinear Coons patch of `boundary` and their distances
// there (from parametrize_on_blanket with the polish): the bilinear base is that patch with these
// numbers; the others are fitted on a share drawn with a fixed seed (the same input gives the same
// base) and measured by Newton from (u, v).
BaseSurface build_base_surface(const PatchBoundary& boundary, const Eigen::Matrix3Xd& points,
                               const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                               const Eigen::VectorXd& distances, const BaseSurfaceOptions& options);

// The true distances of the points to `surface` by Newton from (u, v), in parallel: the feet are
// written back into u and v.
Eigen::VectorXd distances_from_parameters(const NurbsSurface& surface,
                                          const Eigen::Matrix3Xd& points, Eigen::VectorXd& u,
                                          Eigen::VectorXd& v, int threads);

}  // namespace polarform
