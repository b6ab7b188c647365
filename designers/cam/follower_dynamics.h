// The follower's dynamics at the cam's speed, for a follower held on the cam by a spring (Norton,
// Cam Design and Manufacturing Handbook, ch. 8 and 10): the load Q = M·q̈ + c·q̇ + k·q + Q₀ in the
// follower's coordinate q — a translating follower's lift (Q the contact force F = m·a + c·v + k·s
// + F₀), or an oscillating arm's swing (Q the torque about the pivot, F = Q / lever, the lever the
// contact normal's moment arm about the pivot) — over the cycle, where the contact force is least
// (F < 0: the follower jumps), the speed at which it first jumps, the least spring rate that keeps
// contact, the camshaft torque T = Q·dq/dθ (power balance, no friction), and the Hertz
// line-contact stress between roller and cam, p = √(F·(1/R₁ + 1/R₂) / (π·L·((1 − ν₁²)/E₁ +
// (1 − ν₂²)/E₂))).
#pragma once

#include <optional>
#include <vector>

namespace polarform {

struct FollowerLoad {
  // Translating followers.
  double mass = 0.0;         // kg, the follower train's effective mass
  double spring_rate = 0.0;  // N/mm
  double preload = 0.0;      // N, the spring force at s = 0
  double damping = 0.0;      // N·s/mm
  // Oscillating followers (arm != 0): the arm about its pivot.
  bool arm = false;
  double inertia = 0.0;          // kg·m², the arm train's moment of inertia about the pivot
  double torsion_rate = 0.0;     // N·m/rad
  double preload_torque = 0.0;   // N·m, the spring torque at zero swing
  double torsion_damping = 0.0;  // N·m·s/rad
  // Line contact (roller or flat face on the cam): contact length L and both materials.
  double contact_width = 0.0;        // mm; 0: no contact stress
  double youngs_modulus = 210000.0;  // MPa, cam and follower alike
  double poisson_ratio = 0.3;

  bool operator==(const FollowerLoad&) const = default;
};

// The motion at one cam angle, per radian of cam angle, and the contour's radius of curvature
// there (+inf for a flat contour, negative where it is concave).
struct MotionSample {
  double theta = 0.0;                // rad
  double s = 0.0, v = 0.0, a = 0.0;  // mm, mm/rad, mm/rad² (an arm's swing: °, °/rad, °/rad²)
  double contour_radius = 0.0;       // mm
  double lever = 0.0;                // mm, arms only: CamSample::arm_lever
  // A conjugate pair's second roller (conjugate_cam.h): its contour's radius of curvature and, for
  // an arm, its contact normal's moment arm about the pivot (mm, > 0).
  double second_contour_radius = 0.0;
  double second_lever = 0.0;
};

struct DynamicsSample {
  double theta = 0.0;
  double force = 0.0;           // N
  double torque = 0.0;          // N·m, on the camshaft
  double contact_stress = 0.0;  // MPa (0 without a contact width)
  // A conjugate pair: the second roller's contact force (N, >= 0: it carries the load where the
  // first's would be negative) and its Hertz stress.
  double second_force = 0.0;
  double second_stress = 0.0;
};

struct FollowerDynamics {
  std::vector<DynamicsSample> samples;
  DynamicsSample least_force, largest_torque, largest_stress;  // where they occur
  bool jumps = false;              // the least force is negative: contact is lost
  std::optional<double> jump_rpm;  // the lowest speed at which it jumps; none if never
  double min_spring_rate =
      0.0;  // N/mm (arm: N·m/rad): keeps F >= 0 at the design speed (same preload)
  // A conjugate pair (second_roller_radius > 0): the second cam holds the follower where the first
  // would lose it, so it never jumps (jumps false, no jump_rpm); the second roller's largest force
  // and stress and where.
  bool conjugate = false;
  DynamicsSample largest_second_force, largest_second_stress;
};

// At `rpm`; `roller_radius` (mm) is R₁ of the contact (0 for a flat face or a knife edge: then only
// the contour's curvature counts). Throws InputError for a negative mass (inertia), rate, preload,
// damping or width, a non-positive modulus, a Poisson ratio outside [0, 0.5), or an arm's sample
// whose lever is not positive (the cam cannot push the arm there).
// A conjugate pair's second roller of radius `second_roller_radius` (> 0; 0: none) carries the
// load the first cannot, F₂ = −Q (translating) or −Q / second_lever (arm) where that is positive,
// on the second contour (MotionSample::second_*): the same Hertz formula with its radii.
FollowerDynamics follower_dynamics(const std::vector<MotionSample>& motion, double rpm,
                                   double roller_radius, const FollowerLoad& load,
                                   double second_roller_radius = 0.0);

// The Hertz line-contact stress of force F (N) over width L (mm) between radii r1, r2 (mm; +inf
// flat, negative concave) of one material (E in MPa, ν): MPa.
double line_contact_stress(double force, double width, double r1, double r2, double youngs,
                           double poisson);

}  // namespace polarform
