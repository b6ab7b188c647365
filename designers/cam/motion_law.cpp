#include "designers/cam/motion_law.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "src/error.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

struct LawName {
  MotionLaw law;
  std::string_view name;
};
constexpr std::array<LawName, 14> kLawNames = {
    {{MotionLaw::SimpleHarmonic, "harmonic"},
     {MotionLaw::Cycloidal, "cycloidal"},
     {MotionLaw::ModifiedTrapezoid, "modified-trapezoid"},
     {MotionLaw::ModifiedSine, "modified-sine"},
     {MotionLaw::Polynomial345, "3-4-5"},
     {MotionLaw::Polynomial4567, "4-5-6-7"},
     {MotionLaw::Polynomial, "polynomial"},
     {MotionLaw::BSpline, "bspline"},
     {MotionLaw::Scca, "scca"},
     {MotionLaw::ConstantAcceleration, "constant-acceleration"},
     {MotionLaw::Cubic, "cubic"},
     {MotionLaw::DoubleHarmonic, "double-harmonic"},
     {MotionLaw::ConstantVelocity, "constant-velocity"},
     {MotionLaw::Table, "table"}}};

// The polynomial laws in the power basis; Norton, Cam Design and Manufacturing Handbook, polynomial
// functions (3-4-5: 10x^3 - 15x^4 + 6x^5; 4-5-6-7: 35x^4 - 84x^5 + 70x^6 - 20x^7); Rothbart, Cams
// (1956), cubic curve (3x^2 - 2x^3: the cubic with S' = 0 at both ends).
const Polynomial& law_polynomial(MotionLaw law) {
  static const Polynomial cubic(0.0, 1.0, {0, 0, 3, -2});
  static const Polynomial p345(0.0, 1.0, {0, 0, 0, 10, -15, 6});
  static const Polynomial p4567(0.0, 1.0, {0, 0, 0, 0, 35, -84, 70, -20});
  return law == MotionLaw::Cubic ? cubic : law == MotionLaw::Polynomial345 ? p345 : p4567;
}

// Double harmonic rise on all of [0, 1]: S = ½[(1 − cos πx) − ¼(1 − cos 2πx)]; Rothbart, Cams
// (1956), double harmonic curve. S''(0) = 0 but S''(1) = −π²: meant to run straight into a return.
void double_harmonic(double x, double* o) {
  const double s1 = std::sin(kPi * x), c1 = std::cos(kPi * x);
  const double s2 = std::sin(2 * kPi * x), c2 = std::cos(2 * kPi * x);
  o[0] = 0.5 * ((1 - c1) - 0.25 * (1 - c2));
  o[1] = kPi / 2 * (s1 - 0.5 * s2);
  o[2] = kPi * kPi / 2 * (c1 - c2);
  o[3] = kPi * kPi * kPi / 2 * (2 * s2 - s1);
  o[4] = kPi * kPi * kPi * kPi / 2 * (4 * c2 - c1);
}

// A sine acceleration pulse a = A sin(w x) from rest at x = 0 (derivatives s..s'''').
void sine_ramp(double A, double w, double x, double* o) {
  const double sn = std::sin(w * x), cs = std::cos(w * x);
  o[0] = A / w * (x - sn / w);
  o[1] = A / w * (1.0 - cs);
  o[2] = A * sn;
  o[3] = A * w * cs;
  o[4] = -A * w * w * sn;
}

// Continuation from state (s0, v0) with acceleration A cos(w t), t = x - x0.
void cosine_piece(double s0, double v0, double A, double w, double t, double* o) {
  const double sn = std::sin(w * t), cs = std::cos(w * t);
  o[0] = s0 + v0 * t + A / (w * w) * (1.0 - cs);
  o[1] = v0 + A / w * sn;
  o[2] = A * cs;
  o[3] = -A * w * sn;
  o[4] = -A * w * w * cs;
}

// Modified trapezoid on [0, 1/2]: sine ramp to A on [0, 1/8], constant A on [1/8, 3/8], cosine
// decay on [3/8, 1/2]; A = 8π/(π+2) from S(1/2) = 1/2. Norton, Handbook, double-dwell functions.
void modified_trapezoid_half(double x, double* o) {
  constexpr double w = 4 * kPi, A = 8 * kPi / (kPi + 2);
  if (x <= 0.125) return sine_ramp(A, w, x, o);
  const double v1 = A / w, s1 = A / w * (0.125 - 1.0 / w);
  if (x <= 0.375) {
    const double t = x - 0.125;
    o[0] = s1 + v1 * t + 0.5 * A * t * t;
    o[1] = v1 + A * t;
    o[2] = A;
    o[3] = o[4] = 0.0;
    return;
  }
  const double v2 = v1 + 0.25 * A, s2 = s1 + 0.25 * v1 + A / 32;
  cosine_piece(s2, v2, A, w, x - 0.375, o);
}

