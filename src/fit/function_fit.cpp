#include "src/fit/function_fit.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "src/error.h"
#include "src/fit/coefficient_map.h"
#include "src/fit/fairness.h"
#include "src/fit/normal_equations.h"
#include "src/fit/spline_axis.h"
#include "src/nurbs/periodic.h"

namespace polarform {

namespace {

constexpr int kDefaultSize = 12;

const char* measure_name(ToleranceMeasure m) {
  switch (m) {
    case ToleranceMeasure::max: return "max";
    case ToleranceMeasure::p99: return "p99";
    case ToleranceMeasure::p95: return "p95";
    case ToleranceMeasure::rms: return "rms";
  }
  return "?";
}

double statistic(const ErrorStats& s, ToleranceMeasure m) {
  switch (m) {
    case ToleranceMeasure::max: return s.max;
    case ToleranceMeasure::p99: return s.p99;
    case ToleranceMeasure::p95: return s.p95;
    case ToleranceMeasure::rms: return s.rms;
  }
  return s.max;
}

}  // namespace

void check_control_net_size(int size_u, int size_v, const std::string& what) {
  const long coefficients = long(size_u) * size_v;
  if (coefficients > kMaxFitCoefficients)
    throw InputError(what + " " + std::to_string(size_u) + " x " + std::to_string(size_v) + ": " +
                     std::to_string(coefficients) + " coefficients, above the limit of " +
                     std::to_string(kMaxFitCoefficients) + " (e.g. 256 x 256)");
}

namespace {

void check_options(const FunctionFitOptions& o, const FunctionSpace& sp) {
  auto fail = [](const std::string& m) { throw InputError("function fit: " + m); };
  for (int d : {o.degree_u, o.degree_v})
    if (d < 0 || d > 10) fail("degree " + std::to_string(d) + ", expected 0..10");
  if (!(sp.u0 < sp.u1) || !(sp.v0 < sp.v1) || !std::isfinite(sp.u0 + sp.u1 + sp.v0 + sp.v1))
    fail("domain must be finite with u0 < u1 and v0 < v1");
  if (!(o.tolerance >= 0.0) || !std::isfinite(o.tolerance))
    fail("tolerance " + std::to_string(o.tolerance) + ", expected a finite value >= 0");
  if (o.size_u < 0 || o.size_v < 0) fail("control net size must be >= 0");
  check_control_net_size(o.size_u, o.size_v, "function fit: control net");
  if (!(o.constant_tolerance >= 0.0)) fail("constant_tolerance must be >= 0");
  if (sp.symmetric_v && !sp.periodic_v) fail("symmetric_v needs periodic_v");
  if (sp.pole_start < 0 || sp.pole_start > 2 || sp.pole_end < 0 || sp.pole_end > 2)
    fail("pole rows must be 0, 1 or 2");
}

// Spans of an axis with `size` coefficients (distinct ones when periodic).
int spans_for(int size, int degree, bool periodic) { return periodic ? size : size - degree; }

int start_size(int given, double tolerance, int degree, bool periodic, bool symmetric, int minimum) {
  int size = given > 0 ? given : tolerance > 0.0 ? (periodic ? std::max(degree + 1, 4) : degree + 1)
                                                 : kDefaultSize;
  size = std::max(size, minimum);
  if (symmetric && size % 2 != 0) ++size;
  return size;
}

SplineAxis make_axis(int degree, const std::vector<double>& breaks, bool periodic) {
  return periodic ? periodic_axis(degree, breaks) : clamped_axis(degree, breaks);
}

// Per-span value of the tolerance statistic of |err| over the samples of each span.
std::vector<double> span_statistic(const std::vector<int>& span_of, int spans,
                                   const Eigen::VectorXd& err, ToleranceMeasure m) {
  std::vector<std::vector<double>> bucket(static_cast<std::size_t>(spans));
  for (std::size_t k = 0; k < span_of.size(); ++k)
    bucket[static_cast<std::size_t>(span_of[k])].push_back(std::abs(err[static_cast<Eigen::Index>(k)]));
  std::vector<double> out(static_cast<std::size_t>(spans), 0.0);
  for (int s = 0; s < spans; ++s) {
    auto& b = bucket[static_cast<std::size_t>(s)];
    if (b.empty()) continue;
    Eigen::VectorXd v = Eigen::Map<Eigen::VectorXd>(b.data(), static_cast<Eigen::Index>(b.size()));
    out[static_cast<std::size_t>(s)] = statistic(error_stats(v), m);
  }
  return out;
}

// Flags for the spans to split: those above tol, worst first, within the size limit; with
// `symmetric` a span and its half-period partner go together.
std::vector<bool> choose_splits(const std::vector<double>& stat, double tol, int room, bool symmetric) {
  const int spans = static_cast<int>(stat.size());
  std::vector<int> order(spans);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return stat[a] > stat[b]; });
  std::vector<bool> split(static_cast<std::size_t>(spans), false);
  for (int s : order) {
    if (!(stat[s] > tol) || split[s]) continue;
    const int partner = symmetric ? (s + spans / 2) % spans : s;
    const int cost = partner == s ? 1 : 2;
    if (cost > room) continue;
    split[s] = split[partner] = true;
    room -= cost;
  }
  return split;
}

