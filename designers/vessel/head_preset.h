// The heads a vessel engineer knows — hemispherical, semi-ellipsoidal (2:1 by default),
// torispherical (crown and knuckle radii) and conical (half apex angle, with or without a knuckle)
// — as exact meridians R(θ) on [0, π] about the head's polar origin, as curvature distributions,
// and with the places where that curvature jumps (at the junctions with the cylinder, whose
// meridian is straight, and at the knuckle–crown joints). Sampled as curvature targets they are the
// input of the curvature-continuous alternative.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "designers/convert/polar_function.h"
#include "designers/vessel/synthesis_problem.h"

namespace polarform {

enum class HeadKind { hemispherical, ellipsoidal, torispherical, conical, flat };

// "hemispherical", "ellipsoidal", "torispherical", "conical", "flat" (the words of the project
// file).
const char* head_kind_name(HeadKind kind);

struct HeadPreset {
  HeadKind kind = HeadKind::hemispherical;
  double ratio = 2.0;    // ellipsoidal: cylinder radius / head depth (2 for the 2:1 head)
  double crown = 0.0;    // torispherical: crown (dish) radius, mm
  double knuckle =
      0.0;  // torispherical, conical, flat: knuckle radius, mm (a conical head's may be 0)
  double half_angle = 0.0;  // conical: half apex angle α between the cone and the axis, rad

  bool operator==(const HeadPreset&) const = default;
};

// The common torispherical heads by vessel diameter D = 2·radius: crown D, knuckle 0.06 D
// (ASME flanged-and-dished, "100 %/6 %"), and crown 0.8 D, knuckle 0.1 D ("80 %/10 %").
HeadPreset torispherical_100_6(double radius);
HeadPreset torispherical_80_10(double radius);
// The torispherical head of a given depth h with knuckle radius r: the crown radius
// L = (h² − r² + (a − r)²) / (2 (h − r)) that puts the apex at h (a = radius; the knuckle centre
// (a − r, 0), the crown centre (0, h − L)). L − a = (a − h)²/(2(h − r)) >= 0. Throws InputError
// unless 0 < knuckle < depth.
HeadPreset torispherical_of_depth(double radius, double depth, double knuckle);

// A conical head's meridian (x radial, z axial) for a cylinder of radius R: the knuckle of radius
// r about (R − r, 0) from the junction over the angle α to its tangent point
// T = (R − r + r cos α, r sin α) with the cone (outward normal (cos α, sin α)), whose straight
// meridian runs on to the apex (0, z_T + x_T cot α) on the axis.
struct ConeGeometry {
  double knuckle_centre_x = 0.0;            // R − r, mm
  double tangent_x = 0.0, tangent_z = 0.0;  // T, mm
  double apex_z = 0.0;                      // the head's depth, mm
};
// Throws InputError unless 0 < α < 90° and 0 <= r < R.
ConeGeometry cone_geometry(double radius, double half_angle, double knuckle);
// The flanged flat head's: the same with α = 90° (the plate at z = r). Throws InputError unless
// 0 < r < R.
ConeGeometry flat_head_geometry(double radius, double knuckle);
// A conical or flat preset's: its half angle α (90° for a flat head) and its geometry.
std::pair<double, ConeGeometry> knuckled_head_geometry(const HeadPreset& preset, double radius);

struct CurvatureJump {
  double theta = 0.0;         // rad
  double kappa_before = 0.0;  // 1/mm just below θ (the cylinder's 0 before θ = 0)
  double kappa_after = 0.0;   // just above θ (the cylinder's 0 after θ = π)
};

struct HeadShape {
  std::string name;                   // e.g. "torispherical, crown 1000 mm, knuckle 60 mm"
  std::vector<PolarFunction> pieces;  // analytic pieces covering [0, π] in order
  PolarFunction profile;  // all pieces as one R(θ); breakpoints at the joints and at π/2 (apex)
  double depth = 0.0;     // R(π/2), mm: the head's height above the junction plane
  std::vector<CurvatureJump> jumps;   // in θ order, junctions included
  // A flat head's plate radius R − r (0 for the other heads): the plate carries the pressure by
  // bending (flat_plate.h).
  double plate_radius = 0.0;
  // θ up to which the head is a membrane shell: π/2, but 0 for a flat head — its knuckle turns
  // into the plate, where r2 = x/n_x grows without bound; only the junction's membrane state holds.
  double membrane_end() const { return plate_radius > 0.0 ? 0.0 : 1.5707963267948966; }
};

// The preset for a cylinder of `radius` (mm). Throws InputError naming the parameter unless
// radius > 0, ratio > 0 (ellipsoidal), 0 < knuckle < radius <= crown (torispherical: the
// knuckle leaves the cylinder tangentially and meets a crown centred on the axis) and 0 < α < 90°,
// 0 <= knuckle < radius (conical; without a knuckle the cone meets the cylinder at a kink, and
// the apex is a cone point) and 0 < knuckle < radius (flat: the flanged flat head, a knuckle
// turning by 90° into a flat plate at the height of the knuckle radius — the cone of α = 90°).
HeadShape head_shape(const HeadPreset& preset, double radius);

// The curvature distribution as `count` >= 1 targets at θ_k = (k + ½)π / count, weight 1.
std::vector<CurvatureTarget> preset_targets(const HeadShape& shape, int count);

}  // namespace polarform
