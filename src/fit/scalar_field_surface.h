// Scientific visualisation of data measured on spherical or cylindrical set-ups (Bae 2002, §5.3):
// values {(p, φ, θ)} or {(p, θ, z)} are fitted by a single-valued F, and S = (s·F + d)·B (eq. (5.6))
// shows them as the radius of a NURBS surface over the base sphere or cylinder, each control point
// carrying the value of p at its parameters for colouring.
#pragma once

#include <Eigen/Core>
#include <numbers>

#include "src/base/arc_angle.h"
#include "src/fit/error_stats.h"
#include "src/fit/function_fit.h"
#include "src/fit/orthogonal_coordinates.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

struct ScalarFieldOptions {
  FunctionFitOptions function;  // F(u ↔ φ or z, v ↔ θ)
  double scale = 1.0;           // s of (5.6)
  double offset = 0.0;          // d of (5.6)
  ArcKind base_kind = ArcKind::rqb;
  double max_sweep = std::numbers::pi / 2;
  Closure closure = Closure::automatic;
};

struct ScalarFieldSurface {
  NurbsSurface surface;            // S = (s·F + d)·B, local coordinates of the set-up
  BSplineSurface F;                // p = F(u, v)
  Eigen::VectorXd control_values;  // p at control point (i, j) (index i·nv + j), at its Greville point
  double min_value = 0.0, max_value = 0.0;  // over control_values
  ErrorStats fit_error;            // |F(u_k, v_k) − p_k| over the data
};

// p_k at polar angle φ_k ∈ [0, π] and azimuth θ_k (radians); one entry each.
ScalarFieldSurface visualize_spherical(const Eigen::VectorXd& p, const Eigen::VectorXd& phi,
                                       const Eigen::VectorXd& theta, const ScalarFieldOptions& options = {});
// p_k at azimuth θ_k and height z_k.
ScalarFieldSurface visualize_cylindrical(const Eigen::VectorXd& p, const Eigen::VectorXd& theta,
                                         const Eigen::VectorXd& z, const ScalarFieldOptions& options = {});

}  // namespace polarform
