#include "designers/convert/polar_conversion.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stop_token>
#include <string>

#include "designers/convert/arc_layout.h"
#include "designers/convert/conversion_error.h"
#include "designers/convert/degree_limited.h"
#include "designers/convert/function_spline.h"
#include "designers/convert/measured_knot_removal.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/nurbs/curve_join.h"
#include "src/nurbs/curve_reversal.h"
#include "src/nurbs/symbolic_product.h"
#include "src/task_pool.h"

namespace polarform {

namespace {

constexpr std::size_t kMaxArcs = 2000;
// The refit's degrees (the fewest control points wins: 4 and 5 on cam profiles with jumps in
// their derivatives, 6 on near-circular heads, 3 where the others fold) and its effort: a coarser
// table of R than the export's, half its Lawson steps, a third of its placement rounds and 8
// knot removals tried rather than 20, two degrees fitted to the end. Measured on the 66 rows of
// tests/jobs/study/peer_counts_test.cpp: 10 placement rounds give the same 1418 control points
// in all as 30, and take 125 M instructions against 153 M (callgrind, the whole
// BM_RollerCamConversion1um run, about 30 M of it the program's start); 8 removals (the most
// removable first) give 1419 against 1418 with 20 and 1426 with 6, in 109 M against 115 M.
const std::vector<int> kRefitDegrees = {3, 4, 5, 6};
constexpr LimitedEffort kRefitEffort = {512, 10, 4, 8, 2};

// Measures every arc of C; returns the indices of the arcs over the tolerance. `every_core`: the
// pool's threads take arcs too (for the refit, measured when nothing else runs).
std::vector<int> measure_arcs(const NurbsCurve2d& C, const PolarFunction& R,
                              const std::vector<double>& breaks, PolarConversion& out,
                              bool every_core = false) {
  const std::size_t arcs = breaks.size() - 1;
  std::vector<ProfileError> errors(arcs);
  in_parallel(arcs, every_core ? 1 : arcs,
              [&](std::size_t j) { errors[j] = profile_error(C, R, breaks[j], breaks[j + 1]); });
  std::vector<int> failing;
  out.arcs.clear();
  out.max_radial_error = out.max_normal_error = 0.0;
  for (std::size_t j = 0; j < arcs; ++j) {
    const ProfileError& e = errors[j];
    out.arcs.push_back({breaks[j], breaks[j + 1] - breaks[j], e.max_radial});
    if (e.max_radial > out.max_radial_error) {
      out.max_radial_error = e.max_radial;
      out.worst_angle = e.at_angle;
    }
    out.max_normal_error = std::max(out.max_normal_error, e.max_normal);
    if (e.max_radial > out.tolerance) failing.push_back(static_cast<int>(j));
  }
  return failing;
}

// The mirror image of C (over [a, b]) in the line through the origin at polar angle m, traversed
// back over [2m − b, 2m − a]: its point at u is C(2m − u) reflected.
NurbsCurve2d mirror_image(const NurbsCurve2d& C, double m) {
  const NurbsCurve2d back = reversed(C);  // C(a + b − v) on [a, b]
  Knots knots = back.knots();
  for (double& u : knots) u += 2 * m - C.front() - C.back();
  Eigen::Matrix2d S;  // the reflection in the line
  S << std::cos(2 * m), std::sin(2 * m), std::sin(2 * m), -std::cos(2 * m);
  NurbsCurve2d::Points points = back.control_points();
  for (NurbsCurve2d::Point& P : points) P = S * P;
  return NurbsCurve2d(C.degree(), std::move(knots), points, back.weights());
}

// The refit with the fewest control points: a closed R's in one periodic piece; an open R's piece
// by piece between its breakpoints (each with R's end points and end tangents), joined — so that a
// vessel head meets its shell along the shell's tangent. A mirror-symmetric R's pieces up to the
// last breakpoint before the mirror line so, then the piece across the line as one curve that is
// its own mirror image (its control values tied in pairs: the apex on the axis, level, and no
// joint there), then the first pieces' mirror images. The coarse table first; where it misses a
// sharp turn of R, the export's effort. Each piece verified against R's table when `on_table` (the
// caller measures the result against R itself). Nothing if neither reaches tol or `stop` is
// requested.
std::optional<LimitedCurve> fewest_control_points_refit(const PolarFunction& R, double tol,
                                                        bool on_table, std::stop_token stop) {
  const auto fit = [&](const PolarFunction& piece, Mirror mirror) {
    LimitedEffort lean = kRefitEffort, full{.finalists = 2};
    lean.verify_on_table = full.verify_on_table = on_table;
    try {
      return fewest_control_points(piece, kRefitDegrees, tol, lean, stop, mirror);
    } catch (const NumericalError&) {
      return fewest_control_points(piece, kRefitDegrees, tol, full, stop, mirror);
    }
  };
  try {
    if (R.closed() || R.breakpoints.empty()) return fit(R, Mirror::none);
    const bool mirrored = mirror_symmetric(R, tol);
    const double end = mirrored ? 0.5 * (R.start + R.end) : R.end;
    std::vector<double> bounds{R.start};
    for (double b : R.breakpoints)
      if (b < end) bounds.push_back(b);
    bounds.push_back(end);
    std::vector<NurbsCurve2d> pieces;
    for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
      PolarFunction piece = R;
      piece.start = bounds[k], piece.end = bounds[k + 1];
      piece.breakpoints.clear();
      piece.exact.reset();
      const bool across = mirrored && k + 2 == bounds.size();
      pieces.push_back(fit(piece, across ? Mirror::at_end : Mirror::none).curve);
    }
    for (std::size_t k = pieces.size() - 1; mirrored && k-- > 0;)
      pieces.push_back(mirror_image(pieces[k], end));
    LimitedCurve out;
    out.curve = join_curves(pieces);
    out.control_points = out.curve.size();
    return out;
  } catch (const NumericalError&) {
    return std::nullopt;  // knot removal stands in
  }
}

// Replaces out's curve by the refit `on_table` (verified on R's table) when it has fewer control
// points and every arc, measured against R, meets the tolerance; should R itself reject it, by
// the refit verified on R. False (out unchanged) otherwise.
bool refit(const PolarFunction& R, const std::vector<double>& breaks,
           std::optional<LimitedCurve> on_table, PolarConversion& out) {
  for (bool first : {true, false}) {
    std::optional<LimitedCurve> r =
        first ? std::move(on_table) : fewest_control_points_refit(R, out.tolerance, false, {});
    if (!r || r->control_points >= out.curve.size()) return false;
    PolarConversion refitted = out;
    refitted.curve = std::move(r->curve);
    if (measure_arcs(refitted.curve, R, breaks, refitted, true).empty()) {
      out = std::move(refitted);
      return true;
    }
  }
  return false;
}

}  // namespace

