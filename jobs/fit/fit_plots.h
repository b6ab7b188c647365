// The fit job's preview (preview.svg): for a polar curve the data with the fitted curve in the
// profile plane and the signed deviation against polar angle; for a surface the histogram of the
// signed deviations and the deviation against azimuth θ and against φ (spherical) or z
// (cylindrical) in the fit's local frame (Bae 2002, eqs. (3.1), (3.6)).
#pragma once

#include "export/figure.h"
#include "jobs/fit/fit_job.h"

namespace polarform {

Figure fit_preview_figure(const FitJobResult& r);

// Every k-th index so that at most `limit` of n remain (k >= 1): how the preview thins markers.
int marker_stride(Eigen::Index n, int limit);

}  // namespace polarform
