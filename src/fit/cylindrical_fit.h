// Cylindrical NURBS-surface fitting (Bae 2002, §3.2, §3.3.1, §4.3): a local frame (estimated or
// given) → cylindrical coordinates (3.6) → a unit base cylinder over the data's azimuth and height
// ranges (3.7) → u = (z − z_s)/(z_e − z_s), v by (2.7)-(2.8) → a single-valued F(u, v) →
// S = (F·X, F·Y, Z) by the modified symbolic product (B.3), degree (max(p, 1), q+2) (3.8) → global
// coordinates (4.6). A true surface of revolution gives degree (3, 2), a true cylinder (1, 2).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <numbers>

#include "src/base/base_cylinder.h"
#include "src/fit/continuity.h"
#include "src/fit/fit_report.h"
#include "src/fit/function_fit.h"
#include "src/fit/local_frame.h"
#include "src/fit/model_choice.h"
#include "src/fit/orthogonal_coordinates.h"
#include "src/fit/outliers.h"
#include "src/fit/single_valued_check.h"
#include "src/io/point_cloud.h"

namespace polarform {

// Frame options whose ellipsoid rule takes the spheroid axis (the default of cylindrical fits).
inline FrameOptions most_distinct_axis() {
  FrameOptions f;
  f.ellipsoid_axis = EllipsoidAxis::most_distinct;
  return f;
}

struct CylindricalFitOptions {
  FunctionFitOptions function;  // F(u ↔ z, v ↔ θ), default bicubic
  ModelChoiceOptions model;     // net by GCV unless given; F(u) alone when θ adds nothing
  FrameOptions frame = most_distinct_axis();
  ArcKind base_kind = ArcKind::rqb;
  AlphaRule alpha_rule = AlphaRule::minimax;
  double max_sweep = std::numbers::pi / 2;
  Closure closure = Closure::automatic;
  double closed_gap = 0.0;
  bool check_single_valued = true;
  OutlierPolicy outliers = OutlierPolicy::refuse;
};

struct CylindricalFit {
  NurbsSurface surface;   // global coordinates
  BSplineSurface F;       // r = F(u, v) on the base cylinder's parameters
  BaseCylinder base;      // local coordinates
  FrameEstimate frame;
  bool closed = false;
  SeamReport seam;        // closed fits
  SingleValuedness check;
  FitReport report;
};

// Throws InputError for bad input, a frame that cannot be estimated, a few outliers (under
// refuse, with their count), or data that is not single-valued about the axis (naming the z, θ
// ranges); NumericalError when the tolerance cannot be met.
CylindricalFit fit_cylindrical(const Eigen::Matrix3Xd& points, const CylindricalFitOptions& options = {});
CylindricalFit fit_cylindrical(const std::filesystem::path& file,
                               const CylindricalFitOptions& options = {}, const ReadOptions& read = {});

}  // namespace polarform
