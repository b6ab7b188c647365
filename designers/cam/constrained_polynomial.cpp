#include "designers/cam/constrained_polynomial.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "src/error.h"
#include "src/number_text.h"
#include "src/nurbs/binomial.h"

namespace polarform {
namespace {

// The k-th derivative at x of the n + 1 Bernstein polynomials of degree n: the (n−k)-degree
// Bernstein values of the k-th forward differences, times n!/(n−k)! (Farin, Curves and Surfaces
// for CAGD, derivatives of a Bezier curve).
Eigen::RowVectorXd bernstein_derivative_row(int n, int k, double x) {
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(n + 1);
  if (k > n) return row;
  const int m = n - k;
  double scale = 1.0;
  for (int i = 0; i < k; ++i) scale *= n - i;
  for (int j = 0; j <= m; ++j) {
    const double b = binomial(m, j) * std::pow(x, j) * std::pow(1 - x, m - j);
    // Δ^k c_j = Σ_i (−1)^(k−i) C(k, i) c_{j+i}
    for (int i = 0; i <= k; ++i)
      row(j + i) += scale * b * ((k - i) % 2 ? -1.0 : 1.0) * binomial(k, i);
  }
  return row;
}

// Power-basis coefficients a = T b of the Bernstein coefficients b (Polynomial::from_bezier).
Eigen::MatrixXd bernstein_to_power(int n) {
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(n + 1, n + 1);
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k <= i; ++k)
      t(i, k) = binomial(n, i) * ((i - k) % 2 ? -1.0 : 1.0) * binomial(i, k);
  return t;
}

// ∫₀¹ S‴² dx = aᵀ H a in the power basis: H_ij = i(i−1)(i−2)·j(j−1)(j−2)/(i + j − 5), i, j >= 3.
Eigen::MatrixXd jerk_energy_power(int n) {
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(n + 1, n + 1);
  for (int i = 3; i <= n; ++i)
    for (int j = 3; j <= n; ++j)
      h(i, j) = double(i) * (i - 1) * (i - 2) * j * (j - 1) * (j - 2) / (i + j - 5);
  return h;
}

std::string counts(int given, int degree) {
  return std::to_string(given) + " constraint" + (given == 1 ? "" : "s") + " for the " +
         std::to_string(degree + 1) + " coefficients of a degree-" + std::to_string(degree) +
         " polynomial";
}

}  // namespace

