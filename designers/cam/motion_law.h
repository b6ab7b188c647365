// Motion laws of a cam segment: the nine standard normalised laws with exact closed forms, the
// laws with parameters (SCCA, constant velocity with blends), the user motion table, and the two
// synthesised kinds (Hermite polynomial, smoothest constrained B-spline) that meet arbitrary
// endpoint constraints. Names are the spellings used in project files and on the command line.
// Normalised law: x = θ/β in [0, 1], S(0) = 0, S(1) = 1; derivatives are with respect to x.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "designers/cam/polynomial.h"

namespace polarform {

enum class MotionLaw {
  SimpleHarmonic,     // "harmonic"
  Cycloidal,          // "cycloidal"
  ModifiedTrapezoid,  // "modified-trapezoid"
  ModifiedSine,       // "modified-sine"
  Polynomial345,      // "3-4-5"
  Polynomial4567,     // "4-5-6-7"
  Polynomial,  // "polynomial": minimal-degree Hermite polynomial for the endpoint constraints, or
               // of a stated degree with interior constraints (constrained_polynomial.h)
  BSpline,     // "bspline": smoothest B-spline meeting the endpoint constraints
  Scca,        // "scca": sine–constant–cosine acceleration with parameters (scca_law.h)
  ConstantAcceleration,  // "constant-acceleration": parabolic, SCCA (0, 1, 0)
  Cubic,                 // "cubic": 3x² − 2x³
  DoubleHarmonic,        // "double-harmonic": Rothbart's, for a rise followed by a return
  ConstantVelocity,      // "constant-velocity": with cycloidal blends (constant_velocity_law.h)
  Table,                 // "table": a user motion table (motion_table.h)
};

std::string_view motion_law_name(MotionLaw law);
// Throws InputError naming the unknown law and listing the valid names.
MotionLaw parse_motion_law(std::string_view name);
// The nine normalised laws with fixed shape (not Polynomial, BSpline, Scca, ConstantVelocity,
// Table).
bool is_standard_law(MotionLaw law);
// Whether S(x) = 1 − S(1 − x): then a return's normalised law is the rise's. Only the double
// harmonic is not; its return is its rise's mirror image (motion_segment.h).
bool is_antisymmetric_law(MotionLaw law);

// S(x), S'(x), ..., S^(d)(x) into out[0..d] for a standard law, d <= 4 (the fourth derivative
// feeds the third polar derivative of roller and flat-faced contours). x is clamped to [0, 1].
// Throws InputError for a law that is not standard.
void standard_law(MotionLaw law, double x, int d, double* out);

// Normalised x in (0, 1) where a standard law's pieces join and its jerk jumps: 1/8, 3/8, 5/8,
// 7/8 (modified trapezoid), 1/8, 7/8 (modified sine), 1/2 (constant acceleration); none for the
// others.
std::vector<double> law_joins(MotionLaw law);

// The power-basis form of S on [0, 1] when the standard law is a polynomial (cubic, 3-4-5,
// 4-5-6-7).
std::optional<Polynomial> standard_law_polynomial(MotionLaw law);

}  // namespace polarform
