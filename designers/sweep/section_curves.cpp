// Compatible polar section curves on one base circle and one knot vector (Kantz 2003, §5.4).
#include "designers/sweep/section_curves.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "src/error.h"
#include "src/fit/circle_fit.h"
#include "src/fit/fit_pipeline.h"
#include "src/fit/function_fit.h"
#include "src/fit/orthogonal_coordinates.h"
#include "src/fit/polar_curve_fit.h"
#include "src/fit/single_valued_check.h"
#include "src/number_text.h"
#include "src/nurbs/common_basis.h"

namespace polarform {

namespace {

constexpr int kSizes[] = {4, 8, 12, 16, 24, 32, 48, 64};

struct RadialFit {
  SectionCurve curve;
  ErrorStats residual;  // of F + a·G − r over the slab's points
};

RadialFit radial_fit(const SectionSlab& slab, const BaseCircle& base, int size,
                     const SectionCurveOptions& o, const std::string& where) {
  const Eigen::Matrix2Xd& points = slab.points;
  if (points.cols() < std::max(o.min_points, size + 1))
    throw InputError(where + ": " + std::to_string(points.cols()) + " points, need at least " +
                     std::to_string(std::max(o.min_points, size + 1)) +
                     " (a denser scan, or fewer sections)");
  RadialFit out;
  try {
    out.curve.centre = o.centre ? *o.centre : fit_circle(points).centre;
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  }
  PolarCoordinates pc = polar_coordinates(points.colwise() - out.curve.centre, o.threads);
  const AzimuthRange range = azimuth_range(pc.theta, Closure::automatic);
  if (range.largest_gap > o.max_gap)
    throw InputError(where + ": not closed, a gap of " +
                     number_text(range.largest_gap * 180 / std::numbers::pi) +
                     " deg about its centre (at most " +
                     number_text(o.max_gap * 180 / std::numbers::pi) + " deg allowed)");
  unwrap_angles(pc.theta, 0.0);
  const SingleValuedness check = check_single_valued(pc.theta, Eigen::VectorXd(), pc.r, o.threads);
  if (!check.single_valued)
    throw InputError(where +
                     ": not star-shaped about its centre (rays from it cross the section "
                     "twice); the sections kind fits star-shaped sections only");
  // r = F(v) + a·G(v): degree 1 in u = (a + 1)/2 (Bae 2002, eq. (3.8) with two rows), F at u = ½.
  FunctionFitOptions fo;
  fo.degree_u = 1;
  fo.size_u = fo.max_size_u = 2;
  fo.degree_v = o.degree;
  fo.size_v = size;
  fo.threads = o.threads;
  Samples samples;
  samples.u = (slab.along.array() + 1.0) / 2.0;
  samples.v = synchronize(base, pc.theta, o.threads);
  samples.value = pc.r;
  const FunctionFitResult f = fit_function(
      samples, FunctionSpace{0.0, 1.0, base.curve().front(), base.curve().back(), true}, fo);
  const BSplineSurface& S = f.F;
  Eigen::VectorXd middle(S.size_v());
  for (int j = 0; j < S.size_v(); ++j) {
    Eigen::MatrixXd across(1, S.size_u());
    for (int i = 0; i < S.size_u(); ++i) across(0, i) = S.coef(i, j)(0);
    middle[j] = BSpline(S.degree_u(), S.knots_u(), across).point(0.5)[0];
  }
  out.curve.F = BSplineFunction(S.degree_v(), S.knots_v(), middle);
  out.residual = f.stats;
  return out;
}

// The curve, its mean radius and centroid, once F is final.
void finish(SectionCurve& s, const BaseCircle& base) {
  s.curve = polar_product_curve(s.F, base, s.centre);
  // The mean radius, and the centroid of the polygon of 720 curve points (Green's theorem).
  constexpr int kSamples = 720;
  double sum = 0.0, area = 0.0;
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  Eigen::Vector2d prev =
      s.curve.point(base.parameter(2 * std::numbers::pi * (kSamples - 1) / kSamples));
  for (int k = 0; k < kSamples; ++k) {
    const double u = base.parameter(2 * std::numbers::pi * k / kSamples);
    sum += s.F(u);
    const Eigen::Vector2d q = s.curve.point(u);
    const double cross = prev.x() * q.y() - q.x() * prev.y();
    area += cross;
    moment += cross * (prev + q);
    prev = q;
  }
  s.mean_radius = sum / kSamples;
  s.centroid = moment / (3 * area);
}

}  // namespace

BaseCircle section_base_circle() {
  return BaseCircle::equal_arcs(ArcKind::rqb, 0.0, 2 * std::numbers::pi, 4);
}

SectionCurve fit_section_curve(const SectionSlab& slab, const BaseCircle& base, int size,
                               const SectionCurveOptions& o, const std::string& where) {
  RadialFit f = radial_fit(slab, base, size, o, where);
  f.curve.error = f.residual;
  finish(f.curve, base);
  return f.curve;
}

// Kantz 2003, §5.4 (one basis for all sections, Park & Kim's common knot vector; spec K12 step 3).
SectionCurves fit_section_curves(const std::vector<SectionSlab>& sections,
                                 const SectionCurveOptions& o,
                                 const std::vector<std::string>& where) {
  SectionCurves out;
  out.base = section_base_circle();
  std::vector<SectionCurve> best;
  double best_sigma = 0.0;
  Eigen::Index fewest = 0;
  for (std::size_t k = 0; k < sections.size(); ++k)
    fewest = k == 0 ? sections[k].points.cols() : std::min(fewest, sections[k].points.cols());
  for (const int size : kSizes) {
    if (!best.empty() && fewest < 3 * 2 * size) break;  // at least 3 points per coefficient
    std::vector<SectionCurve> fits;
    double worst = 0.0, ss = 0.0;
    std::size_t count = 0;
    for (std::size_t k = 0; k < sections.size(); ++k) {
      const RadialFit f = radial_fit(sections[k], out.base, size, o, where[k]);
      worst = std::max(worst, f.residual.max);
      ss += f.residual.rms * f.residual.rms * static_cast<double>(f.residual.count);
      count += f.residual.count;
      fits.push_back(f.curve);
      fits.back().error = f.residual;
    }
    // The residuals' σ per degree of freedom (2·size coefficients per section): once a larger
    // net no longer lowers it by 1 %, the rest is noise.
    const double dof =
        static_cast<double>(count) - 2.0 * size * static_cast<double>(sections.size());
    const double sigma = std::sqrt(ss / std::max(dof, 1.0));
    if (!best.empty() && sigma > 0.99 * best_sigma) break;
    best = std::move(fits);
    best_sigma = sigma;
    out.size = size;
    if (worst <= o.tolerance) break;
  }
  std::vector<BSpline> Fs;
  for (const SectionCurve& s : best) Fs.push_back(s.F.spline());
  const BSpline common = common_basis(Fs);
  for (std::size_t k = 0; k < best.size(); ++k) {
    best[k].F = BSplineFunction(common.degree(), common.knots(),
                                common.coefs().row(static_cast<Eigen::Index>(k)).transpose());
    finish(best[k], out.base);
  }
  out.sections = std::move(best);
  return out;
}

}  // namespace polarform