// F with degree 0 along v (u) when each row (column) of its net is constant within tol·max|f|.
BSplineSurface reduce_constant_v(const BSplineSurface& F, double tol, bool& reduced) {
  if (F.degree_v() == 0) return F;
  const int nu = F.size_u(), nv = F.size_v();
  const double scale = std::max(F.coefs().cwiseAbs().maxCoeff(), 1e-300);
  Eigen::MatrixXd c(1, nu);
  for (int i = 0; i < nu; ++i) {
    const auto row = F.coefs().middleCols(i * nv, nv);
    if (row.maxCoeff() - row.minCoeff() > tol * scale) return F;
    c(0, i) = row.mean();
  }
  reduced = true;
  return BSplineSurface(F.degree_u(), 0, F.knots_u(), {F.front_v(), F.back_v()}, std::move(c));
}

BSplineSurface transpose(const BSplineSurface& F) {
  const int nu = F.size_u(), nv = F.size_v();
  Eigen::MatrixXd c(1, nu * nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) c(0, j * nu + i) = F.coefs()(0, i * nv + j);
  return BSplineSurface(F.degree_v(), F.degree_u(), F.knots_v(), F.knots_u(), std::move(c));
}

}  // namespace

Eigen::VectorXd parametric_residuals(const BSplineSurface& F, const Samples& s, int threads) {
  Eigen::VectorXd r(static_cast<Eigen::Index>(s.size()));
  const double u0 = F.front_u(), u1 = F.back_u(), v0 = F.front_v(), v1 = F.back_v();
  parallel_chunks(s.size(), worker_count(threads, s.size()), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t k = b; k < e; ++k) {
      const Eigen::Index i = static_cast<Eigen::Index>(k);
      double f;
      F.point(std::clamp(s.u[i], u0, u1), std::clamp(s.v[i], v0, v1), &f);
      r[i] = f - s.value[i];
    }
  });
  return r;
}

