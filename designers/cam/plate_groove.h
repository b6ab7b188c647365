// A grooved plate cam: a face groove in the plate in which the follower's roller rides, so that
// the cam drives it both ways. The groove's flanks are the pitch curve offset by ∓Rr: the inner
// flank is the ordinary contour, the outer flank pitch + Rr·normal (Norton, Cam Design and
// Manufacturing Handbook, grooved (track) cams). The outer flank undercuts where the pitch curve is
// concave with a radius of curvature below Rr (1 + Rr κ_pitch <= 0).
#pragma once

#include "designers/cam/plate_cam.h"
#include "designers/convert/polar_function.h"

namespace polarform {

// The outer flank as the roller's image on the far side. Throws InputError naming groove-depth
// unless the follower has a roller.
RollerImage groove_outer_flank(const PlateCam& cam);

// The outer flank as the converter's R(ψ); InputError naming the θ range and the remedy where it
// undercuts (contour_polar_function.h).
PolarFunction groove_outer_flank_function(const PlateCam& cam);

}  // namespace polarform
