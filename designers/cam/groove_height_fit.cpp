#include "designers/cam/groove_height_fit.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/number_text.h"
#include "src/nurbs/basis.h"

namespace polarform {

namespace {

constexpr int kDegreeU = 5, kDegreeV = 3;
constexpr int kFitPerSpan = 6, kCheckPerSpan = 8;
constexpr int kMaxRounds = 16, kMaxSpansU = 4000, kMaxSpansV = 32;

// Samples (k + offset)/per of every span between consecutive breaks, plus the last break when
// offset is 0.
std::vector<double> span_samples(const std::vector<double>& breaks, int per, double offset) {
  std::vector<double> out;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
    for (int k = 0; k < per; ++k)
      out.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * (k + offset) / per);
  if (offset == 0.0) out.push_back(breaks.back());
  return out;
}

// Collocation matrix N_j(x_k) of a clamped basis (NURBS Book A2.2).
Eigen::MatrixXd collocation(int p, const Knots& U, const std::vector<double>& x) {
  const int n = static_cast<int>(U.size()) - p - 1;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(x.size()), n);
  double N[kMaxDegree + 1];
  for (std::size_t k = 0; k < x.size(); ++k) {
    const int span = find_span(p, U, n, x[k]);
    basis_funs(span, x[k], p, U, N);
    for (int j = 0; j <= p; ++j) A(static_cast<Eigen::Index>(k), span - p + j) = N[j];
  }
  return A;
}

// u knots: multiplicity p at the arc junctions (C0), simple at the span breaks inside the arcs.
Knots u_knots(const std::vector<double>& spans, const std::vector<double>& arcs) {
  std::vector<double> interior;
  for (std::size_t i = 1; i + 1 < spans.size(); ++i) {
    const bool junction = std::find(arcs.begin(), arcs.end(), spans[i]) != arcs.end();
    interior.insert(interior.end(), junction ? kDegreeU : 1, spans[i]);
  }
  return clamped_knots(kDegreeU, spans.front(), spans.back(), interior);
}

struct Grid {
  std::vector<double> u, v;
  Eigen::MatrixXd values;  // values(i, j) = h(angle(u_i), v_j)
};

Grid sample(const std::function<double(double, double)>& h, const BaseCircle& base,
            std::vector<double> u, std::vector<double> v) {
  Grid g{std::move(u), std::move(v), {}};
  g.values.resize(static_cast<Eigen::Index>(g.u.size()), static_cast<Eigen::Index>(g.v.size()));
  for (std::size_t i = 0; i < g.u.size(); ++i) {
    const double psi = base.angle(g.u[i]);
    for (std::size_t j = 0; j < g.v.size(); ++j)
      g.values(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = h(psi, g.v[j]);
  }
  return g;
}

// Least squares on the tensor grid, separable: C = A_u⁺ G (A_v⁺)ᵀ; the first u column absorbs the
// last, so both seam rows share their coefficients (Bae 2002, eq. (3.9) for G0).
BSplineSurface fit(const Grid& g, const Knots& U, const Knots& V) {
  Eigen::MatrixXd Au = collocation(kDegreeU, U, g.u);
  const Eigen::Index nu = Au.cols();
  Au.col(0) += Au.col(nu - 1);
  const Eigen::MatrixXd Av = collocation(kDegreeV, V, g.v);
  const Eigen::MatrixXd X = Au.leftCols(nu - 1).colPivHouseholderQr().solve(g.values);
  const Eigen::MatrixXd C = Av.colPivHouseholderQr().solve(X.transpose()).transpose();
  const Eigen::Index nv = C.cols();
  Eigen::MatrixXd coefs(1, nu * nv);
  for (Eigen::Index i = 0; i < nu; ++i) coefs.middleCols(i * nv, nv) = C.row(i == nu - 1 ? 0 : i);
  return BSplineSurface(kDegreeU, kDegreeV, U, V, std::move(coefs));
}

// The uniform ρ spans (1, 2, 4, …) with which cubic least-squares fits of h(ψ, ·) at 64 angles
// meet `goal` between their samples: the radial direction is smooth and short, so it is settled
// once and the u direction refined against the rest of the budget.
int radial_spans(const std::function<double(double, double)>& h, const BaseCircle& base,
                 double rho0, double rho1, double goal) {
  const std::vector<double> angles =
      span_samples({base.parameters().front(), base.parameters().back()}, 64, 0.5);
  for (int n = 1;; n *= 2) {
    std::vector<double> vb;
    for (int k = 0; k <= n; ++k) vb.push_back(rho0 + (rho1 - rho0) * k / n);
    const Knots V =
        clamped_knots(kDegreeV, rho0, rho1, std::vector<double>(vb.begin() + 1, vb.end() - 1));
    const std::vector<double> fv = span_samples(vb, kFitPerSpan, 0.0),
                              cv = span_samples(vb, kCheckPerSpan, 0.5);
    const Grid g = sample(h, base, angles, fv), c = sample(h, base, angles, cv);
    const Eigen::MatrixXd coefs =
        collocation(kDegreeV, V, fv).colPivHouseholderQr().solve(g.values.transpose());
    const double e =
        (collocation(kDegreeV, V, cv) * coefs - c.values.transpose()).cwiseAbs().maxCoeff();
    if (e <= goal || n >= kMaxSpansV) return n;
  }
}

}  // namespace