FunctionFitResult fit_function(const Samples& samples, const FunctionSpace& space,
                               const FunctionFitOptions& o, const ErrorMeasure& measure_in) {
  validate_samples(samples);
  check_options(o, space);
  const ErrorMeasure measure =
      measure_in ? measure_in
                 : ErrorMeasure([&](const BSplineSurface& F, ProgressRange) {
                     return parametric_residuals(F, samples, o.threads);
                   });
  const int pu = o.degree_u, pv = o.degree_v;
  const int min_u = std::max(pu + 1, space.pole_start + space.pole_end + 1);
  const int min_v = space.periodic_v ? std::max(pv + 1, 2) : pv + 1;
  int size_u = start_size(o.size_u, o.tolerance, pu, false, false, min_u);
  int size_v = start_size(o.size_v, o.tolerance, pv, space.periodic_v, space.symmetric_v, min_v);
  const bool adaptive = o.tolerance > 0.0 && (o.size_u == 0 || o.size_v == 0);
  const bool adapt_u = adaptive && o.size_u == 0, adapt_v = adaptive && o.size_v == 0;

  FunctionFitResult out;
  StageClock clock;
  std::vector<double> bu = place_breaks(o.placement, spans_for(size_u, pu, false), samples.u, space.u0, space.u1);
  std::vector<double> bv =
      place_breaks(space.periodic_v ? KnotPlacement::uniform : o.placement,
                   spans_for(size_v, pv, space.periodic_v), samples.v, space.v0, space.v1);
  out.times.knots += clock.lap();
  ProgressRange progress(o.progress, 0.0, 1.0);
  for (;;) {
    const SplineAxis U = make_axis(pu, bu, false), V = make_axis(pv, bv, space.periodic_v);
    const CoefficientMap map(U.size(), V.size(), space.periodic_v ? V.distinct() : 0,
                             space.pole_start, space.pole_end);
    const Eigen::SparseMatrix<double> T = thin_plate_matrix(U, V, map);
    out.times.knots += clock.lap();
    const NormalEquations ne = assemble_normal_equations(U, V, map, samples, o.threads, progress.sub(0.0, 0.4));
    out.times.assembly += clock.lap();
    const RegularisedSolution sol = solve_regularised(ne, T, o.fairness);
    out.times.solve += clock.lap();
    BSplineSurface F(pu, pv, U.knots, V.knots, map.expand(sol.x).transpose());
    if (space.periodic_v) F = clip_v(F, space.v0, space.v1);  // Bae 2002, §3.3.1 clipping
    out.times.product += clock.lap();
    Eigen::VectorXd err = measure(F, progress.sub(0.4, 1.0));
    const ErrorStats stats = error_stats(err);
    out.times.error += clock.lap();
    out.F = std::move(F);
    out.size_u = U.distinct();
    out.size_v = V.distinct();
    out.lambda = sol.lambda;
    out.dof = sol.dof;
    out.errors = std::move(err);
    out.stats = stats;
    if (!adaptive || statistic(stats, o.measure) <= o.tolerance) break;

    // Knot refinement: split the spans whose own statistic exceeds the tolerance.
    std::vector<int> span_u(samples.size()), span_v(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k) {
      span_u[k] = span_index(bu, samples.u[static_cast<Eigen::Index>(k)]);
      span_v[k] = span_index(bv, samples.v[static_cast<Eigen::Index>(k)]);
    }
    const std::vector<bool> su =
        adapt_u ? choose_splits(span_statistic(span_u, static_cast<int>(bu.size()) - 1, out.errors, o.measure),
                                o.tolerance, o.max_size_u - size_u, false)
                : std::vector<bool>(bu.size() - 1, false);
    const std::vector<bool> sv =
        adapt_v ? choose_splits(span_statistic(span_v, static_cast<int>(bv.size()) - 1, out.errors, o.measure),
                                o.tolerance, o.max_size_v - size_v, space.symmetric_v)
                : std::vector<bool>(bv.size() - 1, false);
    const int add_u = static_cast<int>(std::count(su.begin(), su.end(), true));
    const int add_v = static_cast<int>(std::count(sv.begin(), sv.end(), true));
    if (add_u + add_v == 0) {
      std::ostringstream msg;
      msg << "function fit: tolerance " << o.tolerance << " (" << measure_name(o.measure)
          << ") not met: reached " << statistic(stats, o.measure) << " (rms " << stats.rms
          << ") with a " << size_u << " x " << size_v << " net (limits " << o.max_size_u << " x "
          << o.max_size_v << "); no span above the tolerance can be split further. The noise of"
          << " the data may exceed the tolerance: raise it, raise the limits, or measure p99/rms";
      throw NumericalError(msg.str());
    }
    bu = split_spans(bu, su);
    bv = split_spans(bv, sv);
    size_u += add_u;
    size_v += add_v;
    ++out.refinements;
    out.times.knots += clock.lap();
  }

  if (o.reduce_constant) {
    BSplineSurface F = reduce_constant_v(out.F, o.constant_tolerance, out.reduced_v);
    F = transpose(reduce_constant_v(transpose(F), o.constant_tolerance, out.reduced_u));
    if (out.reduced_u || out.reduced_v) {
      out.times.product += clock.lap();
      out.errors = measure(F, progress.sub(0.4, 1.0));
      out.stats = error_stats(out.errors);
      out.F = std::move(F);
      out.times.error += clock.lap();
    }
  }
  progress(1.0);
  return out;
}

CurveFunctionFit fit_curve_function(const Eigen::VectorXd& u, const Eigen::VectorXd& values, double u0,
                                    double u1, bool periodic, const FunctionFitOptions& options) {
  Samples s;
  s.u = Eigen::VectorXd::Zero(values.size());
  s.v = u;
  s.value = values;
  FunctionFitOptions o = options;
  o.degree_u = 0;
  o.size_u = o.max_size_u = 1;
  FunctionFitResult r = fit_function(s, FunctionSpace{0.0, 1.0, u0, u1, periodic}, o);
  return CurveFunctionFit{BSplineFunction(r.F.degree_v(), r.F.knots_v(), r.F.coefs().row(0).transpose()),
                          r.size_v, r.lambda, std::move(r.errors), r.stats, r.refinements, r.times};
}

}  // namespace polarform
