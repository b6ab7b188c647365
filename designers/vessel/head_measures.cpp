#include "designers/vessel/head_measures.h"

#include <cmath>
#include <numbers>
#include <string>

#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

constexpr double kPi = std::numbers::pi;

void require_positive(double value, const char* name, const char* unit) {
  if (!(value > 0.0 && std::isfinite(value)))
    throw InputError(std::string("head measures: ") + name + " = " + number_text(value) +
                     (*unit ? " " : "") + unit + ", expected > 0");
}

void require_torispherical(double radius, double crown, double knuckle) {
  require_positive(radius, "radius R", "mm");
  if (!(knuckle > 0.0 && knuckle < radius))
    throw InputError("head measures: torispherical knuckle radius r = " + number_text(knuckle) +
                     " mm, expected 0 < r < R = " + number_text(radius) + " mm");
  if (!(crown >= radius && std::isfinite(crown)))
    throw InputError("head measures: torispherical crown radius L = " + number_text(crown) +
                     " mm, expected L >= R = " + number_text(radius) + " mm");
}

// The zone swept by a knuckle: the arc of radius r about (c, 0) from the junction over the angle
// φ, its lamina beyond x = c of area A = r²(φ + sin φ cos φ)/2 and moment c·A + (r²·z − z³/3)/2
// about the axis (z = r sin φ), so the zone holds π·c²·z + 2π·c·A + π(r²·z − z³/3); the arc of
// length r·φ and centroid distance c + r·sin φ/φ sweeps 2π·r(c·φ + r·sin φ) (Pappus).
HeadMeasures knuckle_zone(double c, double r, double phi) {
  const double s = std::sin(phi), z = r * s, lamina = r * r * (phi + s * std::cos(phi)) / 2;
  return {kPi * c * c * z + 2 * kPi * c * lamina + kPi * (r * r * z - z * z * z / 3),
          2 * kPi * r * (c * phi + r * s)};
}

// f(e)/e, and its limit 1 at e = 0, for f = asin, atanh, asinh.
template <class F>
double over_e(double e, F f) {
  return e == 0.0 ? 1.0 : f(e) / e;
}

}  // namespace

HeadMeasures hemispherical_head_measures(double radius) {
  require_positive(radius, "radius R", "mm");
  return {2 * kPi * radius * radius * radius / 3, 2 * kPi * radius * radius};
}

// Half the surface of the oblate or prolate spheroid (Weisstein, MathWorld, "Oblate Spheroid",
// "Prolate Spheroid").
HeadMeasures ellipsoidal_head_measures(double radius, double depth) {
  require_positive(radius, "radius a", "mm");
  require_positive(depth, "depth b", "mm");
  const double a = radius, b = depth;
  const double volume = 2 * kPi * a * a * b / 3;
  if (b <= a) {
    const double e = std::sqrt((a - b) * (a + b)) / a;
    return {volume, kPi * a * a + kPi * b * b * over_e(e, [](double x) { return std::atanh(x); })};
  }
  const double e = std::sqrt((b - a) * (b + a)) / b;
  return {volume, kPi * a * a + kPi * a * b * over_e(e, [](double x) { return std::asin(x); })};
}

double torispherical_depth(double radius, double crown, double knuckle) {
  require_torispherical(radius, crown, knuckle);
  return crown - std::sqrt((crown - radius) * (crown + radius - 2 * knuckle));
}

// Pappus's centroid theorems on the meridian. The knuckle is the arc of radius r about
// (c, 0), c = R − r, from the junction to the joint where its normal, at angle φ from the radial
// direction, points along the line of centres: cos φ = c/(L − r) (knuckle_zone). The crown above
// is a cap of height k = L(1 − sin φ) = L·cos²φ/(1 + sin φ): π·k²(3L − k)/3 and 2π·L·k.
HeadMeasures torispherical_head_measures(double radius, double crown, double knuckle) {
  require_torispherical(radius, crown, knuckle);
  const double r = knuckle, L = crown, c = radius - knuckle;
  const double phi = std::atan2(std::sqrt((L - radius) * (L + radius - 2 * r)), c);
  const double s = std::sin(phi), cs = std::cos(phi);
  const double k = L * cs * cs / (1 + s);
  const HeadMeasures zone = knuckle_zone(c, r, phi);
  return {zone.volume + kPi * k * k * (3 * L - k) / 3, zone.area + 2 * kPi * L * k};
}

// The knuckle zone over φ = α (knuckle_zone: its normal turns from radial to the cone's
// (cos α, sin α)), then the cone from its tangent circle of
// radius x_T to the apex: π·x_T³·cot α/3 and the lateral area π·x_T²/sin α.
HeadMeasures conical_head_measures(double radius, double half_angle, double knuckle) {
  require_positive(radius, "radius R", "mm");
  const ConeGeometry g = cone_geometry(radius, half_angle, knuckle);
  const HeadMeasures zone = knuckle_zone(g.knuckle_centre_x, knuckle, half_angle);
  const double x = g.tangent_x;
  return {zone.volume + kPi * x * x * x / std::tan(half_angle) / 3,
          zone.area + kPi * x * x / std::sin(half_angle)};
}

// The knuckle zone over φ = 90° (its normal turns from radial to axial) and the plate's disc of
// radius R − r above it: V = π c² r + π² c r²/2 + 2π r³/3, A = π² r c + 2π r² + π c² (c = R − r).
HeadMeasures flat_head_measures(double radius, double knuckle) {
  require_positive(radius, "radius R", "mm");
  const ConeGeometry g = flat_head_geometry(radius, knuckle);
  const double c = g.knuckle_centre_x;
  const HeadMeasures zone = knuckle_zone(c, knuckle, kPi / 2);
  return {zone.volume, zone.area + kPi * c * c};
}

