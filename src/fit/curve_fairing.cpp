#include "src/fit/curve_fairing.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/nurbs/knot_insertion.h"
#include "src/nurbs/knot_removal.h"
#include "src/nurbs/knots.h"

namespace polarform {

namespace {

void check(const FairingOptions& o, const char* what) {
  if (!(o.tolerance > 0))
    throw InputError(std::string(what) + ": the fairing tolerance must be > 0");
  if (o.max_passes < 0) throw InputError(std::string(what) + ": max_passes must be >= 0");
}

double jump_at(const std::vector<SplineKnotJump>& jumps, double u) {
  for (const SplineKnotJump& j : jumps)
    if (j.u == u) return j.jump;
  return 0.0;
}

// The cubic Hermite interpolant on [a, b] of values pa, pb and tangents da, db, at t.
Eigen::VectorXd hermite(double a, double b, const Eigen::VectorXd& pa, const Eigen::VectorXd& pb,
                        const Eigen::VectorXd& da, const Eigen::VectorXd& db, double t) {
  const double h = b - a, s = (t - a) / h;
  const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
  const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
  return h00 * pa + h10 * h * da + h01 * pb + h11 * h * db;
}

}  // namespace

std::vector<SplineKnotJump> top_derivative_jumps(const BSpline& c) {
  BSpline d = c;
  for (int k = 0; k < c.degree(); ++k) d = d.derivative();  // degree 0: coefficient i on span i
  const Knots& U = d.knots();
  std::vector<SplineKnotJump> out;
  int previous = -1;  // the last non-empty span
  for (int i = 0; i < d.size(); ++i) {
    if (!(U[static_cast<std::size_t>(i + 1)] > U[static_cast<std::size_t>(i)])) continue;
    if (previous >= 0)
      out.push_back(
          {U[static_cast<std::size_t>(i)], (d.coefs().col(i) - d.coefs().col(previous)).norm()});
    previous = i;
  }
  return out;
}

double max_top_derivative_jump(const BSpline& c) {
  double m = 0.0;
  for (const SplineKnotJump& j : top_derivative_jumps(c)) m = std::max(m, j.jump);
  return m;
}

CurveFairing farin_fair(const BSpline& c, const FairingOptions& o, int point_dim) {
  check(o, "farin_fair");
  CurveFairing r{c, {}, 0.0};
  const std::vector<SplineKnotJump> initial = top_derivative_jumps(c);
  double largest = 0.0;
  for (const SplineKnotJump& j : initial) largest = std::max(largest, j.jump);
  for (int pass = 0; pass < o.max_passes; ++pass) {
    std::vector<SplineKnotJump> jumps = top_derivative_jumps(r.spline);
    std::sort(jumps.begin(), jumps.end(),
              [](const SplineKnotJump& a, const SplineKnotJump& b) { return a.jump > b.jump; });
    bool faired = false;
    for (const SplineKnotJump& j : jumps) {
      if (j.jump <= o.negligible_jump * largest) break;
      if (multiplicity(r.spline.knots(), j.u) != 1) continue;
      const Knots& U = r.spline.knots();
      const int at = static_cast<int>(std::find(U.begin(), U.end(), j.u) - U.begin());
      const int p = r.spline.degree();
      if (at - p < o.fixed_end_points || at - 1 > r.spline.size() - 1 - o.fixed_end_points)
        continue;  // P_{at−p}..P_{at−1} move
      const LeastSquaresRemoval removal = remove_knot_least_squares(r.spline, j.u, point_dim);
      if (r.total_bound + removal.bound > o.tolerance) continue;
      const BSpline next = insert_knot(removal.spline, j.u, 1);
      r.steps.push_back({j.u, j.jump, jump_at(top_derivative_jumps(next), j.u), removal.bound});
      r.total_bound += removal.bound;
      r.spline = next;
      faired = true;
      break;
    }
    if (!faired) break;
  }
  return r;
}

KjellanderFairing kjellander_fair(const Eigen::MatrixXd& values, const Eigen::VectorXd& t,
                                  const FairingOptions& o, const CubicEnds& ends) {
  check(o, "kjellander_fair");
  const int N = static_cast<int>(values.cols());
  if (N < 5) throw InputError("kjellander_fair: " + std::to_string(N) + " points, expected >= 5");
  KjellanderFairing r{interpolate_cubic(values, t, ends), values, {}, 0.0};
  const std::vector<SplineKnotJump> initial = top_derivative_jumps(r.spline);
  double largest = 0.0;
  for (const SplineKnotJump& j : initial) largest = std::max(largest, j.jump);
  for (int pass = 0; pass < o.max_passes; ++pass) {
    // The interior data point (knot t_J, 1 <= J <= N−2) with the largest jump.
    const std::vector<SplineKnotJump> jumps = top_derivative_jumps(r.spline);
    int J = -1;
    double worst = 0.0;
    for (int k = 1; k + 1 < N; ++k) {
      const double jk = jump_at(jumps, t[k]);
      if (jk > worst) worst = jk, J = k;
    }
    if (J < 0 || worst <= o.negligible_jump * largest) break;
    const Eigen::MatrixXd d0 = r.spline.derivatives(t[J - 1], 1),
                          d1 = r.spline.derivatives(t[J + 1], 1);
    const Eigen::VectorXd moved = hermite(t[J - 1], t[J + 1], r.values.col(J - 1),
                                          r.values.col(J + 1), d0.col(1), d1.col(1), t[J]);
    const double from_original = (moved - values.col(J)).norm();
    if (from_original > o.tolerance) break;
    const double move = (moved - r.values.col(J)).norm();
    r.values.col(J) = moved;
    r.spline = interpolate_cubic(r.values, t, ends);
    r.steps.push_back({t[J], worst, jump_at(top_derivative_jumps(r.spline), t[J]), move});
    r.max_data_move = std::max(r.max_data_move, from_original);
  }
  return r;
}

// MIT 13.472J §8.2.3 (8.15)–(8.18) on the spline's own breakpoint values.
CurveFairing kjellander_fair_spline(const BSpline& F, const FairingOptions& o) {
  if (F.degree() != 3)
    throw InputError("--fair kjellander: F has degree " + std::to_string(F.degree()) +
                     "; Kjellander's fairing interpolates cubics (use --fair farin, or degree 3)");
  std::vector<double> t;
  for (const Breakpoint& b : breakpoints(F.knots())) {
    if (b.value > F.front() && b.value < F.back() && b.multiplicity != 1)
      throw InputError("--fair kjellander: F has a multiple knot at u = " +
                       std::to_string(b.value) + "; use --fair farin");
    t.push_back(b.value);
  }
  if (t.size() < 5) return {F, {}, 0.0};  // too few breakpoints to move one
  const Eigen::VectorXd params =
      Eigen::Map<const Eigen::VectorXd>(t.data(), static_cast<Eigen::Index>(t.size()));
  Eigen::MatrixXd values(F.dim(), params.size());
  for (Eigen::Index k = 0; k < params.size(); ++k) values.col(k) = F.point(params[k]);
  CubicEnds ends;
  ends.start_tangent = F.derivatives(F.front(), 1).col(1);
  ends.end_tangent = F.derivatives(F.back(), 1).col(1);
  KjellanderFairing k = kjellander_fair(values, params, o, ends);
  return {std::move(k.spline), std::move(k.steps), k.max_data_move};
}

SurfaceFairing farin_fair_surface_u(const BSplineSurface& s, const FairingOptions& o) {
  const CurveFairing f = farin_fair(s.along_u(), o, s.dim());
  return {BSplineSurface::from_along_u(f.spline, s.degree_v(), s.knots_v(), s.dim()), f.steps,
          f.total_bound};
}

SurfaceFairing farin_fair_surface_v(const BSplineSurface& s, const FairingOptions& o) {
  const CurveFairing f = farin_fair(s.along_v(), o, s.dim());
  return {BSplineSurface::from_along_v(f.spline, s.degree_u(), s.knots_u(), s.dim()), f.steps,
          f.total_bound};
}

}  // namespace polarform
