#include "jobs/study/study_plots.h"

#include <algorithm>

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
  Figure f(900, 760);
  f.title = "Tolerance study: " + name;
  f.shared_x = true;
  std::vector<StudyRow> rows = r.rows;  // by increasing tolerance, as the lines run
  std::sort(rows.begin(), rows.end(),
            [](const StudyRow& a, const StudyRow& b) { return a.tolerance < b.tolerance; });
  std::vector<double> tol, q, rqb, cubic, qa, ra;
  for (const StudyRow& row : rows) {
    tol.push_back(row.tolerance);
    q.push_back(row.quartic.control_points);
    rqb.push_back(row.rqb.control_points);
    cubic.push_back(row.cubic.control_points);
    qa.push_back(row.quartic.arcs);
    ra.push_back(row.rqb.arcs);
  }
  Plot& points = f.add_panel();
  points.log_x = points.log_y = true;
  points.x_label = "tolerance ε [mm]";
  points.y_label = "control points";
  points.add(line("quasi-uniform quartic base (exact degree)", tol, q, "#0072b2"));
  points.add(line("RQB base", tol, rqb, "#e69f00"));
  points.add(line("cubic through sampled points", tol, cubic, "#999999"));
  Plot& arcs = f.add_panel();
  arcs.log_y = true;
  arcs.y_label = "base-circle arcs";
  arcs.add(line("quasi-uniform quartic", tol, qa, "#0072b2"));
  arcs.add(line("RQB", tol, ra, "#e69f00"));
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
