#include "src/nurbs/basis.h"

#include <Eigen/Core>
#include <algorithm>

namespace polarform {

void basis_funs(int span, double u, int p, const Knots& U, double* N) {
  double left[kMaxDegree + 1], right[kMaxDegree + 1];
  N[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[span + 1 - j];
    right[j] = U[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double temp = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    N[j] = saved;
  }
}

void basis_funs_on_span(int span, const double* u, int count, int p, const Knots& U, double* N) {
  // A2.2's right[r + 1] + left[j − r] is U[span + r + 1] − U[span + 1 − j + r], whatever u.
  double inverse[kMaxDegree + 1][kMaxDegree + 1];
  for (int j = 1; j <= p; ++j)
    for (int r = 0; r < j; ++r) inverse[j][r] = 1.0 / (U[span + r + 1] - U[span + 1 - j + r]);
  // Two parameters at a time, one in each lane: the same operations on each as one at a time.
  using Pair = Eigen::Array2d;
  int i = 0;
  for (; i + 1 < count; i += 2, N += 2 * (p + 1)) {
    const Pair t(u[i], u[i + 1]);
    Pair n[kMaxDegree + 1], left[kMaxDegree + 1], right[kMaxDegree + 1];
    n[0] = 1.0;
    for (int j = 1; j <= p; ++j) {
      left[j] = t - U[span + 1 - j];
      right[j] = U[span + j] - t;
      Pair saved = Pair::Zero();
      for (int r = 0; r < j; ++r) {
        const Pair temp = n[r] * inverse[j][r];
        n[r] = saved + right[r + 1] * temp;
        saved = left[j - r] * temp;
      }
      n[j] = saved;
    }
    for (int r = 0; r <= p; ++r) N[r] = n[r](0), N[p + 1 + r] = n[r](1);
  }
  for (; i < count; ++i, N += p + 1) {
    double left[kMaxDegree + 1], right[kMaxDegree + 1];
    N[0] = 1.0;
    for (int j = 1; j <= p; ++j) {
      left[j] = u[i] - U[span + 1 - j];
      right[j] = U[span + j] - u[i];
      double saved = 0.0;
      for (int r = 0; r < j; ++r) {
        const double temp = N[r] * inverse[j][r];
        N[r] = saved + right[r + 1] * temp;
        saved = left[j - r] * temp;
      }
      N[j] = saved;
    }
  }
}

void ders_basis_funs(int span, double u, int p, int d, const Knots& U, double* ders) {
  constexpr int M = kMaxDegree + 1;
  double ndu[M][M], a[2][M], left[M], right[M];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[span + 1 - j];
    right[j] = U[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];  // lower triangle: knot differences
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;  // upper triangle: basis functions
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  const int w = p + 1;
  std::fill(ders, ders + (d + 1) * w, 0.0);
  for (int j = 0; j <= p; ++j) ders[j] = ndu[j][p];
  const int dd = std::min(d, p);
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= dd; ++k) {
      double dk = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        dk = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        dk += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        dk += a[s2][k] * ndu[r][pk];
      }
      ders[k * w + r] = dk;
      std::swap(s1, s2);
    }
  }
  double factor = p;
  for (int k = 1; k <= dd; ++k) {
    for (int j = 0; j <= p; ++j) ders[k * w + j] *= factor;
    factor *= (p - k);
  }
}

Eigen::MatrixXd ders_basis_funs(int span, double u, int p, int d, const Knots& knots) {
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> out(d + 1, p + 1);
  ders_basis_funs(span, u, p, d, knots, out.data());
  return out;
}

}  // namespace polarform
