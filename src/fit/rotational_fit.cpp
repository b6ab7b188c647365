#include "src/fit/rotational_fit.h"

#include <exception>
#include <sstream>

#include "src/error.h"
#include "src/fit/f_distribution.h"
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
// absorbs the tilt is not closer than that. Otherwise the smaller rms distance wins.
bool replaces(const Score& a, const Score& b) {
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
  return a.rms < b.rms;
}

std::string describe(const FrameCandidate& c) {
  std::ostringstream o;
  o.precision(4);
  if (!c.failure.empty()) return c.name + ": failed (" + c.failure + ")";
  o << c.name << ": RMS distance " << c.rms << " mm, " << (c.rotational ? "F(u) alone" : "F(u, v)");
  if (c.p_value >= 0.0) o << " (p = " << c.p_value << ")";
  return o.str();
}

// The chosen fit against the same method in the other frames (Bae 2002, §4.3 frame kept as the
// first candidate): the least-squares axis line and the PCA axis refined by the rotational
// criterion for cylindrical fits, the least-squares centre for spherical ones; `replaces` decides.
RotationalFit choose_frame(RotationalFit fit, const Eigen::Matrix3Xd& points,
                           const RotationalFitOptions& o) {
  const bool spherical = fit.method() == FitMethod::spherical;
  const FrameOptions& given = spherical ? o.spherical.frame : o.cylindrical.frame;
  if ((given.origin && given.axis) || (spherical && given.origin)) return fit;
  const FrameEstimate used = fit.frame();
  std::vector<FrameCandidate> list;
  list.emplace_back();
  list.back().name = given.axis || given.origin ? "given / quadric" : "quadric";
  list.back().origin = used.frame.origin;
  list.back().axis = used.frame.axes.col(2);
  list.back().how = used.reason;
  fill(list.back(), fit.report());
  if (spherical) {
    list.push_back(least_squares_centre(points, used.frame.origin, used.frame.axes.col(2)));
  } else {
    list.push_back(least_squares_axis(points, used.frame.origin, used.frame.axes.col(2),
                                      given.origin.has_value(), given.axis.has_value()));
    if (!given.origin && !given.axis)
      list.push_back(
          profile_refined_axis(points, {{"quadric", used.frame.origin, used.frame.axes.col(2)},
                                        {"least-squares axis", list[1].origin, list[1].axis}}));
  }
  std::size_t chosen = 0;
  Score best = score(fit.report());
  std::optional<RotationalFit> replacement;
  for (std::size_t i = 1; i < list.size(); ++i) {
    FrameCandidate& c = list[i];
    RotationalFitOptions again = o;
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
    if (!replaces(score(rep), best)) continue;
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
    return std::move(r);
  }
  fit.reason += why.str();
  fit.frame_candidates = std::move(list);
  return fit;
}

RotationalFit fit_chosen_method(const Eigen::Matrix3Xd& points, const RotationalFitOptions& o,
                                bool* undecided);

}  // namespace

RotationalFit fit_rotational(const Eigen::Matrix3Xd& points, const RotationalFitOptions& o) {
  bool undecided = false;
  RotationalFit fit = choose_frame(fit_chosen_method(points, o, &undecided), points, o);
  if (!undecided) return fit;
  // The quadric type did not decide the method: the other method in its least-squares frame is
  // one more candidate.
  RotationalFitOptions other_method = o;
  other_method.method =
      fit.method() == FitMethod::spherical ? FitMethod::cylindrical : FitMethod::spherical;
  try {
    RotationalFit alt =
        choose_frame(fit_chosen_method(points, other_method, &undecided), points, other_method);
    for (const FrameCandidate& c : alt.frame_candidates) {
      fit.frame_candidates.push_back(c);
      fit.frame_candidates.back().name = to_string(alt.method()) + " fit, " + c.name;
    }
    if (replaces(score(alt.report()), score(fit.report()))) {
      alt.reason = fit.reason + "; the " + to_string(alt.method()) +
                   " fit in its best frame is closer (RMS distance " +
                   std::to_string(alt.report().error.rms) + " mm): " + to_string(alt.method());
      alt.frame_candidates = std::move(fit.frame_candidates);
      return alt;
    }
  } catch (const InputError&) {
  } catch (const NumericalError&) {
  }
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
