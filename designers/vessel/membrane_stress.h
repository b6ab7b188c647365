// Membrane stresses of the vessel under internal pressure p: the head is a shell of revolution whose
// principal radii come from its polar meridian R(θ) — r1 = 1/κ meridional (DESIGN §4.4), r2 the
// length of the normal from the wall to the axis — with N_φ = p r2 / 2 and N_θ = p r2 (1 − r2/(2 r1))
// (membrane theory of shells of revolution), stress = N / t. Sampled along the meridian from the
// cylinder over junction A to the apex (the half that is revolved), with compressive hoop bands.
#pragma once

#include <vector>

#include "designers/convert/polar_function.h"

namespace polarform {

struct PrincipalRadii {
  double kappa1 = 0.0;  // meridional curvature 1/r1, 1/mm (0 for a straight meridian)
  double r2 = 0.0;      // circumferential radius, mm
};

// At θ in [0, π/2] of a head meridian R(θ) (x = R cos θ radial, z = R sin θ axial); at θ = π/2
// (the apex) r2 takes its limit r1 for a smooth apex and 0 at a cone point.
PrincipalRadii principal_radii(const PolarFunction& head, double theta);

// The meridian's arc length ∫ √(R² + R'²) dθ over [a, b], 4-point Gauss–Legendre on each of
// `intervals` equal parts, mm.
double arc_length(const PolarFunction& R, double a, double b, int intervals = 1);

struct MembraneForces {
  double meridional = 0.0;  // N_φ, N/mm
  double hoop = 0.0;        // N_θ, N/mm
};

// N_φ = p r2/2, N_θ = p r2 (1 − κ1 r2/2); pressure in MPa, r2 in mm, κ1 in 1/mm.
MembraneForces membrane_forces(double pressure, double kappa1, double r2);

struct VesselLoad {
  double radius = 0.0;     // cylinder radius, mm
  double length = 0.0;     // cylinder length, mm
  double thickness = 0.0;  // wall thickness, mm
  double pressure = 0.0;   // internal pressure, MPa
};

// Throws InputError ("membrane stresses: <name> …, expected > 0") unless radius, length,
// thickness and pressure are > 0 and finite.
void check_vessel_load(const VesselLoad& load);

struct StressSample {
  double s = 0.0;       // meridian arc length from junction A, mm (negative on the cylinder)
  double theta = 0.0;   // polar angle on the head, rad (0 on the cylinder)
  double rho = 0.0;     // distance from the axis, mm
  double z = 0.0;       // height above the junction plane, mm
  PrincipalRadii radii;
  MembraneForces forces;
  double meridional_stress = 0.0;  // MPa
  double hoop_stress = 0.0;        // MPa
  bool on_cylinder = false;
};

struct CompressiveBand {
  double theta_from = 0.0, theta_to = 0.0;  // rad, ends located where N_θ = 0
  double s_from = 0.0, s_to = 0.0;          // mm
  double min_hoop_stress = 0.0;             // MPa, the most compressive sample
};

struct StressProfile {
  // Two cylinder samples (s = −length/2 and the junction, cylinder side), then the head samples
  // from θ = 0 (junction, head side) to π/2 (apex; a flat head: the junction only), in θ order:
  // `samples` equal steps of θ, both sides of every joint of the meridian (its breakpoints, where
  // curvature jumps; 1e-10 rad off the joint) and every interior extremum of N_φ or N_θ located by
  // golden section.
  std::vector<StressSample> samples;
  std::vector<CompressiveBand> compressive_hoop;
};

// The head is sampled over [0, membrane_end] (π/2; a flat head's 0: HeadShape::membrane_end()).
// Throws InputError unless radius, length, thickness and pressure are > 0, samples >= 2 and
// 0 <= membrane_end <= π/2.
StressProfile membrane_stresses(const PolarFunction& head, const VesselLoad& load,
                                int samples = 181, double membrane_end = 1.5707963267948966);

}  // namespace polarform
