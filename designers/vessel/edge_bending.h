// The bending at a head's curvature jumps — the head–cylinder junction and a torispherical head's
// knuckle–crown joint — by thin-shell edge theory in Geckeler's approximation (Timoshenko &
// Woinowsky-Krieger, Theory of Plates and Shells, 1959, §§ 130, 132–134): near the joint both
// shells bend like long cylinders of the joint's circumferential radius r2, with
// β = [3(1 − ν²)]^¼ / √(r2 t). Membrane theory leaves their edges apart by the jump of the hoop
// strain; the edge shear that closes the gap is Q0 = p r2 |Δκ| / (8β) with no edge moment (equal
// walls), giving the hemisphere's textbook Q0 = p/(8β). The meridional moment peaks at
// M = e^(−π/4) sin(π/4) Q0/β = 0.3224 Q0/β at the distance π/(4β) from the joint, and the hoop
// force at the joint is the mean of the two membrane values.
#pragma once

#include <vector>

#include "designers/vessel/head_preset.h"
#include "designers/vessel/membrane_stress.h"

namespace polarform {

struct EdgeBending {
  double theta = 0.0;                       // rad, the joint (0: the junction with the cylinder)
  double r2 = 0.0;                          // circumferential radius at the joint, mm
  double kappa_jump = 0.0;                  // κ after − κ before, 1/mm
  double beta = 0.0;                        // 1/mm
  double shear = 0.0;                       // Q0, N/mm
  double max_moment = 0.0;                  // N·mm/mm, at max_moment_offset on either side
  double max_moment_offset = 0.0;           // π/(4β), mm
  double bending_stress = 0.0;              // 6 M / t², MPa (meridional, ± on the two surfaces)
  double hoop_bending_stress = 0.0;         // ν · bending_stress, MPa
  double meridional_membrane_stress = 0.0;  // N_φ / t at the joint, MPa
  double hoop_stress_at_joint = 0.0;        // the mean of the two membrane hoop stresses, MPa
  double max_meridional_stress = 0.0;       // membrane + bending at the peak moment, MPa
  // The decay length π/β against the shorter of the two pieces meeting there (the cylinder's
  // half length for the junction): the approximation wants the bending to die out within both.
  double decay_length = 0.0;   // π/β, mm
  double shorter_piece = 0.0;  // mm (meridian arc length)
  bool approximate() const { return decay_length > shorter_piece; }
};

// Every curvature jump of the head on θ in [0, π/2) (the revolved A half), for the wall thickness
// and pressure of `load` and Poisson's ratio ν. A kink of the meridian (a cone meeting the
// cylinder without a knuckle) is not a curvature jump and is not covered: none is returned for it.
// Throws InputError unless 0 <= ν < 0.5 and the load is valid (check_vessel_load).
std::vector<EdgeBending> edge_bending(const HeadShape& shape, const VesselLoad& load,
                                      double poisson = 0.3);

}  // namespace polarform