ConstrainedPolynomial constrained_polynomial(int degree,
                                             std::span<const PolynomialConstraint> constraints) {
  if (degree < 1 || degree > kMaxConstrainedPolynomialDegree)
    throw InputError("polynomial degree " + std::to_string(degree) + " outside [1, " +
                     std::to_string(kMaxConstrainedPolynomialDegree) + "]");
  const int n = degree, m = static_cast<int>(constraints.size());
  for (const PolynomialConstraint& c : constraints) {
    if (!(c.x >= 0 && c.x <= 1))
      throw InputError("constraint x = " + number_text(c.x) + " outside [0, 1]");
    if (c.derivative < 0 || c.derivative > n)
      throw InputError("constraint derivative " + std::to_string(c.derivative) + " outside [0, " +
                       std::to_string(n) + "] (the degree)");
    if (!std::isfinite(c.value)) throw InputError("constraint value is not finite");
  }
  if (m > n + 1)
    throw InputError("over-determined: " + counts(m, n) + "; raise the degree to " +
                     std::to_string(m - 1) + " or drop " + std::to_string(m - n - 1) +
                     " constraint" + (m - n - 1 == 1 ? "" : "s"));
  Eigen::MatrixXd a(m, n + 1);
  Eigen::VectorXd r(m);
  for (int i = 0; i < m; ++i) {
    a.row(i) = bernstein_derivative_row(n, constraints[i].derivative, constraints[i].x);
    r(i) = constraints[i].value;
  }
  // Rows scaled to unit size, so that the rank test compares like with like.
  for (int i = 0; i < m; ++i) {
    const double s = a.row(i).cwiseAbs().maxCoeff();
    if (s > 0) a.row(i) /= s, r(i) /= s;
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu_a(a);
  lu_a.setThreshold(1e-10);
  if (m > 0 && lu_a.rank() < m)
    throw InputError("the constraints are not independent (contradictory or repeated): rank " +
                     std::to_string(lu_a.rank()) + " of " + counts(m, n));
  ConstrainedPolynomial out;
  Eigen::VectorXd b;
  if (m == n + 1) {
    b = lu_a.solve(r);
  } else {
    // min bᵀ G b subject to A b = r: [G Aᵀ; A 0] [b; λ] = [0; r].
    const Eigen::MatrixXd t = bernstein_to_power(n);
    Eigen::MatrixXd g = t.transpose() * jerk_energy_power(n) * t;
    if (g.size() > 0 && g.cwiseAbs().maxCoeff() > 0) g /= g.cwiseAbs().maxCoeff();
    Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + 1 + m, n + 1 + m);
    kkt.topLeftCorner(n + 1, n + 1) = g;
    kkt.topRightCorner(n + 1, m) = a.transpose();
    kkt.bottomLeftCorner(m, n + 1) = a;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + 1 + m);
    rhs.tail(m) = r;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(kkt);
    lu.setThreshold(1e-10);
    if (lu.rank() < n + 1 + m)
      throw InputError(
          "under-determined: " + counts(m, n) +
          ", and the least jerk energy does not fix the rest (a part of degree <= 2 "
          "stays free); add constraints (e.g. end velocities) or lower the degree to " +
          std::to_string(m - 1));
    b = lu.solve(rhs).head(n + 1);
    out.least_jerk_energy = true;
  }
  out.polynomial =
      Polynomial::from_bezier(0.0, 1.0, std::vector<double>(b.data(), b.data() + b.size()));
  return out;
}

namespace {

// max |q(t)| on [0, 1] for q with power coefficients c (in t).
double max_magnitude(std::vector<double> c) {
  while (c.size() > 1 && c.back() == 0.0) c.pop_back();
  const Polynomial q(0.0, 1.0, c);
  double best = std::max(std::abs(q(0.0)), std::abs(q(1.0)));
  const int n = static_cast<int>(c.size()) - 1;  // degree of q
  if (n < 2) return best;
  // Roots of q' = Σ i c_i t^(i−1): the eigenvalues of its companion matrix.
  std::vector<double> d(n);
  for (int i = 1; i <= n; ++i) d[i - 1] = i * c[i];
  const int m = n - 1;
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(m, m);
  for (int i = 1; i < m; ++i) companion(i, i - 1) = 1.0;
  for (int i = 0; i < m; ++i) companion(i, m - 1) = -d[i] / d[m];
  const Eigen::VectorXcd roots = companion.eigenvalues();
  for (const std::complex<double>& z : roots) {
    if (std::abs(z.imag()) > 1e-6 || z.real() < -1e-6 || z.real() > 1 + 1e-6) continue;
    double t = std::clamp(z.real(), 0.0, 1.0);
    for (int it = 0; it < 4; ++it) {  // Newton on q'
      double o[3];
      q.derivatives(t, 2, o);
      if (o[2] == 0.0) break;
      t = std::clamp(t - o[1] / o[2], 0.0, 1.0);
    }
    best = std::max(best, std::abs(q(t)));
  }
  return best;
}

}  // namespace

PolynomialPeaks polynomial_peaks(const Polynomial& p) {
  double peaks[3] = {0, 0, 0};
  std::vector<double> c = p.coefficients();
  for (int k = 1; k <= 3; ++k) {
    if (c.size() <= 1) break;
    std::vector<double> d(c.size() - 1);
    for (std::size_t i = 1; i < c.size(); ++i) d[i - 1] = static_cast<double>(i) * c[i];
    c = std::move(d);
    peaks[k - 1] = max_magnitude(c);
  }
  return {peaks[0], peaks[1], peaks[2]};
}

}  // namespace polarform