// Modified sine on [0, 1/2]: sine ramp of period 1/2 on [0, 1/8], then a cosine of period 3/2
// on [1/8, 1/2]; A = 4π²/(π+4) from S(1/2) = 1/2. Norton, Handbook, double-dwell functions.
void modified_sine_half(double x, double* o) {
  constexpr double w1 = 4 * kPi, w2 = 4 * kPi / 3, A = 4 * kPi * kPi / (kPi + 4);
  if (x <= 0.125) return sine_ramp(A, w1, x, o);
  const double v1 = A / w1, s1 = A / w1 * (0.125 - 1.0 / w1);
  cosine_piece(s1, v1, A, w2, x - 0.125, o);
}

// The law on [0, 1/2]; every standard law is antisymmetric about (1/2, 1/2).
void half_law(MotionLaw law, double x, double* o) {
  switch (law) {
    case MotionLaw::SimpleHarmonic: {  // S = (1 - cos πx)/2 = sin²(πx/2); Norton, Handbook, double-dwell functions
      const double sn = std::sin(kPi * x), cs = std::cos(kPi * x), h = std::sin(kPi * x / 2);
      o[0] = h * h;
      o[1] = kPi / 2 * sn;
      o[2] = kPi * kPi / 2 * cs;
      o[3] = -kPi * kPi * kPi / 2 * sn;
      o[4] = -kPi * kPi * kPi * kPi / 2 * cs;
      return;
    }
    case MotionLaw::Cycloidal: {  // S = x - sin(2πx)/(2π); Norton, Handbook, double-dwell functions
      const double w = 2 * kPi, sn = std::sin(w * x), cs = std::cos(w * x);
      o[0] = x - sn / w;
      o[1] = 1.0 - cs;
      o[2] = w * sn;
      o[3] = w * w * cs;
      o[4] = -w * w * w * sn;
      return;
    }
    case MotionLaw::ModifiedTrapezoid: return modified_trapezoid_half(x, o);
    case MotionLaw::ModifiedSine: return modified_sine_half(x, o);
    case MotionLaw::ConstantAcceleration:  // S = 2x² up to x = ½; Norton, Handbook, constant
                                           // acceleration
      o[0] = 2 * x * x;
      o[1] = 4 * x;
      o[2] = 4;
      o[3] = o[4] = 0;
      return;
    case MotionLaw::Cubic:
    case MotionLaw::Polynomial345:
    case MotionLaw::Polynomial4567: return law_polynomial(law).derivatives(x, 4, o);
    case MotionLaw::DoubleHarmonic:  // not antisymmetric: standard_law evaluates it whole
    case MotionLaw::Polynomial:
    case MotionLaw::BSpline:
    case MotionLaw::Scca:
    case MotionLaw::ConstantVelocity:
    case MotionLaw::Table:
      break;
  }
  throw InputError("motion law '" + std::string(motion_law_name(law)) +
                   "' has no fixed normalised form: it is synthesised from endpoint constraints or "
                   "takes parameters (scca_law.h)");
}

}  // namespace

std::string_view motion_law_name(MotionLaw law) {
  for (const LawName& n : kLawNames)
    if (n.law == law) return n.name;
  return "unknown";
}

MotionLaw parse_motion_law(std::string_view name) {
  for (const LawName& n : kLawNames)
    if (n.name == name) return n.law;
  std::string valid;
  for (const LawName& n : kLawNames) valid += (valid.empty() ? "" : ", ") + std::string(n.name);
  throw InputError("unknown motion law '" + std::string(name) + "'; expected one of: " + valid);
}

bool is_standard_law(MotionLaw law) {
  return law != MotionLaw::Polynomial && law != MotionLaw::BSpline && law != MotionLaw::Scca &&
         law != MotionLaw::ConstantVelocity && law != MotionLaw::Table &&
         motion_law_name(law) != "unknown";
}

bool is_antisymmetric_law(MotionLaw law) { return law != MotionLaw::DoubleHarmonic; }

void standard_law(MotionLaw law, double x, int d, double* out) {
  if (d < 0 || d > 4) throw InputError("standard motion law: derivative order " + std::to_string(d) + " outside [0, 4]");
  x = std::clamp(x, 0.0, 1.0);
  double o[5];
  if (law == MotionLaw::DoubleHarmonic) {
    double_harmonic(x, o);
    std::copy(o, o + d + 1, out);
    return;
  }
  const bool reflect = x > 0.5;
  half_law(law, reflect ? 1.0 - x : x, o);
  if (reflect) {  // S(x) = 1 - S(1-x), S^(k)(x) = (-1)^(k+1) S^(k)(1-x)
    o[0] = 1.0 - o[0];
    o[2] = -o[2];
    o[4] = -o[4];
  }
  std::copy(o, o + d + 1, out);
}

std::optional<Polynomial> standard_law_polynomial(MotionLaw law) {
  if (law == MotionLaw::Cubic || law == MotionLaw::Polynomial345 ||
      law == MotionLaw::Polynomial4567)
    return law_polynomial(law);
  return std::nullopt;
}

std::vector<double> law_joins(MotionLaw law) {
  switch (law) {
    case MotionLaw::ModifiedTrapezoid: return {0.125, 0.375, 0.625, 0.875};
    case MotionLaw::ModifiedSine: return {0.125, 0.875};
    case MotionLaw::ConstantAcceleration:
      return {0.5};
    default: return {};
  }
}

}  // namespace polarform
