#include "designers/cam/cam_program.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kAngleTolerance = 1e-9;  // rad

std::string quoted(const SegmentSpec& s) { return "segment '" + s.name + "'"; }

// Sorted, contiguous, covering [0, 2π]; snaps matching angles together.
void check_coverage(std::vector<SegmentSpec>& specs) {
  for (const SegmentSpec& s : specs)
    if (!std::isfinite(s.start) || !std::isfinite(s.end) || !(s.start < s.end))
      throw InputError("cam program: " + quoted(s) + " ends at " + degrees_text(s.end) +
                       ", expected an angle after its start " + degrees_text(s.start));
  std::stable_sort(specs.begin(), specs.end(), [](const SegmentSpec& a, const SegmentSpec& b) { return a.start < b.start; });
  if (std::abs(specs.front().start) > kAngleTolerance)
    throw InputError("cam program: the first segment, " + quoted(specs.front()) + ", starts at " +
                     degrees_text(specs.front().start) + "; the program must cover [0°, 360°) starting at 0°");
  specs.front().start = 0.0;
  for (std::size_t i = 1; i < specs.size(); ++i) {
    SegmentSpec &a = specs[i - 1], &b = specs[i];
    if (b.start > a.end + kAngleTolerance)
      throw InputError("cam program: gap between " + quoted(a) + " (ends at " + degrees_text(a.end) + ") and " +
                       quoted(b) + " (starts at " + degrees_text(b.start) + ")");
    if (b.start < a.end - kAngleTolerance)
      throw InputError("cam program: " + quoted(a) + " (" + degrees_text(a.start) + " to " + degrees_text(a.end) +
                       ") overlaps " + quoted(b) + " (" + degrees_text(b.start) + " to " + degrees_text(b.end) + ")");
    b.start = a.end;
  }
  SegmentSpec& last = specs.back();
  if (std::abs(last.end - kTwoPi) > kAngleTolerance)
    throw InputError("cam program: the last segment, " + quoted(last) + ", ends at " + degrees_text(last.end) +
                     "; the program must cover [0°, 360°) ending at 360°");
  last.end = kTwoPi;
}

double signed_lift(const SegmentSpec& s) {
  return s.kind == SegmentKind::Rise ? s.lift : s.kind == SegmentKind::Return ? -s.lift : 0.0;
}

// Constant velocity without blends jumps in velocity at its ends unless the neighbours move at
// its velocity there (e.g. polynomial segments with that endpoint velocity): infinite acceleration
// otherwise, refused.
void check_unblended_velocity(const std::vector<MotionSegment>& segments) {
  const std::size_t n = segments.size();
  for (std::size_t i = 0; i < n; ++i) {
    const MotionSegment& seg = segments[i];
    if (seg.spec().kind == SegmentKind::Dwell || seg.spec().law != MotionLaw::ConstantVelocity ||
        seg.spec().blend != 0.0)
      continue;
    double own[2], other[2];
    for (const bool at_start : {true, false}) {
      const MotionSegment& next = segments[at_start ? (i + n - 1) % n : (i + 1) % n];
      seg.derivatives(at_start ? seg.start() : seg.end(), 1, own);
      next.derivatives(at_start ? next.end() : next.start(), 1, other);
      if (std::abs(own[1] - other[1]) >
          1e-9 * std::max({1.0, std::abs(own[1]), std::abs(other[1])}))
        throw InputError(
            "cam program: " + quoted(seg.spec()) + " has constant velocity " + number_text(own[1]) +
            " mm/rad without blends (blend=\"0\") but " + quoted(next.spec()) + " moves at " +
            number_text(other[1]) + " mm/rad at " +
            degrees_text(at_start ? seg.start() : seg.end()) +
            ": infinite acceleration; give blend > 0 or a neighbour that ends at that velocity");
    }
  }
}

// A segment's exact form as Bezier/B-spline pieces of degree p: unchanged when it has degree p,
// otherwise each knot span as a Bezier piece raised to degree p (Taylor expansion at the span
// start, then Polynomial::bezier).
std::vector<BSplineFunction> pieces_of_degree(const BSplineFunction& f, int p) {
  if (f.degree() == p) return {f};
  std::vector<BSplineFunction> out;
  const std::vector<Breakpoint> breaks = breakpoints(f.knots());
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double a = breaks[i].value, b = breaks[i + 1].value;
    const Eigen::VectorXd taylor = f.derivatives(a, f.degree());
    std::vector<double> coefficients(f.degree() + 1);
    double scale = 1.0;  // (b - a)^k / k!
    for (int k = 0; k <= f.degree(); ++k, scale *= (b - a) / k) coefficients[k] = taylor(k) * scale;
    out.push_back(Polynomial(a, b, std::move(coefficients)).bezier(p));
  }
  return out;
}

}  // namespace

