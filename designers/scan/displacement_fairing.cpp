#include "designers/scan/displacement_fairing.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "designers/scan/design_recovery.h"
#include "src/error.h"
#include "src/nurbs/knot_insertion.h"
#include "src/nurbs/knot_removal.h"
#include "src/nurbs/knots.h"

namespace polarform {

namespace {

// max |a(θ) − b(θ)| over 20 001 cam angles of a's domain.
double max_difference(const BSpline& a, const BSpline& b) {
  double worst = 0.0;
  for (int k = 0; k <= 20000; ++k) {
    const double t = a.front() + (a.back() - a.front()) * k / 20000;
    worst = std::max(worst, std::abs(a.point(t)[0] - b.point(t)[0]));
  }
  return worst;
}

// The largest p-th-derivative jump at a simple interior knot, from the piecewise constant p-th
// derivative at the middles of the two spans about it (NURBS Book A3.2).
double max_simple_knot_jump(const BSpline& c) {
  const std::vector<Breakpoint> b = breakpoints(c.knots());
  const int p = c.degree();
  double worst = 0.0;
  for (std::size_t i = 1; i + 1 < b.size(); ++i) {
    if (b[i].multiplicity != 1) continue;
    const double left = c.derivatives(0.5 * (b[i - 1].value + b[i].value), p)(0, p);
    const double right = c.derivatives(0.5 * (b[i].value + b[i + 1].value), p)(0, p);
    worst = std::max(worst, std::abs(right - left));
  }
  return worst;
}

// Farin's fairing (MIT 13.472J §8.2.3) within the pieces between the multiple knots of c (the
// boundaries of a refit): each piece, clamped there by raising the knot to multiplicity p, is
// faired on its own with its end control values fixed (p of them at the seam, c + 1 at a boundary
// of continuity C^c, which keeps s … s^(c) there), and the knots are lowered back to their
// multiplicity by exact removal. The pieces do not overlap, so each may move by the whole
// tolerance; each pass fairs the largest jump of any piece, so max_passes counts over the whole
// curve.
CurveFairing farin_fair_pieces(const BSpline& c, const FairingOptions& o) {
  const int p = c.degree();
  std::vector<Breakpoint> splits;
  for (const Breakpoint& b : breakpoints(c.knots()))
    if (b.value > c.front() && b.value < c.back() && b.multiplicity > 1) splits.push_back(b);
  BSpline refined = c;
  for (const Breakpoint& b : splits) refined = insert_knot(refined, b.value, p - b.multiplicity);
  const Knots& U = refined.knots();
  Eigen::MatrixXd coefs = refined.coefs();
  CurveFairing out{c, {}, 0.0};
  // Piece ends: the domain's ends (p fixed values) and the splits (continuity p − multiplicity).
  std::vector<std::pair<double, int>> ends{{c.front(), p}};
  for (const Breakpoint& b : splits) ends.emplace_back(b.value, p - b.multiplicity + 1);
  ends.emplace_back(c.back(), p);
  struct Piece {
    BSpline spline;
    int first;     // its first control value in `refined`
    int fixed;     // end control values kept
    double bound;  // Σ of its Farin bounds so far
    bool done;
  };
  std::vector<Piece> pieces;
  for (std::size_t k = 0, first = 0; k + 1 < ends.size(); ++k) {
    const double a = ends[k].first, b = ends[k + 1].first;
    std::vector<double> inner;
    for (double u : U)
      if (u > a && u < b) inner.push_back(u);
    const Eigen::Index count = static_cast<Eigen::Index>(inner.size()) + p + 1;
    pieces.push_back({BSpline(p, clamped_knots(p, a, b, inner),
                              coefs.middleCols(static_cast<Eigen::Index>(first), count)),
                      static_cast<int>(first), std::max(ends[k].second, ends[k + 1].second), 0.0,
                      false});
    first += static_cast<std::size_t>(count) - 1;
  }
  // Each pass fairs the largest jump any piece can fair (Farin's rule over the whole curve).
  for (int pass = 0; pass < o.max_passes; ++pass) {
    std::size_t best = pieces.size();
    CurveFairing best_step;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      if (pieces[k].done) continue;
      FairingOptions po = o;
      po.max_passes = 1;
      po.fixed_end_points = pieces[k].fixed;
      po.tolerance = o.tolerance - pieces[k].bound;
      CurveFairing f = po.tolerance > 0 ? farin_fair(pieces[k].spline, po) : CurveFairing{};
      if (f.steps.empty()) {
        pieces[k].done = true;
        continue;
      }
      if (best == pieces.size() || f.steps[0].jump_before > best_step.steps[0].jump_before)
        best = k, best_step = std::move(f);
    }
    if (best == pieces.size()) break;
    pieces[best].spline = best_step.spline;
    pieces[best].bound += best_step.total_bound;
    out.steps.push_back(best_step.steps[0]);
  }
  for (const Piece& piece : pieces) {
    coefs.middleCols(piece.first, piece.spline.size()) = piece.spline.coefs();
    out.total_bound = std::max(out.total_bound, piece.bound);
  }
  out.spline = BSpline(p, U, coefs);
  for (const Breakpoint& b : splits) {
    if (b.multiplicity == p) continue;
    const double tol = 1e-9 * (1.0 + coefs.cwiseAbs().maxCoeff());
    out.spline = remove_knot(out.spline, b.value, p - b.multiplicity, tol).spline;
  }
  return out;
}

}  // namespace

// Refit along the recovered design (segmented_displacement.h), then MIT 13.472J §8.2.3
// (8.19)–(8.33) on s(θ) within its pieces.
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
  r.max_jump_before = max_top_derivative_jump(s0);
  BSpline start = s0;
  if (options.method == FairingMethod::farin) {
    try {
      const RecoveredDesign design = recover_design(scan);
      SegmentedDisplacementOptions so;
      so.degree = s0.degree();
      SegmentedDisplacement refit =
          fit_segmented_displacement(scan.samples, displacement_pieces(design), so);
      const double moved = max_difference(refit.height.spline(), s0);
      if (!refit.discrepancy_met) {
        // Even the least penalty leaves more than n·σ̂² (the pieces do not fit, or σ̂ is low):
        // smoothing to the discrepancy is not defined.
        r.refit_skipped =
            "the refit along the recovered design cannot reach the discrepancy "
            "n·σ̂²: its residual is " +
            std::to_string(refit.rss) + " mm² against " + std::to_string(refit.target_rss) + " mm²";
      } else if (moved < r.tolerance) {
        start = refit.height.spline();
        r.refit_deviation = moved;
        r.refit = std::move(refit);
      } else {
        r.refit_skipped = "the refit along the recovered design moves s by " +
                          std::to_string(moved) + " mm, beyond the tolerance";
      }
    } catch (const InputError& e) {
      r.refit_skipped = e.what();
    } catch (const NumericalError& e) {
      r.refit_skipped = e.what();
    }
  }
  FairingOptions o;
  o.tolerance = r.tolerance - r.refit_deviation;
  o.max_passes = options.max_passes;
  o.fixed_end_points = start.degree();
  CurveFairing f = options.method == FairingMethod::farin ? farin_fair_pieces(start, o)
                                                          : kjellander_fair_spline(start, o);
  r.steps = std::move(f.steps);
  r.max_jump_after = max_simple_knot_jump(f.spline);
  r.measured_deviation = max_difference(f.spline, s0);
  scan.displacement.height = BSplineFunction(std::move(f.spline));
  return r;
}

}  // namespace polarform
