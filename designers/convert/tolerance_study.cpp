#include "designers/convert/tolerance_study.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "designers/convert/degree_limited.h"
#include "designers/convert/occt_peer.h"
#include "designers/convert/polar_conversion.h"
#include "designers/convert/sisl_peer.h"
#include "src/base/angle_deviation.h"
#include "src/error.h"
#include "src/units.h"

namespace polarform {

std::vector<double> log_tolerances(double loosest, double tightest, int per_decade) {
  if (!(tightest > 0 && loosest >= tightest))
    throw InputError("tolerance range: expected LOOSEST:TIGHTEST with LOOSEST >= TIGHTEST > 0 mm");
  if (per_decade < 1) throw InputError("tolerance range: steps per decade must be >= 1");
  const double decades = std::log10(loosest / tightest);
  const int steps = static_cast<int>(std::lround(decades * per_decade));
  // Rounded to 12 significant digits so that decades land on 1e-4, not 9.999999999999996e-05.
  const auto round12 = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.12g", x);
    return std::strtod(text, nullptr);
  };
  std::vector<double> out;
  for (int k = 0; k <= steps; ++k)
    out.push_back(steps == 0 ? loosest
                             : round12(loosest * std::pow(tightest / loosest, double(k) / steps)));
  return out;
}

namespace {

StudyMethodResult base_method(const PolarFunction& R, double tol, ArcKind kind) {
  ConversionOptions options;
  options.tolerance = tol;
  options.base = kind;
  // The base arcs compared as they build C = F·B (the product step, before any knot removal).
  options.compaction = Compaction::none;
  const PolarConversion c = convert_polar_function(R, options);
  return {static_cast<int>(c.arcs.size()), 0, c.curve.degree(), c.curve.size(), c.max_radial_error};
}

// Issue 14's comparison: our control points over the fewest of the found peer fits'.
StudyPeerRatios peer_ratios(const StudyRow& row) {
  StudyPeerRatios out;
  int best = 0;
  for (const StudyPeerResult* p :
       {&row.occt_degree3, &row.occt_best, &row.sisl_degree3, &row.sisl_best})
    if (p->found && (best == 0 || p->control_points < best)) best = p->control_points;
  if (best > 0) {
    out.exact_to_best = double(row.exact.control_points) / best;
    out.degree3_to_best = double(row.degree3.control_points) / best;
  }
  if (row.occt_degree3.found)
    out.degree3_to_occt_degree3 =
        double(row.degree3.control_points) / row.occt_degree3.control_points;
  if (row.sisl_degree3.found)
    out.degree3_to_sisl_degree3 =
        double(row.degree3.control_points) / row.sisl_degree3.control_points;
  return out;
}

}  // namespace

std::vector<StudyRow> tolerance_study(const PolarFunction& R, const std::vector<double>& tolerances,
                                      const std::function<void(double)>& progress,
                                      const StudyOptions& options) {
  std::vector<StudyRow> rows;
  for (std::size_t k = 0; k < tolerances.size(); ++k) {
    const double tol = tolerances[k];
    StudyRow row;
    row.tolerance = tol;
    row.quartic = base_method(R, tol, ArcKind::quartic);
    row.rqb = base_method(R, tol, ArcKind::rqb);
    const LimitedCurve cubic = interpolate_polar_curve(R, 3, tol);
    // A closed interpolant has as many distinct control values as points (3 repeat at the seam).
    row.cubic = {0, R.closed() ? cubic.control_points - 3 : cubic.control_points, 3,
                 cubic.control_points, cubic.max_radial_error};
    ConversionOptions exact_options;
    exact_options.tolerance = tol;
    const PolarConversion exact = convert_polar_function(R, exact_options);
    row.exact = {static_cast<int>(exact.arcs.size()), 0, exact.curve.degree(), exact.curve.size(),
                 exact.max_radial_error};
    const LimitedCurve degree3 = approximate_polar_curve(R, 3, tol);
    row.degree3 = {0, 0, 3, degree3.control_points, degree3.max_radial_error};
    const auto result = [](const PeerCurve& c) {
      return StudyPeerResult{c.found, c.degree, c.control_points, c.max_radial_error,
                             c.peer_tolerance};
    };
    // Discarded without Open CASCADE (SISL), so that occt_points_to_bspline (sisl_s1961) need not
    // exist.
    if constexpr (kOcctPeersAvailable) {
      if (options.peers) {
        row.peers = true;
        row.occt_degree3 = result(occt_points_to_bspline(R, 3, 3, tol));
        row.occt_best = result(occt_points_to_bspline(R, 3, 8, tol));
      }
    }
    if constexpr (kSislPeersAvailable) {
      if (options.peers) {
        row.peers = true;
        const PeerCurve degree3 = sisl_s1961(R, 3, tol);
        const PeerCurve higher = sisl_s1961_best(R, 4, 8, tol);  // degree 3 is fitted above
        row.sisl_degree3 = result(degree3);
        row.sisl_best = result(
            higher.found && (!degree3.found || higher.control_points < degree3.control_points)
                ? higher
                : degree3);
      }
    }
    if (row.peers) row.ratios = peer_ratios(row);
    rows.push_back(row);
    if (progress) progress(static_cast<double>(k + 1) / tolerances.size());
  }
  return rows;
}

std::vector<DeviationRow> angle_deviation_study(int count) {
  if (count < 2) throw InputError("angle deviation study: at least 2 arc angles");
  std::vector<DeviationRow> out;
  for (int k = 0; k < count; ++k) {
    const double angle =
        2 * kRadiansPerDegree * std::pow(90.0, static_cast<double>(k) / (count - 1));
    DeviationRow row;
    row.arc_angle = angle;
    row.rqb = max_angle_deviation(ArcKind::rqb, angle / 2);
    row.quartic_minimax = max_angle_deviation(ArcKind::quartic, angle / 2, AlphaRule::minimax);
    row.quartic_printed = max_angle_deviation(ArcKind::quartic, angle / 2, AlphaRule::printed);
    out.push_back(row);
  }
  return out;
}

}  // namespace polarform
