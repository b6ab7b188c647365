#include "designers/vessel/edge_bending.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "designers/vessel/polar_curvature.h"
#include "src/error.h"
#include "src/nurbs/error_text.h"

namespace polarform {

namespace {

constexpr double kHalfPi = std::numbers::pi / 2;
// e^(−π/4) sin(π/4): the largest of e^(−βx) sin βx, at βx = π/4.
const double kPeakMoment = std::exp(-std::numbers::pi / 4) * std::sin(std::numbers::pi / 4);

// The meridian's tangent angle (x, z) at θ on `piece`: a kink where the pieces meeting at a
// joint disagree.
double tangent_angle(const PolarFunction& piece, double theta) {
  double d[2];
  piece.derivatives(theta, 1, d);
  const double c = std::cos(theta), s = std::sin(theta);
  return std::atan2(d[1] * s + d[0] * c, d[1] * c - d[0] * s);
}

}  // namespace

// Geckeler's approximation (Timoshenko & Woinowsky-Krieger 1959, §§ 130, 132–134).
std::vector<EdgeBending> edge_bending(const HeadShape& shape, const VesselLoad& load,
                                      double poisson) {
  if (!(poisson >= 0.0 && poisson < 0.5))
    throw InputError("edge bending: Poisson's ratio " + to_text(poisson) + ", expected [0, 0.5)");
  check_vessel_load(load);
  const double t = load.thickness, p = load.pressure;
  const double root = std::pow(3 * (1 - poisson * poisson), 0.25);
  std::vector<EdgeBending> out;
  for (std::size_t j = 0; j < shape.jumps.size(); ++j) {
    const CurvatureJump& jump = shape.jumps[j];
    if (jump.theta >= kHalfPi - 1e-12) break;
    if (jump.theta > shape.membrane_end() + 1e-12) break;  // not beside a plate
    // The pieces before and after the joint (the cylinder before the junction).
    const PolarFunction* after = nullptr;
    const PolarFunction* before = nullptr;
    for (const PolarFunction& piece : shape.pieces) {
      if (std::abs(piece.start - jump.theta) < 1e-12) after = &piece;
      if (std::abs(piece.end - jump.theta) < 1e-12) before = &piece;
    }
    if (!after) continue;
    const double vertical = tangent_angle(*after, jump.theta);
    if (before ? std::abs(vertical - tangent_angle(*before, jump.theta)) > 1e-9
               : std::abs(vertical - kHalfPi) > 1e-9)
      continue;  // a kink, not a curvature jump
    EdgeBending e;
    e.theta = jump.theta;
    e.kappa_jump = jump.kappa_after - jump.kappa_before;
    if (std::abs(e.kappa_jump) * load.radius < 1e-12) continue;
    e.r2 = principal_radii(*after, jump.theta).r2;
    e.beta = root / std::sqrt(e.r2 * t);
    e.shear = p * e.r2 * std::abs(e.kappa_jump) / (8 * e.beta);
    e.max_moment = kPeakMoment * e.shear / e.beta;
    e.max_moment_offset = std::numbers::pi / (4 * e.beta);
    e.bending_stress = 6 * e.max_moment / (t * t);
    e.hoop_bending_stress = poisson * e.bending_stress;
    const MembraneForces a = membrane_forces(p, jump.kappa_before, e.r2);
    const MembraneForces b = membrane_forces(p, jump.kappa_after, e.r2);
    e.meridional_membrane_stress = b.meridional / t;
    e.hoop_stress_at_joint = 0.5 * (a.hoop + b.hoop) / t;
    e.max_meridional_stress = e.meridional_membrane_stress + e.bending_stress;
    e.decay_length = std::numbers::pi / e.beta;
    const double after_length = arc_length(*after, after->start, std::min(after->end, kHalfPi), 64);
    const double before_length =
        before ? arc_length(*before, before->start, before->end, 64) : load.length / 2;
    e.shorter_piece = std::min(after_length, before_length);
    out.push_back(e);
  }
  return out;
}

}  // namespace polarform
