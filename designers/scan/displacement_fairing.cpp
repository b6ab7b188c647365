#include "designers/scan/displacement_fairing.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"

namespace polarform {

// MIT 13.472J §8.2.3 (8.19)–(8.33) on s(θ).
DisplacementFairing fair_scanned_displacement(ScannedCam& scan,
                                              const ProfileFairingOptions& options) {
  DisplacementFairing r;
  r.method = options.method;
  r.tolerance = fairing_tolerance(options, scan.displacement.noise);
  const BSpline s0 = scan.displacement.height.spline();
  if (options.method == FairingMethod::kjellander && s0.degree() != 3)
    throw InputError("--fair kjellander: the recovered displacement s(θ) has degree " +
                     std::to_string(s0.degree()) +
                     "; Kjellander's fairing interpolates cubics (use --fair farin)");
  FairingOptions o;
  o.tolerance = r.tolerance;
  o.max_passes = options.max_passes;
  o.fixed_end_points = s0.degree();
  r.max_jump_before = max_top_derivative_jump(s0);
  CurveFairing f =
      options.method == FairingMethod::farin ? farin_fair(s0, o) : kjellander_fair_spline(s0, o);
  r.steps = std::move(f.steps);
  r.max_jump_after = max_top_derivative_jump(f.spline);
  for (int k = 0; k <= 20000; ++k) {
    const double t = s0.front() + (s0.back() - s0.front()) * k / 20000;
    r.measured_deviation =
        std::max(r.measured_deviation, std::abs(f.spline.point(t)[0] - s0.point(t)[0]));
  }
  scan.displacement.height = BSplineFunction(std::move(f.spline));
  return r;
}

}  // namespace polarform
