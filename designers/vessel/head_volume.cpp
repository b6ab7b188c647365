#include "designers/vessel/head_volume.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/nurbs/basis.h"
#include "src/nurbs/gauss_legendre.h"

namespace polarform {

namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

HeadMeasures polar_head_measures(const PolarFunction& R) {
  HeadMeasures out;
  out.volume = 2 * kPi / 3 *
               integrate_gauss_legendre([&](double t) { return std::pow(R(t), 3) * std::cos(t); },
                                        0.0, kPi / 2, 256);
  out.area = 2 * kPi *
             integrate_gauss_legendre(
                 [&](double t) {
                   double d[2];
                   R.derivatives(t, 1, d);
                   return d[0] * std::cos(t) * std::hypot(d[0], d[1]);
                 },
                 0.0, kPi / 2, 256);
  return out;
}

// R³cosθ on a span is a polynomial of degree 3p times cosθ: 4-point rules on 3p + 8 parts of every
// span in [0, π/2] integrate it to round-off.
HeadVolumeConstraint::HeadVolumeConstraint(const SynthesisSpace& space) {
  const int p = space.degree, n = space.ordinates();
  std::vector<double> breaks;
  for (double u : space.knots)
    if (u < kPi / 2 && (breaks.empty() || u > breaks.back())) breaks.push_back(u);
  breaks.push_back(kPi / 2);
  std::vector<Eigen::RowVectorXd> rows;
  std::vector<double> weights;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
    visit_gauss_legendre(
        [&](double t, double w) {
          const int span = find_span(p, space.knots, n, t);
          Eigen::RowVectorXd on_ordinates = Eigen::RowVectorXd::Zero(n);
          on_ordinates.segment(span - p, p + 1) =
              ders_basis_funs(span, t, p, 0, space.knots).row(0);
          rows.push_back(on_ordinates * space.map);
          weights.push_back(2 * kPi / 3 * w * std::cos(t));
        },
        breaks[k], breaks[k + 1], 3 * p + 8);
  rows_.resize(static_cast<Eigen::Index>(rows.size()), space.unknowns());
  weights_.resize(static_cast<Eigen::Index>(weights.size()));
  for (std::size_t q = 0; q < rows.size(); ++q) {
    rows_.row(static_cast<Eigen::Index>(q)) = rows[q];
    weights_(static_cast<Eigen::Index>(q)) = weights[q];
  }
}

double HeadVolumeConstraint::value(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const {
  const Eigen::ArrayXd r = (rows_ * x).array();
  if (gradient) *gradient = rows_.transpose() * (3 * weights_.array() * r.square()).matrix();
  return (weights_.array() * r.cube()).sum();
}

}  // namespace polarform
