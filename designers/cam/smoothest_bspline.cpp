#include "designers/cam/smoothest_bspline.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/fit/constrained_least_squares.h"
#include "src/nurbs/basis.h"

namespace polarform {
namespace {

// Gauss-Legendre nodes and weights on [-1, 1] by the Golub-Welsch eigenvalue method
// (Golub & Welsch, Math. Comp. 23, 1969).
void gauss_legendre(int m, Eigen::VectorXd& nodes, Eigen::VectorXd& weights) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(m, m);
  for (int k = 1; k < m; ++k) J(k, k - 1) = J(k - 1, k) = k / std::sqrt(4.0 * k * k - 1.0);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(J);
  nodes = eig.eigenvalues();
  weights = 2.0 * eig.eigenvectors().row(0).transpose().array().square();
}

void validate(std::span<const double> start, std::span<const double> end, const BSplineLawSettings& s) {
  const auto fail = [](const std::string& why) { throw InputError("B-spline law: " + why); };
  if (start.size() != end.size() || start.empty() || start.size() > 4)
    fail("expected 1 to 4 endpoint values at each end and the same number at both, got " +
         std::to_string(start.size()) + " and " + std::to_string(end.size()));
  const int k = static_cast<int>(start.size()) - 1, conditions = 2 * (k + 1);
  if (s.degree < std::max(k, 1) || s.degree > kMaxDegree)
    fail("degree " + std::to_string(s.degree) + " outside [" + std::to_string(std::max(k, 1)) + ", " +
         std::to_string(kMaxDegree) + "]");
  if (s.control_values > kMaxBSplineControlValues)
    fail("control_values " + std::to_string(s.control_values) + " above the limit " +
         std::to_string(kMaxBSplineControlValues));
  if (s.control_values < std::max(s.degree + 1, conditions))
    fail("control_values " + std::to_string(s.control_values) + " below max(degree + 1, " +
         std::to_string(conditions) + " endpoint conditions) = " + std::to_string(std::max(s.degree + 1, conditions)));
  if (s.minimised_derivative < 1 || s.minimised_derivative > std::min(s.degree, conditions))
    fail("minimised_derivative " + std::to_string(s.minimised_derivative) + " outside [1, " +
         std::to_string(std::min(s.degree, conditions)) + "] (at most the degree, and at most the " +
         std::to_string(conditions) + " endpoint conditions so that they fix the objective's null space)");
}

}  // namespace

// Angeles 1983 / MacCarthy 1988: endpoint constraints (Bae 2002, eq. (5.1)) as C x = d, the
// smoothness integral as ||A x||² by Gauss-Legendre quadrature exact for the piecewise polynomial
// integrand, minimised by constrained least squares (Bae 2002, Appendix C).
BSplineFunction smoothest_bspline(double u0, double u1, std::span<const double> start, std::span<const double> end,
                                  const BSplineLawSettings& settings) {
  validate(start, end, settings);
  if (!(u0 < u1)) throw InputError("B-spline law: empty interval");
  const int p = settings.degree, n = settings.control_values, r = settings.minimised_derivative;
  const int k = static_cast<int>(start.size()) - 1, spans = n - p;
  const double h = u1 - u0;
  const Knots x_knots = uniform_clamped_knots(p, spans, 0.0, 1.0);  // work in x = (u - u0)/h

  // Constraints: f_x^(i)(0) = h^i f_u^(i)(u0), f_x^(i)(1) = h^i f_u^(i)(u1).
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(2 * (k + 1), n), d(2 * (k + 1), 1);
  const Eigen::MatrixXd at0 = ders_basis_funs(p, 0.0, p, k, x_knots);
  const Eigen::MatrixXd at1 = ders_basis_funs(n - 1, 1.0, p, k, x_knots);
  double hi = 1.0;
  for (int i = 0; i <= k; ++i, hi *= h) {
    C.block(i, 0, 1, p + 1) = at0.row(i);
    C.block(k + 1 + i, n - 1 - p, 1, p + 1) = at1.row(i);
    d(i, 0) = start[i] * hi;
    d(k + 1 + i, 0) = end[i] * hi;
  }

  // Objective rows sqrt(w_q |span|/2) N^(r)(x_q): (f^(r))² has degree 2(p - r) per span.
  const int m = p - r + 1;
  Eigen::VectorXd nodes, weights;
  gauss_legendre(m, nodes, weights);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(spans * m, n);
  for (int s = 0; s < spans; ++s) {
    const int span = p + s;
    const double a = x_knots[span], b = x_knots[span + 1];
    for (int q = 0; q < m; ++q) {
      const double x = 0.5 * (a + b) + 0.5 * (b - a) * nodes(q);
      const Eigen::MatrixXd ders = ders_basis_funs(span, x, p, r, x_knots);
      A.block(s * m + q, span - p, 1, p + 1) = std::sqrt(0.5 * (b - a) * weights(q)) * ders.row(r);
    }
  }
  const Eigen::MatrixXd coefs = constrained_least_squares(A, Eigen::MatrixXd::Zero(A.rows(), 1), C, d);
  return BSplineFunction(p, uniform_clamped_knots(p, spans, u0, u1), coefs.col(0));
}

}  // namespace polarform
