// A fitted profile's curvature.svg (the fit job's profiles, scan-cam's cam profile): the signed
// curvature against the polar angle about the centre with the inflections ringed, and below it the
// jump of the degree-th derivative at every knot (profile_interrogation.h).
#pragma once

#include <string>

#include "export/figure.h"
#include "jobs/fit/profile_interrogation.h"

namespace polarform {

// angle_label: the x axis, e.g. "polar angle θ about the centre [deg]".
Figure profile_curvature_figure(const ProfileInterrogation& interrogation,
                                const std::string& angle_label);

}  // namespace polarform
