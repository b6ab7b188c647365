// Ruled surface and bilinear patch (NURBS Book §8.2, §8.4).
#include "src/nurbs/ruled_surface.h"

#include "src/error.h"
#include "src/nurbs/common_basis.h"

namespace polarform {

// NURBS Book §8.4, eq. (8.2)-(8.3): P_{i,0} = C0's, P_{i,1} = C1's control points on one basis.
NurbsSurface ruled_surface(const NurbsCurve3d& c0, const NurbsCurve3d& c1) {
  if (c0.front() != c1.front() || c0.back() != c1.back())
    throw InputError("ruled surface: the curves' domains differ; expected one parameter domain");
  // Each homogeneous curve divided by its first weight: a constant factor does not change a curve.
  const BSpline both =
      common_basis({BSpline(c0.degree(), c0.knots(), c0.homogeneous().coefs() / c0.weight(0)),
                    BSpline(c1.degree(), c1.knots(), c1.homogeneous().coefs() / c1.weight(0))});
  const auto w0 = both.coefs().row(3), w1 = both.coefs().row(7);
  if ((w0 - w1).cwiseAbs().maxCoeff() > 1e-12 * w0.cwiseAbs().maxCoeff())
    throw InputError(
        "ruled surface: the curves' weight functions differ, so (1 − v)·C0 + v·C1 is "
        "not a NURBS surface of degree 1 in v; expected equal weights");
  const int n = both.size();
  Eigen::MatrixXd P(4, 2 * n);
  for (int i = 0; i < n; ++i) {
    P.col(2 * i) = both.coefs().col(i).head<4>();
    P.col(2 * i + 1) << both.coefs().col(i).segment<3>(4) * (w0(i) / w1(i)), w0(i);
  }
  return NurbsSurface(BSplineSurface(both.degree(), 1, both.knots(), {0, 0, 1, 1}, std::move(P)));
}

// NURBS Book §8.2, the bilinear surface as a degree (1, 1) tensor product.
NurbsSurface bilinear_surface(const Eigen::Vector3d& p00, const Eigen::Vector3d& p10,
                              const Eigen::Vector3d& p01, const Eigen::Vector3d& p11) {
  return NurbsSurface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, {p00, p01, p10, p11});
}

}  // namespace polarform
