// Closed-form measures of the standard heads and the cylinder on inside dimensions: the volume they
// enclose (a head's above its junction plane), the area of their inner surface, the torispherical
// head's depth, the metal volume of a wall of thickness t (between the inner surface and the outer
// one offset by t along the normal) and its weight. Lengths in mm, volumes in mm³, areas in mm².
// Every function throws InputError naming the parameter unless lengths are finite and > 0 and the
// torispherical head's 0 < r < R <= L (the conical head's: 0 < α < 90°, 0 <= r < R).
#pragma once

#include "designers/vessel/head_preset.h"

namespace polarform {

struct HeadMeasures {
  double volume = 0.0;  // enclosed by the inner surface and, for a head, the junction plane, mm³
  double area = 0.0;    // of the inner surface, mm²
};

// Hemisphere of inside radius R: V = 2/3·π·R³, A = 2π·R².
HeadMeasures hemispherical_head_measures(double radius);

// Half spheroid of semi-axes a (radius) and b (depth): V = 2/3·π·a²·b; A = π·a² + π·(b²/e)·atanh e
// with e² = 1 − b²/a² for b < a, π·a² + π·a·b·(asin e)/e with e² = 1 − a²/b² for b > a, 2π·a² at
// b = a.
HeadMeasures ellipsoidal_head_measures(double radius, double depth);

// Torispherical head of vessel radius R, crown radius L and knuckle radius r (0 < r < R <= L): the
// knuckle's torus zone plus the crown's spherical cap.
HeadMeasures torispherical_head_measures(double radius, double crown, double knuckle);

// Conical head of vessel radius R, half apex angle α (0 < α < 90°) and knuckle radius r
// (0 <= r < R): the knuckle's torus zone plus the cone to the apex (cone_geometry).
HeadMeasures conical_head_measures(double radius, double half_angle, double knuckle);
// Flanged flat head of vessel radius R and knuckle radius r (0 < r < R): the knuckle's torus zone
// over 90° plus the plate's disc of radius R − r at the height r.
HeadMeasures flat_head_measures(double radius, double knuckle);
// h = L − √((L − r)² − (R − r)²), the apex's height above the junction plane.
double torispherical_depth(double radius, double crown, double knuckle);

// Cylinder of radius R and length ℓ (no ends): V = π·R²·ℓ, A = 2π·R·ℓ.
HeadMeasures cylinder_measures(double radius, double length);

// The preset's head on a cylinder of `radius`: the ellipsoid's depth is radius / ratio.
HeadMeasures head_measures(const HeadPreset& preset, double radius);

// Metal volumes of a wall of thickness t > 0 outside the inner surface. The hemisphere's,
// torispherical head's and cylinder's outer surfaces are the same shapes on R + t (L + t, r + t),
// so theirs is the volume formula at outside dimensions minus at inside ones. The offset of an
// ellipse is no ellipse: the ellipsoidal head's is Pappus's theorem on the band between the
// meridian and its offset, t·A + π·t²·(b + ∫x dφ) + 2/3·π·t³ (φ the normal's angle; ∫x dφ =
// a·(asin e)/e for b < a, a·(asinh ε)/ε with ε² = b²/a² − 1 for b > a).
double hemispherical_metal_volume(double radius, double thickness);
double ellipsoidal_metal_volume(double radius, double depth, double thickness);
double torispherical_metal_volume(double radius, double crown, double knuckle, double thickness);
// The conical head's outer surface is the same shape on R + t, r + t but for the apex, where it
// is a sphere of radius t: the sharp tip beyond it is subtracted.
double conical_metal_volume(double radius, double half_angle, double knuckle, double thickness);
// The flat head's outer surface is the same shape on R + t, r + t.
double flat_metal_volume(double radius, double knuckle, double thickness);
double cylinder_metal_volume(double radius, double length, double thickness);
double head_metal_volume(const HeadPreset& preset, double radius, double thickness);

// The weight (mass) in kg of `metal_volume` mm³ of a material of `density` kg/m³ (steel ≈ 7850).
double metal_weight(double metal_volume, double density);

}  // namespace polarform