CamProgram::CamProgram(std::vector<SegmentSpec> specs) {
  if (specs.empty()) throw InputError("cam program: no segments; expected dwell / rise / return segments covering 360°");
  for (std::size_t i = 0; i < specs.size(); ++i)
    if (specs[i].name.empty()) specs[i].name = "segment " + std::to_string(i + 1);
  check_coverage(specs);

  std::vector<double> levels = {0.0};
  for (const SegmentSpec& s : specs) levels.push_back(levels.back() + signed_lift(s));
  double rises = 0.0, returns = 0.0;
  for (const SegmentSpec& s : specs) (s.kind == SegmentKind::Rise ? rises : returns) += std::abs(signed_lift(s));
  const double lowest = *std::min_element(levels.begin(), levels.end());

  auto data = std::make_shared<Data>();
  for (std::size_t i = 0; i < specs.size(); ++i) {
    data->starts.push_back(specs[i].start);
    data->segments.emplace_back(std::move(specs[i]), levels[i] - lowest);
  }
  if (std::abs(levels.back()) > 1e-9 * std::max(1.0, rises)) {
    std::ostringstream msg;
    msg << "cam program: the rises total " << rises << " mm but the returns total " << returns
        << " mm; the program must end at the level it starts with";
    throw InputError(msg.str());
  }
  data->stroke = *std::max_element(levels.begin(), levels.end()) - lowest;
  for (const MotionSegment& s : data->segments)  // a rise-return peaks inside
    if (s.spec().kind == SegmentKind::RiseReturn)
      data->stroke = std::max(data->stroke, s.start_level() + s.spec().lift);
  check_unblended_velocity(data->segments);
  data_ = std::move(data);
}

double wrap_angle(double theta) {
  const double t = theta - kTwoPi * std::floor(theta / kTwoPi);
  return t >= kTwoPi ? 0.0 : t;
}

int CamProgram::segment_index(double theta) const {
  const double t = wrap_angle(theta);
  const auto& starts = data_->starts;
  return static_cast<int>(std::upper_bound(starts.begin(), starts.end(), t) - starts.begin()) - 1;
}

void CamProgram::derivatives(double theta, int d, double* out) const {
  const double t = wrap_angle(theta);
  data_->segments[segment_index(t)].derivatives(t, d, out);
}

double CamProgram::operator()(double theta) const {
  double s;
  derivatives(theta, 0, &s);
  return s;
}

Kinematics CamProgram::kinematics(double theta, double rpm) const {
  if (!(rpm > 0) || !(rpm <= kMaxRpm))
    throw InputError("cam program: rpm " + number_text(rpm) + ", expected in (0, " +
                     number_text(kMaxRpm) + "]");
  const double omega = kTwoPi * rpm / 60.0;  // rad/s
  double s[4];
  derivatives(theta, 3, s);
  return {s[0], s[1] * omega, s[2] * omega * omega, s[3] * omega * omega * omega};
}

std::optional<BSplineFunction> CamProgram::exact() const {
  std::vector<BSplineFunction> forms;
  int p = 0;
  for (const MotionSegment& seg : data_->segments) {
    std::optional<BSplineFunction> f = seg.exact();
    if (!f) return std::nullopt;
    p = std::max(p, f->degree());
    forms.push_back(std::move(*f));
  }
  if (p == 0) return BSplineFunction(0, {0.0, kTwoPi}, Eigen::VectorXd::Constant(1, data_->segments.front().start_level()));

  // Join clamped pieces: interior knots kept, p knots at each join, one shared control value.
  Knots knots(p + 1, 0.0);
  std::vector<double> values;
  for (std::size_t i = 0; i < forms.size(); ++i) {
    for (const BSplineFunction& piece : pieces_of_degree(forms[i], p)) {
      const Knots& k = piece.knots();
      knots.insert(knots.end(), k.begin() + p + 1, k.end() - p - 1);
      knots.insert(knots.end(), p, piece.back());
      const Eigen::VectorXd c = piece.values();
      values.insert(values.end(), c.data() + (values.empty() ? 0 : 1), c.data() + c.size());
    }
  }
  knots.push_back(kTwoPi);
  return BSplineFunction(p, std::move(knots), Eigen::Map<const Eigen::VectorXd>(values.data(), values.size()));
}

std::vector<double> CamProgram::smoothness_breaks() const {
  std::vector<double> out;
  for (const MotionSegment& seg : segments()) {
    if (seg.start() > 0) out.push_back(seg.start());
    const std::vector<double> joins = seg.joins();
    out.insert(out.end(), joins.begin(), joins.end());
  }
  return out;
}

}  // namespace polarform
