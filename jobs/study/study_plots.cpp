#include "jobs/study/study_plots.h"

#include <algorithm>
#include <cmath>

#include "src/units.h"

namespace polarform {

namespace {

Series line(std::string label, std::vector<double> x, std::vector<double> y, std::string color) {
  Series s;
  s.label = std::move(label);
  s.x = std::move(x);
  s.y = std::move(y);
  s.style = Series::Style::line_markers;
  s.color = std::move(color);
  return s;
}

}  // namespace

Figure study_figure(const StudyJobResult& r, const std::string& name) {
  std::vector<StudyRow> rows = r.rows;  // by increasing tolerance, as the lines run
  std::sort(rows.begin(), rows.end(),
            [](const StudyRow& a, const StudyRow& b) { return a.tolerance < b.tolerance; });
  // A peer that found no curve leaves a gap.
  const auto peer_points = [](const StudyPeerResult& p) {
    return p.found ? double(p.control_points) : StudyPeerRatios::kNone;
  };
  std::vector<double> tol, q, rqb, cubic, exact, degree3, occt3, occt_best, sisl3, sisl_best, qa,
      ra;
  std::vector<double> exact_ratio, degree3_ratio;
  for (const StudyRow& row : rows) {
    tol.push_back(row.tolerance);
    q.push_back(row.quartic.control_points);
    rqb.push_back(row.rqb.control_points);
    cubic.push_back(row.cubic.control_points);
    exact.push_back(row.exact.control_points);
    degree3.push_back(row.degree3.control_points);
    occt3.push_back(peer_points(row.occt_degree3));
    occt_best.push_back(peer_points(row.occt_best));
    sisl3.push_back(peer_points(row.sisl_degree3));
    sisl_best.push_back(peer_points(row.sisl_best));
    exact_ratio.push_back(row.ratios.exact_to_best);
    degree3_ratio.push_back(row.ratios.degree3_to_best);
    qa.push_back(row.quartic.arcs);
    ra.push_back(row.rqb.arcs);
  }
  const auto finite = [](double v) { return std::isfinite(v); };
  const bool ratio_panel = std::any_of(exact_ratio.begin(), exact_ratio.end(), finite);
  Figure f(900, ratio_panel ? 1000 : 760);
  f.title = "Tolerance study: " + name;
  f.shared_x = true;
  Plot& points = f.add_panel();
  points.log_x = points.log_y = true;
  points.x_label = "tolerance ε [mm]";
  points.y_label = "control points";
  points.add(line("quasi-uniform quartic base (exact degree)", tol, q, "#0072b2"));
  points.add(line("RQB base", tol, rqb, "#e69f00"));
  points.add(line("cubic through sampled points", tol, cubic, "#999999"));
  points.add(line("exact form, compacted", tol, exact, "#009e73"));
  points.add(line("degree 3, knots by need", tol, degree3, "#cc79a7"));
  if (r.peers) {
    points.add(line("OCCT PointsToBSpline, degree 3", tol, occt3, "#d55e00"));
    points.add(line("OCCT PointsToBSpline, degrees 3..8", tol, occt_best, "#000000"));
    points.add(line("SISL s1961, degree 3", tol, sisl3, "#56b4e9"));
    points.add(line("SISL s1961, best of degrees 3..8", tol, sisl_best, "#f0e442"));
  }
  Plot& arcs = f.add_panel();
  arcs.log_y = true;
  arcs.y_label = "base-circle arcs";
  arcs.add(line("quasi-uniform quartic", tol, qa, "#0072b2"));
  arcs.add(line("RQB", tol, ra, "#e69f00"));
  if (ratio_panel) {
    Plot& ratios = f.add_panel();
    ratios.y_label = "control points / best peer fit";
    ratios.add(line("exact form, compacted", tol, exact_ratio, "#009e73"));
    ratios.add(line("degree 3, knots by need", tol, degree3_ratio, "#cc79a7"));
  }
  return f;
}

Figure deviation_figure(const StudyJobResult& r) {
  Figure f(900, 560);
  f.title = "Max angle deviation of a base arc (Bae 2002, Fig. 5.4)";
  Plot& plot = f.add_panel();
  plot.log_x = plot.log_y = true;
  plot.x_label = "arc angle 2φ [deg]";
  plot.y_label = "max |ξ(η) − 2φη| [rad]";
  std::vector<double> x, rqb, minimax, printed;
  for (const DeviationRow& d : r.deviation) {
    x.push_back(d.arc_angle * kDegreesPerRadian);
    rqb.push_back(d.rqb);
    minimax.push_back(d.quartic_minimax);
    printed.push_back(d.quartic_printed);
  }
  auto series = [](std::string label, std::vector<double> x, std::vector<double> y, Series::Style s,
                   std::string color) {
    Series out;
    out.label = std::move(label), out.x = std::move(x), out.y = std::move(y), out.style = s;
    out.color = std::move(color);
    return out;
  };
  plot.add(series("RQB arc", x, rqb, Series::Style::line, "#e69f00"));
  plot.add(series("quartic, minimax α", x, minimax, Series::Style::line, "#0072b2"));
  plot.add(series("quartic, printed α", x, printed, Series::Style::dashed, "#56b4e9"));
  return f;
}

}  // namespace polarform
