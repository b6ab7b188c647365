// The cam job's figures: SVAJ (four panels against cam angle), analyses (pressure angle, radii of
// curvature, undercut), the profile itself (contour, control polygon, base and pitch circles) and
// the measured conversion error along the profile.
#pragma once

#include "export/svg_plot.h"
#include "jobs/cam/cam_job.h"

namespace polarform {

Figure svaj_figure(const CamJobResult& r);
Figure analysis_figure(const CamJobResult& r);
Figure profile_figure(const CamJobResult& r);
Figure conversion_error_figure(const CamJobResult& r);

// (polar angle ψ, radial error) of the final curve at `count` parameters, ψ in degrees.
std::vector<std::pair<double, double>> radial_error_samples(const CamJobResult& r, int count);

}  // namespace polarform
