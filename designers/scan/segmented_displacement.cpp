#include "designers/scan/segmented_displacement.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "src/error.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/knots.h"

namespace polarform {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kZeroDerivative = 1e-9;  // |S^(k)| of a normalised law at an end that is zero
constexpr double kSnap = 0.25;            // a uniform knot this many spans from a break is left out
constexpr double kOnKnot = 0.05;  // a break this many spans from a uniform knot is put on it
constexpr double kBreakZ = 3.0;   // … or this many of its standard deviations

double wrap(double a) {
  const double t = std::fmod(a, kTwoPi);
  return t < 0 ? t + kTwoPi : t;
}

// a + 2πk nearest to `near` (as design_recovery.cpp joins the fitted ends).
double nearest_turn(double a, double near) { return a + kTwoPi * std::round((near - a) / kTwoPi); }

// The continuity of a law with a dwell at its start (x = 0) or end (x = 1): C2 when S′ and S″
// vanish there, C1 when S′ does.
int end_continuity(const LawShape& shape, double x) {
  double d[3];
  law_shape_derivatives(shape, x, d);
  if (std::abs(d[1]) > kZeroDerivative) return 0;
  return std::abs(d[2]) > kZeroDerivative ? 1 : 2;
}

// Gauss–Legendre nodes and weights on [−1, 1], 7 points: exact for the degree-2(p−3) integrand of
// ∫s‴² on a span up to degree 9.
constexpr int kGauss = 7;
constexpr double kGaussX[kGauss] = {
    -0.9491079123427585, -0.7415311855993945, -0.4058451513773972, 0.0,
    0.4058451513773972,  0.7415311855993945,  0.9491079123427585};
constexpr double kGaussW[kGauss] = {0.1294849661688697, 0.2797053914892766, 0.3818300505051189,
                                    0.4179591836734694, 0.3818300505051189, 0.2797053914892766,
                                    0.1294849661688697};

}  // namespace

// The boundaries as design_recovery.cpp joins the fitted laws (law_fit.h for their ends).
DisplacementPieces displacement_pieces(const RecoveredDesign& r) {
  DisplacementPieces out;
  const std::size_t n = r.motions.size();
  for (std::size_t k = 0; k < n; ++k) {
    const DwellRun& anchor = r.segmentation.anchors[k];
    const LawFit& before = r.motions[(k + n - 1) % n].law();
    const LawFit& after = r.motions[k].law();
    const double arrive = nearest_turn(before.end, anchor.start);
    const double leave = nearest_turn(after.start, anchor.end);
    const int c_arrive = end_continuity(before.shape, 1.0);
    const int c_leave = end_continuity(after.shape, 0.0);
    const double sd_arrive = before.sd.size() > 1 ? before.sd[1] : 0.0;
    const double sd_leave = after.sd.size() > 0 ? after.sd[0] : 0.0;
    if (r.segmentation.is_dwell[k] && arrive < leave) {
      out.breaks.push_back({wrap(arrive), c_arrive, sd_arrive});
      out.breaks.push_back({wrap(leave), c_leave, sd_leave});
      out.dwells.emplace_back(wrap(arrive), wrap(leave));
    } else {
      // The mean of the two ends: its variance is a quarter of the sum of theirs, and it is at
      // least half their difference from either.
      out.breaks.push_back(
          {wrap(0.5 * (arrive + leave)), std::min(c_arrive, c_leave),
           std::max(0.5 * std::hypot(sd_arrive, sd_leave), 0.5 * std::abs(leave - arrive))});
    }
  }
  std::sort(
      out.breaks.begin(), out.breaks.end(),
      [](const DisplacementBreak& a, const DisplacementBreak& b) { return a.theta < b.theta; });
  return out;
}