HeightFit fit_groove_height(const std::function<double(double, double)>& h, const BaseCircle& base,
                            double rho0, double rho1, double target) {
  if (!base.closed()) throw InputError("groove height: the base circle must be closed");
  if (!(rho0 < rho1) || !(target > 0)) throw InputError("groove height: bad radii or target");
  const std::vector<double>& arcs = base.parameters();
  const double u0 = arcs.front(), u1 = arcs.back();

  // A constant height (zero lift) is exactly a degree-(0, 0) function.
  const Grid probe =
      sample(h, base, span_samples(arcs, kFitPerSpan, 0.0), {rho0, 0.5 * (rho0 + rho1), rho1});
  if (probe.values.maxCoeff() == probe.values.minCoeff())
    return {BSplineSurface(0, 0, {u0, u1}, {rho0, rho1},
                           Eigen::MatrixXd::Constant(1, 1, probe.values(0, 0))),
            0.0, true};

  std::vector<double> spans;  // four spans per arc to start
  for (std::size_t a = 0; a + 1 < arcs.size(); ++a)
    for (int k = 0; k < 4; ++k) spans.push_back(arcs[a] + (arcs[a + 1] - arcs[a]) * k / 4);
  spans.push_back(u1);
  const int v_spans = radial_spans(h, base, rho0, rho1, 0.25 * target);

  for (int round = 0;; ++round) {
    std::vector<double> vb;
    for (int k = 0; k <= v_spans; ++k) vb.push_back(rho0 + (rho1 - rho0) * k / v_spans);
    const Knots U = u_knots(spans, arcs);
    const Knots V =
        clamped_knots(kDegreeV, rho0, rho1, std::vector<double>(vb.begin() + 1, vb.end() - 1));
    const BSplineSurface Z = fit(
        sample(h, base, span_samples(spans, kFitPerSpan, 0.0), span_samples(vb, kFitPerSpan, 0.0)),
        U, V);

    // Measure between the fitting samples; the largest error of each u span decides its split.
    std::vector<double> cu = span_samples(spans, kCheckPerSpan, 0.5),
                        cv = span_samples(vb, kCheckPerSpan, 0.5);
    cv.insert(cv.begin(), rho0);
    cv.push_back(rho1);
    const Grid check = sample(h, base, cu, cv);
    std::vector<double> eu(spans.size() - 1, 0.0);
    double worst = 0.0;
    for (std::size_t i = 0; i < cu.size(); ++i)
      for (std::size_t j = 0; j < cv.size(); ++j) {
        double z;
        Z.point(cu[i], cv[j], &z);
        const double e =
            std::abs(z - check.values(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
        const std::size_t su = i / kCheckPerSpan;
        eu[su] = std::max(eu[su], e);
        worst = std::max(worst, e);
      }
    if (worst <= target) return {Z, worst, false};
    if (round == kMaxRounds || spans.size() > kMaxSpansU)
      throw NumericalError("groove wall height: fit error " + number_text(worst) + " mm with " +
                           std::to_string(spans.size() - 1) + " x " + std::to_string(v_spans) +
                           " spans still exceeds " + number_text(target) + " mm");
    std::vector<double> next{spans.front()};
    for (std::size_t i = 0; i + 1 < spans.size(); ++i) {
      if (eu[i] > 0.5 * target) next.push_back(0.5 * (spans[i] + spans[i + 1]));
      next.push_back(spans[i + 1]);
    }
    spans = std::move(next);
  }
}

}  // namespace polarform
