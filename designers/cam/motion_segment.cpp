#include "designers/cam/motion_segment.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <vector>

#include "designers/cam/hermite_polynomial.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/nurbs/basis.h"

namespace polarform {
namespace {

[[noreturn]] void fail(const SegmentSpec& spec, const std::string& why) {
  throw InputError("segment '" + spec.name + "': " + why);
}

void validate(const SegmentSpec& spec) {
  if (!std::isfinite(spec.start) || !std::isfinite(spec.end) || !(spec.start < spec.end))
    fail(spec, "end angle " + degrees_text(spec.end) + " must be after start angle " + degrees_text(spec.start));
  if (segment_kind_name(spec.kind) == "unknown") fail(spec, "unknown segment kind");
  if (spec.kind == SegmentKind::Dwell) {
    if (spec.lift != 0.0) fail(spec, "a dwell has no lift, got " + number_text(spec.lift) + " mm");
    return;
  }
  if (!std::isfinite(spec.lift) || !(spec.lift > 0))
    fail(spec, "lift must be a positive number of mm for a " + std::string(segment_kind_name(spec.kind)) +
                   ", got " + number_text(spec.lift));
  if (motion_law_name(spec.law) == "unknown") fail(spec, "unknown motion law");
  if (spec.kind == SegmentKind::RiseReturn && !has_normalised_form(spec.law) &&
      spec.law != MotionLaw::Polynomial)
    fail(spec, "a rise-return takes a law with a closed form or 'polynomial', not '" +
                   std::string(motion_law_name(spec.law)) + "'");
  if (spec.kind == SegmentKind::RiseReturn && spec.law == MotionLaw::ConstantVelocity &&
      spec.blend == 0.0)
    fail(spec,
         "a rise-return at constant velocity needs blend > 0 (the velocity reverses at the top)");
  if (spec.law == MotionLaw::Polynomial || spec.law == MotionLaw::BSpline) {
    if (spec.constrained_order < 0 || spec.constrained_order > 3)
      fail(spec, "constrained_order " + std::to_string(spec.constrained_order) + " outside [0, 3]");
    for (const EndpointDerivatives& e : {spec.at_start, spec.at_end})
      if (!std::isfinite(e.velocity) || !std::isfinite(e.acceleration) || !std::isfinite(e.jerk))
        fail(spec, "an endpoint velocity, acceleration or jerk is not finite");
  }
  // A degree and interior constraints belong to a polynomial rise or return; other laws ignore them
  // (as they do the B-spline and SCCA settings), so that switching laws in the studio keeps them.
  if (spec.law != MotionLaw::Polynomial || spec.kind == SegmentKind::RiseReturn) return;
  if (spec.polynomial_degree < 0 || spec.polynomial_degree > kMaxConstrainedPolynomialDegree)
    fail(spec, "polynomial degree " + std::to_string(spec.polynomial_degree) + " outside [1, " +
                   std::to_string(kMaxConstrainedPolynomialDegree) + "] (0: the least degree)");
  for (const PolynomialConstraint& c : spec.interior) {
    if (!(c.x > 0 && c.x < 1))
      fail(spec, "interior constraint x = " + number_text(c.x) +
                     " outside (0, 1); the ends are constrained by <start> and <end>");
    if (c.derivative < 0 || c.derivative > kMaxConstraintDerivative)
      fail(spec, "interior constraint derivative " + std::to_string(c.derivative) +
                     " outside [0, " + std::to_string(kMaxConstraintDerivative) + "]");
    if (!std::isfinite(c.value)) fail(spec, "an interior constraint value is not finite");
  }
}

std::vector<double> endpoint_values(double level, const EndpointDerivatives& e, int order) {
  const std::vector<double> all = {level, e.velocity, e.acceleration, e.jerk};
  return std::vector<double>(all.begin(), all.begin() + order + 1);
}

// B-spline derivatives without allocation; NURBS Book A3.2 on the basis derivatives of A2.3.
void bspline_derivatives(const BSplineFunction& f, double u, int d, double* out) {
  const int p = f.degree(), n = f.size();
  const Knots& U = f.knots();
  const int span = find_span(p, U, n, u);
  double ders[(4 + 1) * (kMaxDegree + 1)];
  ders_basis_funs(span, u, p, d, U, ders);
  const double* c = f.spline().coefs().data();
  for (int k = 0; k <= d; ++k) {
    double sum = 0.0;
    for (int j = 0; j <= p; ++j) sum += ders[k * (p + 1) + j] * c[span - p + j];
    out[k] = sum;
  }
}

}  // namespace

MotionSegment::MotionSegment(SegmentSpec spec, double start_level) : spec_(std::move(spec)), start_level_(start_level) {
  validate(spec_);
  const double signed_lift =
      spec_.kind == SegmentKind::Rise ? spec_.lift : spec_.kind == SegmentKind::Return ? -spec_.lift : 0.0;
  end_level_ = start_level_ + signed_lift;
  if (spec_.kind == SegmentKind::Dwell) {
    shape_ = Polynomial(spec_.start, spec_.end, {start_level_});
    return;
  }
  try {
    if (spec_.kind == SegmentKind::RiseReturn && spec_.law == MotionLaw::Polynomial) {
      // Norton, Handbook, single-dwell 3-4-5-6 polynomial: 64x³ − 192x⁴ + 192x⁵ − 64x⁶
      shape_ = Polynomial(spec_.start, spec_.end, {0, 0, 0, 64, -192, 192, -64})
                   .affine(spec_.lift, start_level_);
    } else if (has_normalised_form(spec_.law)) {
      const double lift = spec_.kind == SegmentKind::Return ? -spec_.lift : spec_.lift;
      shape_ = ScaledLaw{NormalisedLaw(spec_.kind, spec_.law, spec_.scca, spec_.blend), lift};
    } else if (spec_.law == MotionLaw::Table) {
      shape_ = table_shape();
    } else {
      const int order = spec_.constrained_order;
      const std::vector<double> a = endpoint_values(start_level_, spec_.at_start, order);
      const std::vector<double> b = endpoint_values(end_level_, spec_.at_end, order);
      if (spec_.law == MotionLaw::Polynomial &&
          (spec_.polynomial_degree != 0 || !spec_.interior.empty()))
        shape_ = solved_polynomial(signed_lift);
      else if (spec_.law == MotionLaw::Polynomial)
        shape_ = hermite_polynomial(spec_.start, spec_.end, a, b);
      else
        shape_ = smoothest_bspline(spec_.start, spec_.end, a, b, spec_.bspline);
    }
  } catch (const InputError& e) {
    fail(spec_, e.what());
  }
}

// The polynomial law of the spec's degree from its end and interior constraints, all in
// normalised units (S^(k) = s^(k)·β^k/lift) and solved on [0, 1], then mapped onto the segment.
Polynomial MotionSegment::solved_polynomial(double signed_lift) {
  const double beta = spec_.end - spec_.start;
  const int order = spec_.constrained_order;
  std::vector<PolynomialConstraint> all;
  for (const auto& [x, level, e] :
       {std::tuple{0.0, 0.0, spec_.at_start}, std::tuple{1.0, 1.0, spec_.at_end}}) {
    const double values[4] = {level, e.velocity, e.acceleration, e.jerk};
    double scale = 1.0 / signed_lift;  // β^k / lift
    for (int k = 0; k <= order; ++k, scale *= beta)
      all.push_back({x, k, values[k] * (k ? scale : 1.0)});
  }
  all.insert(all.end(), spec_.interior.begin(), spec_.interior.end());
  const int degree =
      spec_.polynomial_degree ? spec_.polynomial_degree : static_cast<int>(all.size()) - 1;
  const ConstrainedPolynomial solved = constrained_polynomial(degree, all);
  least_jerk_energy_ = solved.least_jerk_energy;
  return Polynomial(spec_.start, spec_.end, solved.polynomial.coefficients())
      .affine(signed_lift, start_level_);
}

int MotionSegment::polynomial_degree() const {
  const auto* poly = std::get_if<Polynomial>(&shape_);
  return poly && spec_.kind != SegmentKind::Dwell ? poly->degree() : 0;
}

// The table's normalised spline mapped onto the segment: knots θ = start + βx, values
// start_level ± lift·S.
BSplineFunction MotionSegment::table_shape() const {
  const BSplineFunction normalised = interpolate_motion_table(spec_.table);
  Knots knots = normalised.knots();
  const double beta = spec_.end - spec_.start;
  for (double& k : knots) k = k == 1.0 ? spec_.end : spec_.start + beta * k;
  const double lift = spec_.kind == SegmentKind::Return ? -spec_.lift : spec_.lift;
  const Eigen::VectorXd values = (lift * normalised.values()).array() + start_level_;
  return BSplineFunction(normalised.degree(), std::move(knots), values);
}

void MotionSegment::derivatives(double theta, int d, double* out) const {
  if (d < 0 || d > 4) throw InputError("segment '" + spec_.name + "': derivative order " + std::to_string(d) + " outside [0, 4]");
  theta = std::clamp(theta, spec_.start, spec_.end);
  if (const auto* law = std::get_if<ScaledLaw>(&shape_)) {
    const double beta = spec_.end - spec_.start;
    law->law.derivatives((theta - spec_.start) / beta, d, out);
    double scale = law->signed_lift;  // h / β^k
    for (int k = 0; k <= d; ++k, scale /= beta) out[k] *= scale;
    out[0] += start_level_;
  } else if (const auto* poly = std::get_if<Polynomial>(&shape_)) {
    poly->derivatives(theta, d, out);
  } else {
    bspline_derivatives(std::get<BSplineFunction>(shape_), theta, d, out);
  }
}

std::optional<BSplineFunction> MotionSegment::exact() const {
  if (const auto* law = std::get_if<ScaledLaw>(&shape_)) {
    const std::optional<Polynomial> normalised = standard_law_polynomial(spec_.law);
    if (!normalised || spec_.kind == SegmentKind::RiseReturn) return std::nullopt;
    const Polynomial p =
        Polynomial(spec_.start, spec_.end, normalised->coefficients()).affine(law->signed_lift, start_level_);
    return p.bezier(p.degree());
  }
  if (const auto* poly = std::get_if<Polynomial>(&shape_)) return poly->bezier(poly->degree());
  return std::get<BSplineFunction>(shape_);
}

std::vector<double> MotionSegment::joins() const {
  const auto* law = std::get_if<ScaledLaw>(&shape_);
  if (!law) return {};
  std::vector<double> out;
  for (double x : law->law.joins()) out.push_back(spec_.start + x * (spec_.end - spec_.start));
  return out;
}

}  // namespace polarform
