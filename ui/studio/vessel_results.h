// Everything the vessel workspace shows about a design, computed by the vessel designer off the
// UI thread: the curvature synthesis (NLopt) with its residuals, the design's and the preset's
// profiles, curvatures and membrane stresses as plot series (degrees, mm, 1/mm, MPa), and the
// converted NURBS profile revolved into the vessel's surfaces.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "designers/vessel/vessel_design.h"
#include "designers/vessel/vessel_surfaces.h"
#include "jobs/project/vessel_project.h"
#include "ui/studio/conversion_summary.h"

namespace polarform::studio {

struct XYSeries {
  std::vector<double> x, y;
};

struct VesselResults {
  VesselProject project;
  VesselSolution solution;
  XYSeries radius, kappa;      // R(θ), κ(θ) over θ in degrees
  XYSeries targets, achieved;  // κ_k and κ(θ_k) at the targets
  XYSeries residuals;          // κ(θ_k) − κ_k
  XYSeries meridional, hoop;   // stresses over the meridian arc length s
  std::optional<XYSeries> preset_radius, preset_kappa, preset_meridional, preset_hoop;
  std::optional<ConversionSummary> conversion;
  std::optional<VesselSurfaces> surfaces;
  std::string conversion_error;  // why there is no conversion
};

// Throws InputError / NumericalError from the synthesis; a failed conversion is reported in
// conversion_error instead, so the synthesis still shows.
VesselResults compute_vessel_results(const VesselProject& project);

}  // namespace polarform::studio
