// The fit options of the fit workspace as its panel edits them — method (automatic, polar profile,
// spherical, cylindrical), degrees, a tolerance or a fixed control net (both values kept while the
// other is chosen), fairness, base arcs, closure, pole treatment, outlier rejection and an
// optional frame origin and axis instead of the estimated ones — and their exchange with fit
// projects (jobs/project/fit_project.h), from which the fit job takes its options.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <optional>

#include "jobs/project/fit_project.h"

namespace polarform::studio {

struct FitSettings {
  int method = 0;  // FitJobMethod: 0 automatic, 1 polar, 2 spherical, 3 cylindrical
  int degree_u = 3, degree_v = 3;
  // Off by default, as in `polarform fit`: a net chosen by the data always fits, whereas any
  // default tolerance is below the noise of some scan.
  bool use_tolerance = false;
  double tolerance = 0.1;  // mm, on the true distance statistic `measure`
  int measure = 1;         // ToleranceMeasure: scans are noisy, so p99 rather than the max
  bool automatic_net =
      true;  // no tolerance: the net chosen by the data (GCV), else size_u x size_v
  int size_u = 12, size_v = 12;
  int fairness = 1;  // FairnessOptions::Mode
  double fairness_weight = 1e-7;
  bool quartic_base = false;
  int closure = 0;  // Closure
  int pole = 0;     // PoleTreatment (spherical), both poles
  // The local frame's origin and axis k, mm; unset: estimated from the cloud (Bae 2002, §4.3).
  std::optional<Eigen::Vector3d> center, axis;
  bool skip_bad = true;  // the studio always skips bad records (and says how many); kept for files
  bool reject_outliers = false;  // leave outliers out of the fit instead of refusing the cloud
  int revolution = 0;            // RevolutionMode: 0 F-test, 1 always F(u) alone, 2 never

  bool operator==(const FitSettings&) const = default;
};

// The settings a fit project asks for.
FitSettings fit_settings(const FitProject& project);

// The fit project for these settings and this scan path.
FitProject fit_project(const FitSettings& settings, const std::filesystem::path& scan);

}  // namespace polarform::studio
