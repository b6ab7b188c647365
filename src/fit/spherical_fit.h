// Spherical NURBS-surface fitting (Bae 2002, §3.1, §3.3, §4.3): a local frame (estimated by the
// general-quadric fit or given) → spherical coordinates (3.1) → a base sphere over the data's angle
// ranges (3.3) → synchronization (φ, θ) → (u, v) → a single-valued F(u, v) of degree (p, q) →
// S = F·B of degree (p+2, q+2) by the symbolic product (3.5) → back to global coordinates (4.6).
// Closed in θ for full-azimuth data (periodic F, clipped, §3.3.1); poles closed by the simple G1
// condition (3.14) or by a cap surface (§3.3.2); a closed pole far from the data, or one that
// creases, is flagged. A true sphere gives degree (2, 2).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <numbers>
#include <optional>

#include "src/base/base_sphere.h"
#include "src/fit/continuity.h"
#include "src/fit/fit_report.h"
#include "src/fit/function_fit.h"
#include "src/fit/local_frame.h"
#include "src/fit/model_choice.h"
#include "src/fit/orthogonal_coordinates.h"
#include "src/fit/outliers.h"
#include "src/fit/pole_cap.h"
#include "src/fit/single_valued_check.h"
#include "src/io/point_cloud.h"

namespace polarform {

enum class PoleTreatment {
  automatic,  // g0 when the data comes within pole_reach of the pole, else none
  none,       // the surface ends at the data's polar-angle range
  g0,         // extended to the pole, collapsed to one point: f_{0,j} = f_{0,0} (eq. (3.14a))
  g1,         // extended to the pole with f_{0,j} = f_{1,j} = f_{0,0} (Bae 2002, eq. (3.14)):
              // one point with a tangent plane perpendicular to the axis
  cap,        // a separate cap surface over the hole (§3.3.2 Steps 1-4); needs a closed fit
};

struct SphericalFitOptions {
  FunctionFitOptions function;  // F(u ↔ φ, v ↔ θ), default bicubic
  ModelChoiceOptions model;     // net by GCV unless given; F(u) alone when θ adds nothing
  FrameOptions frame;
  ArcKind base_kind = ArcKind::rqb;
  AlphaRule alpha_rule = AlphaRule::minimax;
  double max_sweep = std::numbers::pi / 2;  // square-based base circles
  Closure closure = Closure::automatic;
  double closed_gap = 0.0;                  // see azimuth_range
  PoleTreatment north = PoleTreatment::automatic;  // at φ = 0
  PoleTreatment south = PoleTreatment::automatic;  // at φ = π
  double pole_reach = std::numbers::pi / 18;       // 10°: see PoleTreatment::automatic
  bool check_single_valued = true;
  OutlierPolicy outliers = OutlierPolicy::refuse;
};

// A pole whose normals (3.12) spread by more than this about their mean creases: it has no
// tangent plane (a G0 pole (3.14a) in general; G1 (3.14) and caps have one by construction).
constexpr double kMaxPoleNormalSpread = std::numbers::pi / 180;  // 1°

// What a closed pole rests on.
struct PoleCheck {
  double nearest_data = 0.0;  // polar angle (rad) from the pole to the nearest data point
  bool extrapolated = false;  // closed (g0, g1, cap) with no data within pole_reach of the pole
  bool creased = false;       // g0, g1: normal spread above kMaxPoleNormalSpread
};

struct SphericalFit {
  NurbsSurface surface;                      // global coordinates
  std::optional<PoleCap> north_cap, south_cap;  // global coordinates
  BSplineSurface F;                          // ρ = F(u, v) on the base sphere's parameters
  BaseSphere base;                           // local coordinates
  FrameEstimate frame;
  bool closed = false;
  SeamReport seam;                           // closed fits
  PoleTreatment north = PoleTreatment::none, south = PoleTreatment::none;  // as applied
  std::optional<PoleReport> north_pole, south_pole;  // g0 / g1 poles, measured on the surface
  PoleCheck north_check, south_check;
  SingleValuedness check;
  FitReport report;
};

// Throws InputError for bad input, a frame that cannot be estimated, a cap without a closed fit,
// a few outliers (under refuse, with their count), or data that is not single-valued about the
// origin (naming the φ, θ ranges); NumericalError when the tolerance cannot be met.
SphericalFit fit_spherical(const Eigen::Matrix3Xd& points, const SphericalFitOptions& options = {});
SphericalFit fit_spherical(const std::filesystem::path& file, const SphericalFitOptions& options = {},
                           const ReadOptions& read = {});

}  // namespace polarform