PolarConversion convert_polar_function(const PolarFunction& R, const ConversionOptions& options) {
  if (!(options.tolerance > 0)) throw InputError("conversion: tolerance must be > 0 mm");
  if (!(options.function_share > 0 && options.function_share < 1))
    throw InputError("conversion: function_share must lie in (0, 1)");
  if (R.end - R.start > 2 * std::numbers::pi + 1e-12)
    throw InputError("conversion: angular domain exceeds 360°");

  // The refit needs only R and ε: it runs as a task of its own while the product is built and
  // measured (and is stopped, should the product fail); waiting for it, this thread takes its
  // queued work.
  std::stop_source stop_refit;
  Task<std::optional<LimitedCurve>> refitting;
  if (options.compaction == Compaction::refit)
    refitting = run_task([&R, &options, stop = stop_refit.get_token()] {
      if (stop.stop_requested()) return std::optional<LimitedCurve>();  // the product failed first
      return fewest_control_points_refit(R, options.tolerance, true, stop);
    });
  struct StopOnExit {
    std::stop_source& source;
    ~StopOnExit() { source.request_stop(); }  // before `refitting` waits for the refit
  } stop_on_exit{stop_refit};

  PolarConversion out;
  out.tolerance = options.tolerance;
  const FunctionSpline F = represent_as_bspline(R, options.function_share * options.tolerance);
  out.function = F.spline;
  out.function_error = F.max_error;
  out.function_exact = F.exact;

  const double arc_budget = options.tolerance - F.max_error;
  std::vector<double> breaks = layout_arcs(
      F.spline, R.breakpoints, {options.base, options.alpha, 0.9 * arc_budget});

  // Build, measure, and split every arc the measurement rejects, until all arcs pass.
  for (int round = 0;; ++round) {
    out.base = BaseCircle(options.base, breaks, options.alpha);
    out.curve = product(F.spline, out.base.curve());
    const std::vector<int> failing = measure_arcs(out.curve, R, breaks, out);
    if (failing.empty()) break;
    // Splitting can only approach the round-off floor of R's evaluation; stop long before the
    // arc count explodes.
    if (round == 20 || breaks.size() + failing.size() > kMaxArcs + 1)
      throw NumericalError("conversion: measured error " + number_text(out.max_radial_error) +
                           " mm still exceeds the tolerance " + number_text(options.tolerance) +
                           " mm with " + std::to_string(breaks.size() - 1) +
                           " arcs; the tolerance is below what this profile can reach");
    for (auto j = failing.rbegin(); j != failing.rend(); ++j)
      breaks.insert(breaks.begin() + *j + 1, 0.5 * (breaks[*j] + breaks[*j + 1]));
  }

  out.steps.push_back({"product", out.curve.size(), out.max_radial_error});
  // The base arcs' synchronisation with F (whichever curve is kept), while the refit runs.
  out.synchronization_error = 0.0;
  for (std::size_t j = 0; j + 1 < breaks.size(); ++j)
    out.synchronization_error = std::max(
        out.synchronization_error, arc_synchronization_error(F.spline, breaks[j], breaks[j + 1],
                                                             options.base, options.alpha, 64));
  const PolarConversion product_only = out;
  if (options.compaction == Compaction::refit && refit(R, breaks, refitting.get(), out)) {
    out.steps.push_back({"refit", out.curve.size(), out.max_radial_error});
  } else {
    // Knot removal within the budget the measured error left; kept only if the whole curve,
    // measured again, still meets the tolerance.
    const MeasuredRemoval removal =
        options.compaction == Compaction::none
            ? MeasuredRemoval{out.curve, 0}
            : remove_knots_within(out.curve, R, options.tolerance,
                                  options.compaction == Compaction::between_breakpoints
                                      ? R.breakpoints
                                      : std::vector<double>{});
    if (removal.removed > 0) {
      out.curve = removal.curve;
      if (!measure_arcs(out.curve, R, breaks, out).empty()) out = product_only;
    }
    out.steps.push_back({"knot removal", out.curve.size(), out.max_radial_error});
  }

  out.max_tangent_jump =
      max_tangent_jump(out.curve, std::vector<double>(breaks.begin() + 1, breaks.end() - 1));
  return out;
}

}  // namespace polarform
