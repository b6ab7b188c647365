#include "src/fit/net_selection.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace polarform {

namespace {

long free_coefficients(const FunctionSpace& space, int size_u, int size_v) {
  long m = long(size_u) * size_v;
  for (int rows : {space.pole_start, space.pole_end})
    if (rows > 0) m -= long(rows) * size_v - 1;  // Bae 2002, (3.14): tied rows share one value
  return std::max(m, 1L);
}

// The net of a direction with `spans` uniform spans: one coefficient per span when periodic.
int size_of(int spans, int degree, bool periodic) { return periodic ? spans : spans + degree; }

// The fewest spans, a multiple of `arcs` (even when symmetric, (3.15)), giving at least `minimum`
// coefficients.
int first_spans(int arcs, int degree, bool periodic, bool symmetric, int minimum) {
  const int step = symmetric && arcs % 2 != 0 ? 2 * arcs : arcs;
  int spans = step;
  while (size_of(spans, degree, periodic) < minimum) spans += step;
  return spans;
}

// Half again as many spans, rounded up to a multiple of the arcs (and even when symmetric).
int grown_spans(int spans, int arcs, bool symmetric) {
  const int step = symmetric && arcs % 2 != 0 ? 2 * arcs : arcs;
  const int want = spans + std::max(1, spans / 2);
  return (want + step - 1) / step * step;
}

}  // namespace

Samples strided_subsample(const Samples& s, std::size_t count) {
  if (s.size() <= count) return s;
  const std::size_t stride = (s.size() + count - 1) / count;
  const Eigen::Index n = static_cast<Eigen::Index>((s.size() + stride - 1) / stride);
  Samples out;
  out.u.resize(n), out.v.resize(n), out.value.resize(n);
  if (s.weight.size()) out.weight.resize(n);
  for (Eigen::Index a = 0; a < n; ++a) {
    const Eigen::Index k = a * static_cast<Eigen::Index>(stride);
    out.u[a] = s.u[k], out.v[a] = s.v[k], out.value[a] = s.value[k];
    if (s.weight.size()) out.weight[a] = s.weight[k];
  }
  return out;
}

// GCV(m) = (RSS/n) / (1 − m/n)² (Craven & Wahba 1979) with m the free coefficients.
NetCandidate evaluate_net(const Samples& samples, const FunctionSpace& space,
                          const FunctionFitOptions& options, int size_u, int size_v) {
  FunctionFitOptions o = options;
  o.size_u = size_u, o.size_v = size_v;
  o.tolerance = 0.0;
  o.reduce_constant = false;
  o.progress = {};
  const FunctionFitResult fit = fit_function(samples, space, o);
  NetCandidate c;
  c.size_u = size_u, c.size_v = size_v;
  c.coefficients = free_coefficients(space, size_u, size_v);
  c.rms = fit.stats.rms;
  const double n = static_cast<double>(samples.size());
  const double shrink = std::max(1.0 - double(c.coefficients) / n, 1e-6);
  c.gcv = c.rms * c.rms / (shrink * shrink);
  return c;
}

NetSelection select_net(const Samples& all, const FunctionSpace& space,
                        const FunctionFitOptions& o) {
  const Samples s = strided_subsample(all, kSelectionSamples);
  NetSelection sel;
  sel.automatic = true;
  sel.samples = s.size();
  sel.max_coefficients = std::max(1L, long(s.size()) / kSamplesPerCoefficient);
  const bool free_u = o.size_u == 0 && o.max_size_u > 1, free_v = o.size_v == 0 && o.max_size_v > 1;
  const int min_u = std::max({o.degree_u + 1, 4, space.pole_start + space.pole_end + 1});
  const int min_v = std::max({o.degree_v + 1, 4, space.periodic_v ? 2 : 0});
  const int au = std::max(space.arcs_u, 1), av = std::max(space.arcs_v, 1);
  int spans_u = first_spans(au, o.degree_u, false, false, min_u);
  int spans_v = first_spans(av, o.degree_v, space.periodic_v, space.symmetric_v, min_v);
  const auto net_u = [&](int spans) {
    return free_u ? size_of(spans, o.degree_u, false) : o.size_u;
  };
  const auto net_v = [&](int spans) {
    return free_v ? size_of(spans, o.degree_v, space.periodic_v) : o.size_v;
  };
  int su = net_u(spans_u), sv = net_v(spans_v);
  auto fits = [&](int u, int v) {
    return u <= o.max_size_u && v <= o.max_size_v &&
           free_coefficients(space, u, v) <= sel.max_coefficients &&
           long(u) * v <= kMaxFitCoefficients;
  };
  NetCandidate best = evaluate_net(s, space, o, su, sv);
  sel.candidates.push_back(best);
  int stale = 0;
  for (;;) {
    struct Step {
      int spans_u, spans_v;
    };
    std::vector<Step> next;
    const int gu = grown_spans(spans_u, au, false),
              gv = grown_spans(spans_v, av, space.symmetric_v);
    if (free_u && fits(net_u(gu), sv)) next.push_back({gu, spans_v});
    if (free_v && fits(su, net_v(gv))) next.push_back({spans_u, gv});
    if (free_u && free_v && fits(net_u(gu), net_v(gv))) next.push_back({gu, gv});
    if (next.empty() && !free_u && !free_v) {
      sel.stop = "the net is given: nothing to grow";
      break;
    }
    if (next.empty()) {
      std::ostringstream why;
      why << "no larger net within the rule of at most one coefficient per "
          << kSamplesPerCoefficient << " samples (" << sel.max_coefficients
          << ") and the size limits (" << o.max_size_u << " x " << o.max_size_v << ")";
      sel.stop = why.str();
      break;
    }
    NetCandidate step;
    Step taken{};
    for (const Step& n : next) {
      const int u = net_u(n.spans_u), v = net_v(n.spans_v);
      const auto seen =
          std::find_if(sel.candidates.begin(), sel.candidates.end(),
                       [&](const NetCandidate& c) { return c.size_u == u && c.size_v == v; });
      const NetCandidate c = seen != sel.candidates.end() ? *seen : evaluate_net(s, space, o, u, v);
      if (seen == sel.candidates.end()) sel.candidates.push_back(c);
      if (step.coefficients == 0 || c.gcv < step.gcv) step = c, taken = n;
    }
    // No gain: go on from the largest net tried (the error need not fall monotonically with the
    // spans, e.g. where spans and base arcs do not line up).
    const bool gain = step.gcv < best.gcv * (1.0 - kGcvImprovement);
    if (!gain) taken = next.back();
    spans_u = taken.spans_u, spans_v = taken.spans_v;
    su = net_u(spans_u), sv = net_v(spans_v);
    if (gain) {
      best = step, stale = 0;
    } else if (++stale >= 2) {
      sel.noise_reached = true;
      sel.stop = "GCV improved by less than " + std::to_string(int(kGcvImprovement * 100)) +
                 " % over two larger nets: the residual has reached the noise level";
      break;
    }
  }
  sel.size_u = best.size_u, sel.size_v = best.size_v;
  const double n = static_cast<double>(s.size());
  sel.noise = best.rms * std::sqrt(n / std::max(n - double(best.coefficients), 1.0));
  return sel;
}

}  // namespace polarform
