// `polarform fit --fair kjellander|farin` on a surface fit (MIT 13.472J §8.2.4): the rows and
// columns of the fitted F(u, v) faired (src/fit/surface_fairing.h) so S = F·B stays exact, and
// report.json's "fairing" block and fairing.svg for it, alongside the profile's
// (profile_interrogation.h).
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "export/figure.h"
#include "src/fit/rotational_fit.h"
#include "src/fit/surface_fairing.h"

namespace polarform {

// Fairs the fit's F in place (cylindrical or spherical); `points` are the fit's input.
SurfaceFitFairing fair_surface_fit(RotationalFit& fit, const Eigen::Matrix3Xd& points,
                                   const ProfileFairingOptions& options);

// "fairing": method, tolerance_mm, passes, knots_faired[{direction, u, jump_before, jump_after,
// bound_mm}], max_jump_{before,after}_{u,v}, measured_deviation_mm, error_before_max_mm.
nlohmann::ordered_json surface_fairing_json(const SurfaceFitFairing& fairing);

// fairing.svg: the p-th derivative jump of F's net at every knot faired, before and after, along
// u and along v.
Figure surface_fairing_figure(const SurfaceFitFairing& fairing);

}  // namespace polarform
