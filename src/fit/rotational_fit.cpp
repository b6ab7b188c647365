#include "src/fit/rotational_fit.h"

#include <exception>
#include <sstream>

#include "src/error.h"
#include "src/fit/f_distribution.h"
#include "src/fit/point_subset.h"
#include "src/fit/quadric_fit.h"

namespace polarform {

std::string to_string(FitMethod m) { return m == FitMethod::spherical ? "spherical" : "cylindrical"; }

FitMethod RotationalFit::method() const {
  return std::holds_alternative<SphericalFit>(fit) ? FitMethod::spherical : FitMethod::cylindrical;
}
const NurbsSurface& RotationalFit::surface() const {
  return std::visit([](const auto& f) -> const NurbsSurface& { return f.surface; }, fit);
}
const FitReport& RotationalFit::report() const {
  return std::visit([](const auto& f) -> const FitReport& { return f.report; }, fit);
}
FitReport& RotationalFit::report() {
  return std::visit([](auto& f) -> FitReport& { return f.report; }, fit);
}
const FrameEstimate& RotationalFit::frame() const {
  return std::visit([](const auto& f) -> const FrameEstimate& { return f.frame; }, fit);
}

namespace {

// One attempt: the fit, or the message of the error that stopped it.
struct Attempt {
  std::optional<SphericalFit> sph;
  std::optional<CylindricalFit> cyl;
  std::exception_ptr error;
  std::string message;
  bool ok() const { return sph || cyl; }
  double rms() const { return sph ? sph->report.error.rms : cyl->report.error.rms; }
};

Attempt attempt(FitMethod m, const Eigen::Matrix3Xd& points, const RotationalFitOptions& o) {
  Attempt a;
  try {
    if (m == FitMethod::spherical) a.sph = fit_spherical(points, o.spherical);
    else a.cyl = fit_cylindrical(points, o.cylindrical);
  } catch (const InputError& e) {
    a.error = std::current_exception(), a.message = e.what();
  } catch (const NumericalError& e) {
    a.error = std::current_exception(), a.message = e.what();
  }
  return a;
}

RotationalFit result(FitMethod m, Attempt& a, std::string reason) {
  if (m == FitMethod::spherical) return {std::move(*a.sph), std::move(reason), {}};
  return {std::move(*a.cyl), std::move(reason), {}};
}

FitMethod other(FitMethod m) {
  return m == FitMethod::spherical ? FitMethod::cylindrical : FitMethod::spherical;
}

// The numbers a frame is compared by.
struct Score {
  double rms = 0.0;
  bool rotational = false;
  long coefficients = 0;
  std::size_t points = 0;
};

Score score(const FitReport& r) {
  return {r.error.rms, r.revolution.rotational, long(r.size_u) * long(std::max(r.size_v, 1)),
          r.error.count};
}

void fill(FrameCandidate& c, const FitReport& r) {
  c.rms = r.error.rms;
  c.rotational = r.revolution.rotational;
  c.p_value = r.revolution.tested ? r.revolution.p_value : -1.0;
  c.coefficients = long(r.size_u) * long(std::max(r.size_v, 1));
  c.points = r.error.count;
}

// Whether the fit scored `a` is to replace the fit scored `b`. A frame in which F(u) alone explains
// the data (a surface of revolution) is kept over one in which F(u, v) is needed unless the latter
// is closer beyond the noise: the extra-sum-of-squares F-test of the two fits' true distances,
// the rotational one the restricted model (Draper & Smith, §6.2); a tilted frame whose F(u, v)
// absorbs the tilt is not closer than that. Otherwise the smaller rms distance wins; with
// `later_wins_ties`, a later frame within kFrameTie of the rms replaces an earlier one (the frames
// are listed from the quadric's to the one refined by the rotational criterion).
constexpr double kFrameTie = 1e-3;
bool replaces(const Score& a, const Score& b, bool later_wins_ties = false) {
  if (a.rotational != b.rotational) {
    const Score& rot = a.rotational ? a : b;
    const Score& full = a.rotational ? b : a;
    bool rot_wins = rot.rms <= full.rms;
    if (!rot_wins && full.points > 0) {
      const double n = double(full.points);
      const double d1 = std::max(1.0, double(full.coefficients - rot.coefficients));
      const double d2 = std::max(1.0, n - double(full.coefficients));
      const double rss0 = rot.rms * rot.rms * n, rss1 = full.rms * full.rms * n;
      const double f = rss1 > 0.0 ? (rss0 - rss1) / d1 / (rss1 / d2) : HUGE_VAL;
      rot_wins = f_upper_tail(f, d1, d2) >= kRevolutionAlpha;
    }
    return a.rotational ? rot_wins : !rot_wins;
  }
  return later_wins_ties ? a.rms <= b.rms * (1.0 + kFrameTie) : a.rms < b.rms;
}

std::string describe(const FrameCandidate& c) {
  std::ostringstream o;
  o.precision(4);
  if (!c.failure.empty()) return c.name + ": failed (" + c.failure + ")";
  o << c.name << ": RMS distance " << c.rms << " mm, " << (c.rotational ? "F(u) alone" : "F(u, v)");
  if (c.p_value >= 0.0) o << " (p = " << c.p_value << ")";
  return o.str();
}

// Clouds of more than twice this many points choose method and frame on an evenly strided
// subsample of this many (the frame candidates with the F(u, v) net of the first fit), and only
// the winner is fitted to every point (choosing its own net again).
constexpr Eigen::Index kFrameScorePoints = 100000;

// The frames to try (Bae 2002, §4.3 frame kept as the first): the least-squares centre and the
// axis refined by the rotational criterion through it for spherical fits, the least-squares axis
// line and the PCA axis refined by the rotational criterion for cylindrical ones. A given origin
// or axis stays fixed in every candidate.
std::vector<FrameCandidate> frame_list(const Eigen::Matrix3Xd& points, const FrameEstimate& used,
                                       const FrameOptions& given, bool spherical) {
  const Eigen::Vector3d origin = used.frame.origin, axis = used.frame.axes.col(2);
  std::vector<FrameCandidate> list(1);
  list[0].name = given.axis || given.origin ? "given / quadric" : "quadric";
  list[0].origin = origin;
  list[0].axis = axis;
  list[0].how = used.reason;
  AxisConstraint fixed;
  if (given.origin) fixed.point = origin;
  if (given.axis) fixed.direction = axis;
  if (spherical) {
    if (!given.origin) list.push_back(least_squares_centre(points, origin, axis));
    if (!given.axis) {
      fixed.point = list.back().origin;
      list.push_back(profile_refined_axis(points, {{"quadric", fixed.point.value(), axis}}, fixed));
      if (!given.origin) list.back().name = "least-squares centre, PCA + profile refinement";
    }
  } else {
    list.push_back(
        least_squares_axis(points, origin, axis, given.origin.has_value(), given.axis.has_value()));
    list.push_back(profile_refined_axis(
        points, {{"quadric", origin, axis}, {"least-squares axis", list[1].origin, list[1].axis}},
        fixed));
  }
  return list;
}

// The options that fit every frame with the first fit's F(u, v) net: the one its revolution test
// used where F(u) alone was kept, else the chosen (or fitted) net.
RotationalFitOptions scoring_options(const RotationalFitOptions& o, const FitReport& first,
                                     bool spherical) {
  RotationalFitOptions s = o;
  FunctionFitOptions& f = spherical ? s.spherical.function : s.cylindrical.function;
  const RevolutionTest& t = first.revolution;
  const bool tested = t.tested && t.rotational;
  const int u = tested ? t.size_u : first.net.size_u > 0 ? first.net.size_u : first.size_u;
  const int v = tested ? t.size_v : first.net.size_v > 0 ? first.net.size_v : first.size_v;
  f.size_u = std::max(u, f.degree_u + 1);
  f.size_v = std::max(v, f.degree_v + 1);
  f.tolerance = 0.0;
  return s;
}

// The chosen fit against the same method in the other frames of frame_list, each fitted with its
// own net, or with the first fit's (`fixed_net`); `replaces` decides, later frames winning ties.
RotationalFit choose_frame(RotationalFit fit, const Eigen::Matrix3Xd& points,
                           const RotationalFitOptions& o, bool fixed_net) {
  const bool spherical = fit.method() == FitMethod::spherical;
  const FrameOptions& given = spherical ? o.spherical.frame : o.cylindrical.frame;
  if (given.origin && given.axis) return fit;
  const FrameEstimate used = fit.frame();
  std::vector<FrameCandidate> list = frame_list(points, used, given, spherical);
  // With a fixed net the first frame is fitted again with it, so that all compare alike.
  const RotationalFitOptions base = fixed_net ? scoring_options(o, fit.report(), spherical) : o;
  fill(list[0], fit.report());
  std::size_t chosen = 0;
  Score best = score(fit.report());
  std::optional<RotationalFit> replacement;
  for (std::size_t i = fixed_net ? 0 : 1; i < list.size(); ++i) {
    FrameCandidate& c = list[i];
    RotationalFitOptions again = base;
    FrameOptions& f = spherical ? again.spherical.frame : again.cylindrical.frame;
    f.origin = c.origin;
    f.axis = c.axis;
    if (!f.reference) f.reference = used.frame.axes.col(0);
    Attempt b = attempt(fit.method(), points, again);
    if (!b.ok()) {
      c.failure = b.message;
      continue;
    }
    const FitReport& rep = b.sph ? b.sph->report : b.cyl->report;
    fill(c, rep);
    if (i == 0) {
      best = score(rep);
      continue;
    }
    if (!replaces(score(rep), best, true)) continue;
    best = score(rep), chosen = i;
    // Neither the first fit nor an earlier replacement is returned any more: their per-point
    // distances go first (80 MB each at 10^7 points, while the next candidate is fitted).
    if (!replacement) fit.report().signed_distance = Eigen::VectorXd();
    replacement.reset();
    replacement = result(fit.method(), b, fit.reason);
  }
  std::ostringstream why;
  why << "; frame: " << describe(list[chosen]) << " (";
  bool first = true;
  for (std::size_t i = 0; i < list.size(); ++i)
    if (i != chosen) why << (first ? "" : "; ") << describe(list[i]), first = false;
  why << ")";
  if (replacement) {
    RotationalFit& r = *replacement;
    r.reason += why.str();
    std::visit(
        [&](auto& f) {
          f.frame.quadric = used.quadric;  // the quadric the candidates started from
          f.frame.reason = list[chosen].how;
        },
        r.fit);
    r.frame_candidates = std::move(list);
    r.chosen_candidate = static_cast<int>(chosen);
    return std::move(r);
  }
  fit.reason += why.str();
  fit.frame_candidates = std::move(list);
  fit.chosen_candidate = static_cast<int>(chosen);
  return fit;
}

RotationalFit fit_chosen_method(const Eigen::Matrix3Xd& points, const RotationalFitOptions& o,
                                bool* undecided);

}  // namespace

namespace {

// The method (by the quadric type, else by the error) and then the frame (choose_frame) on these
// points.
RotationalFit choose_method_and_frame(const Eigen::Matrix3Xd& points, const RotationalFitOptions& o,
                                      bool fixed_net) {
  bool undecided = false;
  RotationalFit fit = choose_frame(fit_chosen_method(points, o, &undecided), points, o, fixed_net);
  if (!undecided) return fit;
  // The quadric type did not decide the method: the other method in its best frame is one more
  // candidate.
  RotationalFitOptions other_method = o;
  other_method.method =
      fit.method() == FitMethod::spherical ? FitMethod::cylindrical : FitMethod::spherical;
  try {
    RotationalFit alt = choose_frame(fit_chosen_method(points, other_method, &undecided), points,
                                     other_method, fixed_net);
    const int offset = static_cast<int>(fit.frame_candidates.size());
    for (const FrameCandidate& c : alt.frame_candidates) {
      fit.frame_candidates.push_back(c);
      fit.frame_candidates.back().name = to_string(alt.method()) + " fit, " + c.name;
    }
    if (replaces(score(alt.report()), score(fit.report()))) {
      alt.reason = fit.reason + "; the " + to_string(alt.method()) +
                   " fit in its best frame is closer (RMS distance " +
                   std::to_string(alt.report().error.rms) + " mm): " + to_string(alt.method());
      alt.frame_candidates = std::move(fit.frame_candidates);
      if (alt.chosen_candidate >= 0) alt.chosen_candidate += offset;
      return alt;
    }
  } catch (const InputError&) {
  } catch (const NumericalError&) {
  }
  return fit;
}

}  // namespace

RotationalFit fit_rotational(const Eigen::Matrix3Xd& points, const RotationalFitOptions& o) {
  const FrameOptions& given = o.spherical.frame;
  const bool both_given =
      given.origin && given.axis && o.cylindrical.frame.origin && o.cylindrical.frame.axis;
  if (points.cols() <= 2 * kFrameScorePoints || both_given)
    return choose_method_and_frame(points, o, false);
  // A large cloud: method and frame chosen on a subsample, the winner fitted to every point.
  const Eigen::Matrix3Xd sample = strided_columns(points, kFrameScorePoints);
  const RotationalFit decision = choose_method_and_frame(sample, o, true);
  RotationalFitOptions final_options = o;
  final_options.method = decision.method();
  const LocalFrame& frame = decision.frame().frame;
  for (FrameOptions* f : {&final_options.spherical.frame, &final_options.cylindrical.frame}) {
    f->origin = frame.origin;
    f->axis = frame.axes.col(2);
    f->reference = frame.axes.col(0);
  }
  Attempt a = attempt(decision.method(), points, final_options);
  if (!a.ok()) std::rethrow_exception(a.error);
  std::ostringstream why;
  why << decision.reason << "; method and frame chosen on " << sample.cols() << " of "
      << points.cols() << " points (frames with a fixed net), then fitted to every point";
  RotationalFit fit = result(decision.method(), a, why.str());
  std::visit(
      [&](auto& f) {
        f.frame.quadric = decision.frame().quadric;
        f.frame.reason = decision.frame().reason;
      },
      fit.fit);
  fit.frame_candidates = decision.frame_candidates;
  fit.chosen_candidate = decision.chosen_candidate;
  return fit;
}

namespace {

RotationalFit fit_chosen_method(const Eigen::Matrix3Xd& points, const RotationalFitOptions& o,
                                bool* undecided) {
  *undecided = false;
  if (o.method) {
    Attempt a = attempt(*o.method, points, o);
    if (!a.ok()) std::rethrow_exception(a.error);
    return result(*o.method, a, to_string(*o.method) + " fit requested");
  }
  QuadricFitOptions qo = o.spherical.frame.quadric;
  qo.threads = o.spherical.function.threads;
  const QuadricFit q = fit_quadric(points, qo);
  const QuadricType t = q.classification.type;
  std::ostringstream why;
  why.precision(4);
  why << "best-fit quadric: " << to_string(t);
  const bool sphere_like = t == QuadricType::real_ellipsoid;
  const bool cylinder_like = t == QuadricType::real_elliptic_cylinder || t == QuadricType::hyperboloid_of_one_sheet;
  if (sphere_like || cylinder_like) {
    const FitMethod first = sphere_like ? FitMethod::spherical : FitMethod::cylindrical;
    why << " suggests a " << to_string(first) << " fit";
    Attempt a = attempt(first, points, o);
    if (a.ok()) {
      why << " (RMS distance " << a.rms() << ")";
      return result(first, a, why.str());
    }
    Attempt b = attempt(other(first), points, o);
    if (!b.ok()) std::rethrow_exception(a.error);
    why << ", which failed (" << a.message << "); " << to_string(other(first)) << " fit instead (RMS distance "
        << b.rms() << ")";
    return result(other(first), b, why.str());
  }
  Attempt s = attempt(FitMethod::spherical, points, o), c = attempt(FitMethod::cylindrical, points, o);
  if (!s.ok() && !c.ok()) std::rethrow_exception(s.error);
  why << " does not decide; ";
  *undecided = true;
  if (s.ok() && c.ok()) {
    const FitMethod m = s.rms() <= c.rms() ? FitMethod::spherical : FitMethod::cylindrical;
    why << "RMS distance spherical " << s.rms() << ", cylindrical " << c.rms() << ": " << to_string(m);
    return result(m, m == FitMethod::spherical ? s : c, why.str());
  }
  Attempt& ok = s.ok() ? s : c;
  const FitMethod m = s.ok() ? FitMethod::spherical : FitMethod::cylindrical;
  why << "only the " << to_string(m) << " fit succeeded (RMS distance " << ok.rms() << "; the other: "
      << (s.ok() ? c.message : s.message) << ")";
  return result(m, ok, why.str());
}

}  // namespace

RotationalFit fit_rotational(const std::filesystem::path& file, const RotationalFitOptions& options,
                             const ReadOptions& read) {
  StageClock clock;
  const PointCloud cloud = read_point_cloud(file, read);
  const double t = clock.lap();
  RotationalFit fit = fit_rotational(cloud.points, options);
  FitReport& r = fit.report();
  r.times.read = t;
  r.times.total += t;
  return fit;
}

}  // namespace polarform
