// The plate of a flanged flat head, which carries the pressure by bending, not as a membrane: the
// circular plate of radius a (the knuckle's inner end) and thickness t under uniform pressure p,
// bounded by its two edge conditions (Timoshenko & Woinowsky-Krieger, Theory of Plates and
// Shells, 1959, §§ 15–16): simply supported, the largest stress at the centre,
// σ = 3(3 + ν) p a² / (8 t²); clamped, at the edge, σ_r = 3 p a² / (4 t²) (at the centre
// 3(1 + ν) p a² / (8 t²)). The knuckle restrains the edge partly: the truth lies between.
#pragma once

namespace polarform {

struct FlatPlateBending {
  double plate_radius = 0.0;             // a, mm
  double simply_supported_centre = 0.0;  // MPa, σ_r = σ_θ at the centre
  double clamped_edge = 0.0;             // MPa, σ_r at the edge (the clamped plate's largest)
  double clamped_centre = 0.0;           // MPa
};

// Throws InputError unless a, t, p > 0 and 0 <= ν < 0.5.
FlatPlateBending flat_plate_bending(double plate_radius, double thickness, double pressure,
                                    double poisson);

}  // namespace polarform
