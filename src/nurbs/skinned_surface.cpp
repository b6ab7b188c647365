// Skinning through section curves (NURBS Book §10.3).
#include "src/nurbs/skinned_surface.h"

#include <string>

#include "src/error.h"
#include "src/nurbs/common_basis.h"
#include "src/nurbs/curve_interpolation.h"

namespace polarform {

// NURBS Book §10.3: compatible sections, then each control column interpolated across v (here the
// cubic spline with knots at the v_k and Bessel ends, §9.2.4).
NurbsSurface skin_sections(const std::vector<NurbsCurve3d>& sections,
                           const std::vector<double>& v) {
  const std::size_t K = sections.size();
  if (K < 2) throw InputError("skinning: " + std::to_string(K) + " sections, expected at least 2");
  if (v.size() != K)
    throw InputError("skinning: " + std::to_string(v.size()) + " section parameters for " +
                     std::to_string(K) + " sections");
  for (std::size_t k = 1; k < K; ++k)
    if (!(v[k] > v[k - 1]))
      throw InputError("skinning: the section parameters must increase strictly");
  std::vector<BSpline> parts;
  for (const NurbsCurve3d& c : sections) {
    if (c.front() != sections[0].front() || c.back() != sections[0].back())
      throw InputError("skinning: the sections' parameter domains differ; expected one domain");
    parts.push_back(c.homogeneous());
  }
  const BSpline all = common_basis(parts);  // row block k: section k's homogeneous coefficients
  const int n = all.size();
  Eigen::MatrixXd columns(4 * n, static_cast<Eigen::Index>(K));
  for (std::size_t k = 0; k < K; ++k)
    for (int i = 0; i < n; ++i)
      columns.block<4, 1>(4 * i, static_cast<Eigen::Index>(k)) =
          all.coefs().block<4, 1>(4 * static_cast<Eigen::Index>(k), i);
  const Eigen::Map<const Eigen::VectorXd> at(v.data(), static_cast<Eigen::Index>(v.size()));
  const BSpline across =
      interpolate_cubic(columns, at, K >= 3 ? bessel_ends(columns, at) : CubicEnds{});
  const int m = across.size();
  Eigen::MatrixXd net(4, n * m);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) net.col(i * m + j) = across.coefs().block<4, 1>(4 * i, j);
  return NurbsSurface(
      BSplineSurface(all.degree(), across.degree(), all.knots(), across.knots(), std::move(net)));
}

}  // namespace polarform
