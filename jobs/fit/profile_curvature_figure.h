// A fitted profile's curvature.svg (the fit job's profiles, scan-cam's cam profile): the signed
// curvature against the polar angle about the centre with the inflections ringed, and below it the
// jump of the degree-th derivative at every knot (profile_interrogation.h), before and after a
// fairing when there was one.
#pragma once

#include <string>

#include "export/figure.h"
#include "jobs/fit/profile_interrogation.h"

namespace polarform {

// angle_label: the x axis, e.g. "polar angle θ about the centre [deg]". With `before` (the curve
// before fairing) its κ and jumps are drawn in grey under the faired ones.
Figure profile_curvature_figure(const ProfileInterrogation& interrogation,
                                const std::string& angle_label,
                                const ProfileInterrogation* before = nullptr);

}  // namespace polarform