// Morozov 1966 on the smoothing spline λ∫s‴² (Wahba 1990, §1.2), GCV σ̂ (Craven & Wahba 1979).
SegmentedDisplacement fit_segmented_displacement(const FollowerSamples& s,
                                                 const DisplacementPieces& pieces,
                                                 const SegmentedDisplacementOptions& o) {
  const int p = o.degree;
  if (p < 3 || p > 9 || o.spans < p + 1)
    throw InputError("segmented displacement: degree " + std::to_string(p) + " and " +
                     std::to_string(o.spans) + " spans; expected 3–9 and more spans than it");
  const Eigen::Index n = s.theta.size();
  if (n < 2 * o.spans)
    throw InputError("segmented displacement: " + std::to_string(n) + " samples for " +
                     std::to_string(o.spans) + " spans; expected at least two per span");
  // The uniform knots, less any within kSnap spans of a break (no sliver spans); the breaks stay
  // where the design put them, except within kOnKnot spans or 3 standard deviations of a uniform
  // knot (θ = 0: the seam), where they go on it, and two breaks within half a span, which join at
  // the first.
  const double h = kTwoPi / o.spans;
  std::vector<DisplacementBreak> sorted = pieces.breaks;
  for (DisplacementBreak& b : sorted) b.theta = wrap(b.theta);
  std::sort(
      sorted.begin(), sorted.end(),
      [](const DisplacementBreak& a, const DisplacementBreak& b) { return a.theta < b.theta; });
  std::vector<std::pair<double, int>> at;         // knot value, the lowest continuity asked there
  std::vector<std::pair<double, double>> placed;  // a break's angle → its knot (0: the seam)
  int seam = p - 1;
  for (const DisplacementBreak& b : sorted) {
    // A uniform knot within kBreakZ standard deviations of the break: the data cannot tell them
    // apart, and the break goes on it.
    const double slack = std::max(kOnKnot * h, kBreakZ * b.sd);
    const double k = std::round(b.theta / h);
    const double t = std::abs(b.theta - k * h) <= slack ? (k >= o.spans ? 0.0 : k * h) : b.theta;
    const int c = std::clamp(b.continuity, 0, p - 1);
    if (t == 0.0) {
      seam = std::min(seam, c);
      placed.emplace_back(b.theta, 0.0);
    } else if (!at.empty() && t - at.back().first < 0.5 * h) {
      at.back().second = std::min(at.back().second, c);
      placed.emplace_back(b.theta, at.back().first);
    } else {
      at.emplace_back(t, c);
      placed.emplace_back(b.theta, t);
    }
  }
  const auto place = [&](double a) {
    const double t = wrap(a);
    for (const auto& [from, to] : placed)
      if (from == t) return to;
    return t;
  };
  std::vector<double> interior;
  for (int k = 1; k < o.spans; ++k) {
    const double u = k * h;
    if (std::none_of(at.begin(), at.end(),
                     [&](const auto& e) { return std::abs(e.first - u) < kSnap * h; }))
      interior.push_back(u);
  }
  for (const auto& [t, c] : at)
    for (int m = 0; m < p - c; ++m) interior.push_back(t);
  std::sort(interior.begin(), interior.end());
  const Knots U = clamped_knots(p, 0.0, kTwoPi, interior);
  const int N = static_cast<int>(U.size()) - p - 1;

  // Linear constraints C·c = 0: tied control values over each dwell, periodicity at the seam.
  std::vector<Eigen::RowVectorXd> rows;
  std::size_t dwells = 0;
  const auto tie = [&](double a, double b) {
    if (!(b > a)) return;
    int lo = N, hi = -1;
    for (int j = p; j < N; ++j)
      if (U[j + 1] > U[j] && U[j] >= a && U[j + 1] <= b) lo = std::min(lo, j - p), hi = j;
    for (int i = lo; i < hi; ++i) {
      Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(N);
      r[i] = 1.0, r[i + 1] = -1.0;
      rows.push_back(r);
    }
  };
  for (const auto& [start, end] : pieces.dwells) {
    const double a = place(start), b = place(end);             // b <= a: the dwell holds the seam
    if ((b > a ? b - a : b + kTwoPi - a) < 0.5 * h) continue;  // a joint, not a dwell
    ++dwells;
    if (b > a) {
      tie(a, b);
    } else {
      tie(a, kTwoPi);
      tie(0.0, b);
    }
  }
  {
    const Eigen::MatrixXd d0 = ders_basis_funs(p, 0.0, p, seam, U);
    const Eigen::MatrixXd d1 = ders_basis_funs(N - 1, kTwoPi, p, seam, U);
    for (int k = 0; k <= seam; ++k) {
      Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(N);
      r.head(p + 1) += d0.row(k);
      r.tail(p + 1) -= d1.row(k);
      rows.push_back(r / r.cwiseAbs().maxCoeff());
    }
  }
  Eigen::MatrixXd C(static_cast<Eigen::Index>(rows.size()), N);
  for (std::size_t i = 0; i < rows.size(); ++i) C.row(static_cast<Eigen::Index>(i)) = rows[i];
  Eigen::BDCSVD<Eigen::MatrixXd> svd(C, Eigen::ComputeFullV);
  const Eigen::VectorXd sv = svd.singularValues();
  Eigen::Index rank = 0;
  while (rank < sv.size() && sv[rank] > 1e-10 * sv[0]) ++rank;
  const Eigen::MatrixXd Z = svd.matrixV().rightCols(N - rank);  // c = Z·x

  // Normal equations and the penalty ∫s‴² (s^(m), m = 3: the quintic smoothing spline).
  const int m = std::min(3, p);
  Eigen::MatrixXd BtB = Eigen::MatrixXd::Zero(N, N), P = Eigen::MatrixXd::Zero(N, N);
  Eigen::VectorXd Bty = Eigen::VectorXd::Zero(N);
  // The data about their mean (a constant is in the space, unpenalised): RSS keeps its digits.
  const double mean = s.height.mean();
  double yty = 0.0;
  std::vector<double> Nb(static_cast<std::size_t>(p) + 1);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double t = wrap(s.theta[k]);
    const int span = find_span(p, U, N, t);
    basis_funs(span, t, p, U, Nb.data());
    const double y = s.height[k] - mean;
    yty += y * y;
    for (int i = 0; i <= p; ++i) {
      Bty[span - p + i] += Nb[static_cast<std::size_t>(i)] * y;
      for (int j = 0; j <= p; ++j)
        BtB(span - p + i, span - p + j) +=
            Nb[static_cast<std::size_t>(i)] * Nb[static_cast<std::size_t>(j)];
    }
  }
  for (int j = p; j < N; ++j) {
    if (!(U[j + 1] > U[j])) continue;
    const double half = 0.5 * (U[j + 1] - U[j]), mid = 0.5 * (U[j + 1] + U[j]);
    for (int g = 0; g < kGauss; ++g) {
      const Eigen::MatrixXd d = ders_basis_funs(j, mid + half * kGaussX[g], p, m, U);
      const Eigen::VectorXd dm = d.row(m).transpose();
      P.block(j - p, j - p, p + 1, p + 1) += half * kGaussW[g] * dm * dm.transpose();
    }
  }
  const Eigen::MatrixXd M = Z.transpose() * BtB * Z, Q = Z.transpose() * P * Z;
  const Eigen::VectorXd g = Z.transpose() * Bty;
  const double scale = M.trace() / std::max(Q.trace(), 1e-300);
  // Q and B = M + μQ diagonalised together (Wᵀ B W = I, Wᵀ Q W = D; Demmler & Reinsch 1975), so
  // that for every λ, with e_i = 1 + (λ − μ)d_i and b = Wᵀg: x = W diag(1/e) b,
  // tr H = Σ (1 − μd_i)/e_i and RSS = yᵀy − Σ (2/e_i − (1 − μd_i)/e_i²) b_i².
  const double mu = scale;
  const Eigen::MatrixXd B = M + mu * Q;
  // B singular: a direction neither the samples nor the penalty see.
  if (Eigen::LLT<Eigen::MatrixXd>(B).info() != Eigen::Success)
    throw NumericalError("segmented displacement: the penalised system is singular");
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(Q, B);
  if (eig.info() != Eigen::Success)
    throw NumericalError("segmented displacement: the penalised system is singular");
  const Eigen::VectorXd d = eig.eigenvalues().cwiseMax(0.0);
  // A clearly negative eigenvalue: B is too ill-conditioned for the eigenvectors to be trusted.
  if (eig.eigenvalues().minCoeff() < -1e-9 * eig.eigenvalues().maxCoeff())
    throw NumericalError("segmented displacement: the penalised system is ill-conditioned");
  const Eigen::MatrixXd& W = eig.eigenvectors();
  const Eigen::VectorXd bw = W.transpose() * g;
  // RSS(λ) and tr H(λ).
  const auto rss_dof = [&](double lambda, double& dof) {
    double rss = yty;
    dof = 0.0;
    for (Eigen::Index i = 0; i < d.size(); ++i) {
      const double keep = std::max(0.0, 1.0 - mu * d[i]), e = keep + lambda * d[i];
      if (!(e > 0)) continue;
      dof += keep / e;
      rss -= (2.0 / e - keep / (e * e)) * bw[i] * bw[i];
    }
    return std::max(0.0, rss);
  };
  const auto at_log = [&](double t) { return scale * std::pow(10.0, t); };
  SegmentedDisplacement out;
  out.dwells = dwells;
  out.breaks = at.size() + (seam < p - 1 ? 1 : 0);
  const double nn = static_cast<double>(n);
  // GCV(λ) = n·RSS / (n − tr H)² on a grid of log λ, refined by golden section about its least.
  const auto gcv = [&](double t) {
    double dof;
    const double rss = rss_dof(at_log(t), dof);
    return nn * rss / ((nn - dof) * (nn - dof));
  };
  double best_t = -14.0, best_g = gcv(best_t);
  for (double t = -13.75; t <= 10.0; t += 0.25)
    if (const double v = gcv(t); v < best_g) best_g = v, best_t = t;
  {
    constexpr double kGolden = 0.6180339887498949;
    double lo = best_t - 0.25, hi = best_t + 0.25;
    for (int it = 0; it < 40; ++it) {
      const double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
      if (gcv(x1) < gcv(x2))
        hi = x2;
      else
        lo = x1;
    }
    if (gcv(0.5 * (lo + hi)) < best_g) best_t = 0.5 * (lo + hi);
  }
  double gcv_dof;
  const double gcv_rss = rss_dof(at_log(best_t), gcv_dof);
  out.gcv_lambda = at_log(best_t);
  out.gcv_dof = gcv_dof;
  out.noise = std::sqrt(gcv_rss / std::max(1.0, nn - gcv_dof));
  out.target_rss = nn * out.noise * out.noise;
  // RSS(λ) increases with λ: bisect log λ for RSS = n·σ̂².
  double lo = -14.0, hi = 10.0, dof;
  if (rss_dof(at_log(lo), dof) >= out.target_rss) {
    hi = lo;
  } else if (rss_dof(at_log(hi), dof) <= out.target_rss) {
    lo = hi;
  } else {
    out.discrepancy_met = true;
    for (int it = 0; it < 100; ++it) {
      const double mid = 0.5 * (lo + hi);
      (rss_dof(at_log(mid), dof) < out.target_rss ? lo : hi) = mid;
    }
  }
  out.lambda = at_log(0.5 * (lo + hi));
  out.rss = rss_dof(out.lambda, out.dof);
  const Eigen::VectorXd e =
      (Eigen::VectorXd::Ones(d.size()) - mu * d).cwiseMax(0.0) + out.lambda * d;
  const Eigen::VectorXd x = W * bw.cwiseQuotient(e);
  out.height = BSplineFunction(p, U, (Z * x).array() + mean);
  return out;
}

}  // namespace polarform
