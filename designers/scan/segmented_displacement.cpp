#include "designers/scan/segmented_displacement.h"

#include <Eigen/Cholesky>
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
constexpr double kSnap = 0.25;            // a break this many spans from a uniform knot moves on it

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

// Gauss–Legendre nodes and weights on [−1, 1], 4 points: exact for the degree-2(p−3) integrand of
// ∫s‴² on a quintic's span.
constexpr double kGaussX[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                               0.8611363115940526};
constexpr double kGaussW[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                               0.3478548451374538};

}  // namespace

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
    if (r.segmentation.is_dwell[k] && arrive < leave) {
      out.breaks.push_back({wrap(arrive), c_arrive});
      out.breaks.push_back({wrap(leave), c_leave});
      out.dwells.emplace_back(wrap(arrive), wrap(leave));
    } else {
      out.breaks.push_back({wrap(0.5 * (arrive + leave)), std::min(c_arrive, c_leave)});
    }
  }
  std::sort(
      out.breaks.begin(), out.breaks.end(),
      [](const DisplacementBreak& a, const DisplacementBreak& b) { return a.theta < b.theta; });
  return out;
}

SegmentedDisplacement fit_segmented_displacement(const FollowerSamples& s,
                                                 const DisplacementPieces& pieces, double noise,
                                                 const SegmentedDisplacementOptions& o) {
  const int p = o.degree;
  if (p < 3 || p > 9 || o.spans < p + 1)
    throw InputError("segmented displacement: degree " + std::to_string(p) + " and " +
                     std::to_string(o.spans) + " spans; expected 3–9 and more spans than it");
  if (!(noise > 0)) throw InputError("segmented displacement: the noise σ̂ must be positive");
  const Eigen::Index n = s.theta.size();
  if (n < 2 * o.spans)
    throw InputError("segmented displacement: " + std::to_string(n) + " samples for " +
                     std::to_string(o.spans) + " spans; expected at least two per span");
  // The uniform grid; a break within kSnap spans of a grid value moves onto it (index 0 and
  // `spans` both mean the seam).
  const double h = kTwoPi / o.spans;
  std::vector<double> grid(static_cast<std::size_t>(o.spans) + 1);
  for (int k = 0; k <= o.spans; ++k) grid[static_cast<std::size_t>(k)] = k * h;
  grid.back() = kTwoPi;
  const auto snap = [&](double a) {
    const double t = wrap(a);
    const long k = std::lround(t / h);
    if (std::abs(t - k * h) < kSnap * h)
      return k >= o.spans ? 0.0 : grid[static_cast<std::size_t>(k)];
    return t;
  };
  // Interior knot value → the lowest continuity asked there.
  std::vector<std::pair<double, int>> at;
  int seam = p - 1;
  for (const DisplacementBreak& b : pieces.breaks) {
    const double t = snap(b.theta);
    const int c = std::clamp(b.continuity, 0, p - 1);
    if (t == 0.0) {
      seam = std::min(seam, c);
      continue;
    }
    auto it = std::find_if(at.begin(), at.end(), [&](const auto& e) { return e.first == t; });
    if (it == at.end())
      at.emplace_back(t, c);
    else
      it->second = std::min(it->second, c);
  }
  std::vector<double> interior;
  for (int k = 1; k < o.spans; ++k)
    if (std::none_of(at.begin(), at.end(),
                     [&](const auto& e) { return e.first == grid[static_cast<std::size_t>(k)]; }))
      interior.push_back(grid[static_cast<std::size_t>(k)]);
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
    const double a = snap(start), b = snap(end);               // b <= a: the dwell holds the seam
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
    for (int g = 0; g < 4; ++g) {
      const Eigen::MatrixXd d = ders_basis_funs(j, mid + half * kGaussX[g], p, m, U);
      const Eigen::VectorXd dm = d.row(m).transpose();
      P.block(j - p, j - p, p + 1, p + 1) += half * kGaussW[g] * dm * dm.transpose();
    }
  }
  const Eigen::MatrixXd M = Z.transpose() * BtB * Z, Q = Z.transpose() * P * Z;
  const Eigen::VectorXd g = Z.transpose() * Bty;
  const double scale = M.trace() / std::max(Q.trace(), 1e-300);

  struct Solved {
    Eigen::VectorXd x;
    double rss;
  };
  const auto solve = [&](double lambda) {
    Eigen::LDLT<Eigen::MatrixXd> f(M + lambda * Q);
    Solved r{f.solve(g), 0.0};
    r.rss = std::max(0.0, yty - 2.0 * r.x.dot(g) + r.x.dot(M * r.x));
    return r;
  };
  SegmentedDisplacement out;
  out.target_rss = static_cast<double>(n) * noise * noise;
  out.dwells = dwells;
  out.breaks = at.size() + (seam < p - 1 ? 1 : 0);
  // RSS(λ) increases with λ: bisect log λ for RSS = n·σ̂².
  double lo = -14.0, hi = 10.0;
  if (solve(scale * std::pow(10.0, lo)).rss >= out.target_rss) {
    hi = lo;
  } else if (solve(scale * std::pow(10.0, hi)).rss <= out.target_rss) {
    lo = hi;
  } else {
    out.discrepancy_met = true;
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (lo + hi);
      (solve(scale * std::pow(10.0, mid)).rss < out.target_rss ? lo : hi) = mid;
    }
  }
  out.lambda = scale * std::pow(10.0, 0.5 * (lo + hi));
  const Solved best = solve(out.lambda);
  out.rss = best.rss;
  Eigen::LDLT<Eigen::MatrixXd> f(M + out.lambda * Q);
  out.dof = f.solve(M).trace();
  out.height = BSplineFunction(p, U, (Z * best.x).array() + mean);
  return out;
}

}  // namespace polarform
