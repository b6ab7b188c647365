#include "src/nurbs/curve_interpolation.h"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <string>
#include <vector>

#include "src/error.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/knots.h"

namespace polarform {

// The derivative of the Lagrange parabola through (a, p0), (b, p1), (e, p2) at x.
CubicEnds bessel_ends(const Eigen::MatrixXd& values, const Eigen::VectorXd& t) {
  const Eigen::Index N = values.cols();
  if (N < 3 || t.size() != N)
    throw InputError("bessel_ends: " + std::to_string(N) + " values and " +
                     std::to_string(t.size()) + " parameters; expected at least 3 of each");
  const auto slope = [&](Eigen::Index i, double x) {
    const double a = t[i], b = t[i + 1], e = t[i + 2];
    if (!(a < b && b < e)) throw InputError("bessel_ends: the parameters must increase strictly");
    return Eigen::VectorXd(values.col(i) * ((2 * x - b - e) / ((a - b) * (a - e))) +
                           values.col(i + 1) * ((2 * x - a - e) / ((b - a) * (b - e))) +
                           values.col(i + 2) * ((2 * x - a - b) / ((e - a) * (e - b))));
  };
  return CubicEnds{slope(0, t[0]), slope(N - 3, t[N - 1])};
}

BSpline interpolate_cubic(const Eigen::MatrixXd& values, const Eigen::VectorXd& t,
                          const CubicEnds& ends) {
  const int N = static_cast<int>(values.cols());
  if (N < 2 || t.size() != N)
    throw InputError("interpolate_cubic: " + std::to_string(N) + " values and " +
                     std::to_string(t.size()) + " parameters; expected at least 2 of each");
  for (int k = 1; k < N; ++k)
    if (!(t[k] > t[k - 1]))
      throw InputError("interpolate_cubic: parameter " + std::to_string(k) + " does not increase");
  if (!values.allFinite()) throw InputError("interpolate_cubic: a value is not finite");
  const int p = 3, n = N + 2;  // control values
  Knots U(4, t[0]);
  for (int k = 1; k + 1 < N; ++k) U.push_back(t[k]);
  U.insert(U.end(), 4, t[N - 1]);
  // Rows: C(t_k) = value_k (k = 0..N−1), then the two end conditions.
  std::vector<Eigen::Triplet<double>> a;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, values.rows());
  const auto row_of = [&](int row, double u, int order) {
    const int span = find_span(p, U, n, u);
    const Eigen::MatrixXd ders = ders_basis_funs(span, u, p, order, U);
    for (int j = 0; j <= p; ++j) a.emplace_back(row, span - p + j, ders(order, j));
  };
  for (int k = 0; k < N; ++k) {
    row_of(k, t[k], 0);
    rhs.row(k) = values.col(k).transpose();
  }
  const std::optional<Eigen::VectorXd>* given[2] = {&ends.start_tangent, &ends.end_tangent};
  for (int e = 0; e < 2; ++e) {
    const double u = e == 0 ? t[0] : t[N - 1];
    if (given[e]->has_value()) {
      if ((*given[e])->size() != values.rows())
        throw InputError("interpolate_cubic: an end tangent of dimension " +
                         std::to_string((*given[e])->size()) + ", expected " +
                         std::to_string(values.rows()));
      row_of(N + e, u, 1);
      rhs.row(N + e) = (*given[e])->transpose();
    } else {
      row_of(N + e, u, 2);
    }
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(a.begin(), a.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(A);
  if (lu.info() != Eigen::Success)
    throw NumericalError("interpolate_cubic: the interpolation system is singular");
  const Eigen::MatrixXd coefs = lu.solve(rhs);
  return BSpline(p, U, coefs.transpose());
}

}  // namespace polarform