HeadMeasures cylinder_measures(double radius, double length) {
  require_positive(radius, "radius R", "mm");
  require_positive(length, "length", "mm");
  return {kPi * radius * radius * length, 2 * kPi * radius * length};
}

HeadMeasures head_measures(const HeadPreset& preset, double radius) {
  switch (preset.kind) {
    case HeadKind::hemispherical:
      return hemispherical_head_measures(radius);
    case HeadKind::ellipsoidal:
      require_positive(preset.ratio, "ellipsoidal ratio radius/depth", "");
      return ellipsoidal_head_measures(radius, radius / preset.ratio);
    case HeadKind::torispherical:
      return torispherical_head_measures(radius, preset.crown, preset.knuckle);
    case HeadKind::conical:
      return conical_head_measures(radius, preset.half_angle, preset.knuckle);
    case HeadKind::flat:
      return flat_head_measures(radius, preset.knuckle);
  }
  return {};
}

double hemispherical_metal_volume(double radius, double thickness) {
  require_positive(thickness, "thickness t", "mm");
  const double inside = hemispherical_head_measures(radius).volume;
  return hemispherical_head_measures(radius + thickness).volume - inside;
}

// Pappus's second theorem on the band {p(s) + u·n(s), 0 <= u <= t} between the meridian p and its
// offset: its area element is (1 + κu) du ds, so the volume is 2π∫∫(x + u·n_x)(1 + κu) du ds =
// t·2π∫x ds + π·t²∫(κx + n_x) ds + 2/3·π·t³∫κ·n_x ds, where 2π∫x ds = A, ∫n_x ds = b, κ ds = dφ,
// ∫cos φ dφ = 1 and, with x = a² cos φ/√(a² cos²φ + b² sin²φ) and u = sin φ, ∫x dφ =
// a∫du/√(1 − e²u²) over [0, 1], e² = 1 − b²/a² (negative for b > a, hence asinh).
double ellipsoidal_metal_volume(double radius, double depth, double thickness) {
  require_positive(thickness, "thickness t", "mm");
  const double a = radius, b = depth, t = thickness;
  const double area = ellipsoidal_head_measures(a, b).area;
  const double e = std::sqrt(std::abs((a - b) * (a + b))) / a;
  const double x_dphi = b <= a ? a * over_e(e, [](double x) { return std::asin(x); })
                               : a * over_e(e, [](double x) { return std::asinh(x); });
  return t * area + kPi * t * t * (b + x_dphi) + 2 * kPi * t * t * t / 3;
}

double torispherical_metal_volume(double radius, double crown, double knuckle, double thickness) {
  require_positive(thickness, "thickness t", "mm");
  const double t = thickness, inside = torispherical_head_measures(radius, crown, knuckle).volume;
  return torispherical_head_measures(radius + t, crown + t, knuckle + t).volume - inside;
}

// The outer surface is the conical head on R + t with knuckle r + t about the same centre (the
// offset of a circle is concentric, of a line parallel), except at the apex, where the offset of
// the cone point is the sphere of radius t about it: the sharp tip beyond the sphere's tangent
// circle (at height t·sin α above the apex) is a cone of volume π·t³·cos⁴α/(3 sin α), the sphere's
// cap above it π·H²(3t − H)/3 with H = t(1 − sin α).
double conical_metal_volume(double radius, double half_angle, double knuckle, double thickness) {
  require_positive(thickness, "thickness t", "mm");
  const double t = thickness, a = half_angle, c = std::cos(a), s = std::sin(a);
  const double inside = conical_head_measures(radius, a, knuckle).volume;
  const double H = t * (1 - s);
  const double tip = kPi * t * t * t * c * c * c * c / (3 * s) - kPi * H * H * (3 * t - H) / 3;
  return conical_head_measures(radius + t, a, knuckle + t).volume - inside - tip;
}

double flat_metal_volume(double radius, double knuckle, double thickness) {
  require_positive(thickness, "thickness t", "mm");
  const double inside = flat_head_measures(radius, knuckle).volume;
  return flat_head_measures(radius + thickness, knuckle + thickness).volume - inside;
}

double cylinder_metal_volume(double radius, double length, double thickness) {
  require_positive(thickness, "thickness t", "mm");
  const double inside = cylinder_measures(radius, length).volume;
  return cylinder_measures(radius + thickness, length).volume - inside;
}

double head_metal_volume(const HeadPreset& preset, double radius, double thickness) {
  switch (preset.kind) {
    case HeadKind::hemispherical:
      return hemispherical_metal_volume(radius, thickness);
    case HeadKind::ellipsoidal:
      require_positive(preset.ratio, "ellipsoidal ratio radius/depth", "");
      return ellipsoidal_metal_volume(radius, radius / preset.ratio, thickness);
    case HeadKind::torispherical:
      return torispherical_metal_volume(radius, preset.crown, preset.knuckle, thickness);
    case HeadKind::conical:
      return conical_metal_volume(radius, preset.half_angle, preset.knuckle, thickness);
    case HeadKind::flat:
      return flat_metal_volume(radius, preset.knuckle, thickness);
  }
  return 0.0;
}

double metal_weight(double metal_volume, double density) {
  if (!(metal_volume >= 0.0 && std::isfinite(metal_volume)))
    throw InputError("head measures: metal volume = " + number_text(metal_volume) +
                     " mm³, expected >= 0");
  require_positive(density, "density", "kg/m³");
  return metal_volume * std::pow(kMetresPerMillimetre, 3) * density;
}

}  // namespace polarform
