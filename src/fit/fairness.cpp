#include "src/fit/fairness.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "src/nurbs/basis.h"

namespace polarform {

namespace {

// Gauss–Legendre nodes and weights on [-1, 1]: Newton on the Legendre polynomial P_n (Numerical
// Recipes §4.6, gauleg).
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = 0.0;
      for (int k = 1; k <= n; ++k) {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
      }
      dp = n * (z * p0 - p1) / (z * z - 1.0);
      const double dz = p0 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
}

}  // namespace

Eigen::MatrixXd derivative_gram(const SplineAxis& axis, int order) {
  const int n = axis.size(), p = axis.degree;
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, n);
  if (order > p) return G;
  const double length = axis.back() - axis.front();
  std::vector<double> gx, gw;
  gauss_legendre(p - order + 1, gx, gw);  // exact for polynomials of degree 2(p - order) + 1
  std::vector<double> ders(static_cast<std::size_t>((order + 1) * (p + 1)));
  for (int span = p; span < n; ++span) {
    const double a = axis.knots[span], b = axis.knots[span + 1];
    if (!(b > a)) continue;
    for (std::size_t g = 0; g < gx.size(); ++g) {
      const double u = 0.5 * (a + b) + 0.5 * (b - a) * gx[g], wq = 0.5 * (b - a) * gw[g];
      ders_basis_funs(span, u, p, order, axis.knots, ders.data());
      const double* d = ders.data() + order * (p + 1);
      for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= p; ++j) G(span - p + i, span - p + j) += wq * d[i] * d[j];
    }
  }
  // d/ds = length · d/du and ds = du / length.
  return G * std::pow(length, 2 * order - 1);
}

Eigen::SparseMatrix<double> thin_plate_matrix(const SplineAxis& u, const SplineAxis& v,
                                              const CoefficientMap& map) {
  const Eigen::MatrixXd G0u = derivative_gram(u, 0), G1u = derivative_gram(u, 1),
                        G2u = derivative_gram(u, 2);
  const Eigen::MatrixXd G0v = derivative_gram(v, 0), G1v = derivative_gram(v, 1),
                        G2v = derivative_gram(v, 2);
  const int nu = u.size(), nv = v.size(), pu = u.degree, pv = v.degree;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(nu) * nv * (2 * pu + 1) * (2 * pv + 1));
  for (int i = 0; i < nu; ++i)
    for (int k = std::max(0, i - pu); k <= std::min(nu - 1, i + pu); ++k)
      for (int j = 0; j < nv; ++j)
        for (int l = std::max(0, j - pv); l <= std::min(nv - 1, j + pv); ++l) {
          const double e = G2u(i, k) * G0v(j, l) + 2.0 * G1u(i, k) * G1v(j, l) + G0u(i, k) * G2v(j, l);
          if (e != 0.0) t.emplace_back(map(i, j), map(k, l), e);
        }
  Eigen::SparseMatrix<double> T(map.unknowns(), map.unknowns());
  T.setFromTriplets(t.begin(), t.end());
  return T;
}

}  // namespace polarform
