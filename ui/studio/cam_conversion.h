// The cam profile converted to an exact-degree NURBS by the polar converter: the contour R(ψ) of
// a plate cam → PolarConversion (a cylindrical cam's track height goes through the job layer,
// which keeps it positive for the converter), its summary, and the measured radial error densely
// along the curve for the error plot (ψ in degrees, error in µm), with the arc junctions. Throws
// InputError / NumericalError from the converter.
#pragma once

#include <vector>

#include "designers/convert/polar_conversion.h"
#include "jobs/project/cam_project.h"
#include "ui/studio/cam_results.h"
#include "ui/studio/conversion_summary.h"

namespace polarform::studio {

struct CamConversion {
  ConversionOptions options;
  PolarConversion conversion;
  ConversionSummary summary;
  std::vector<double> error_angle_deg, error_um;  // sorted by angle
  std::vector<double> junctions_deg;              // arc starts after the first
};

CamConversion convert_cam(const CamResults& results, const CamProject& project);

}  // namespace polarform::studio
