#include "jobs/sweep/sweep_plots.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace polarform {

namespace {

// At most about 20 000 points in a figure (evenly strided).
Eigen::Index figure_stride(Eigen::Index n) { return std::max<Eigen::Index>(1, n / 20000); }

}  // namespace

Figure sweep_profile_figure(const SweepJobResult& r) {
  const SweptFit& v = r.fit();
  Figure f(900, 600);
  f.title = (r.is_sections    ? "sections of "
             : r.is_extrusion ? "section of "
                              : "meridian profile of ") +
            r.input.filename().string();
  Plot& p = f.add_panel();
  p.x_label = r.is_sections    ? "x in the station frame [mm]"
              : r.is_extrusion ? "x in the section plane [mm]"
                               : "z along the axis [mm]";
  p.y_label = r.is_sections    ? "y in the station frame [mm]"
              : r.is_extrusion ? "y in the section plane [mm]"
                               : "r from the axis [mm]";
  p.equal_aspect = true;
  Series pts{"projected points", {}, {}, Series::Style::markers, "#9ab"};
  for (Eigen::Index k = 0; k < v.plane.cols(); k += figure_stride(v.plane.cols())) {
    pts.x.push_back(v.plane(0, k));
    pts.y.push_back(v.plane(1, k));
  }
  p.add(pts);
  for (std::size_t l = 0; l < v.profile.loops.size(); ++l) {
    const MeridianLoop& loop = v.profile.loops[l];
    const std::string tag = v.profile.loops.size() > 1 ? " " + std::to_string(l + 1) : "";
    Series fitted{l > 0             ? ""
                  : r.is_sections   ? "slab points"
                  : v.profile.rings ? "ring points"
                                    : "thinned points",
                  {},
                  {},
                  Series::Style::markers,
                  "#e80"};
    for (Eigen::Index k = 0; k < loop.points.cols(); k += figure_stride(loop.points.cols())) {
      fitted.x.push_back(loop.points(0, k));
      fitted.y.push_back(loop.points(1, k));
    }
    p.add(fitted);
    Series curve{r.is_sections ? (l == 0 ? "sections" : "") : "profile" + tag,
                 {},
                 {},
                 Series::Style::line,
                 "#14c"};
    for (int s = 0; s <= 2000; ++s) {
      const Eigen::Vector2d q = loop.curve.point(
          loop.curve.front() + (loop.curve.back() - loop.curve.front()) * s / 2000);
      curve.x.push_back(q.x());
      curve.y.push_back(q.y());
    }
    p.add(curve);
    if (!loop.corners.empty()) {
      Series c{l == 0 ? "corners" : "", {}, {}, Series::Style::markers, "#c00"};
      for (const Eigen::Vector2d& q : loop.corners) c.x.push_back(q.x()), c.y.push_back(q.y());
      p.add(c);
    }
  }
  return f;
}

Figure sweep_preview_figure(const SweepJobResult& r) {
  const SweptFit& v = r.fit();
  Figure f(900, 450);
  f.title = r.is_sections    ? "deviation of every point from the skinned surface"
            : r.is_extrusion ? "deviation of every point from the extruded surface"
                             : "deviation of every point from the surface of revolution";
  Plot& p = f.add_panel();
  p.x_label = r.is_sections    ? "s along the spine [mm]"
              : r.is_extrusion ? "angle φ about the section's centroid [°]"
                               : "z along the axis [mm]";
  p.y_label = "signed distance [mm]";
  Series d{"points", {}, {}, Series::Style::markers, "#14c"};
  for (Eigen::Index k = 0; k < v.distances.size(); k += figure_stride(v.distances.size())) {
    d.x.push_back(r.is_sections ? r.sections->s[k]
                  : r.is_extrusion
                      ? std::atan2(v.plane(1, k), v.plane(0, k)) * 180 / std::numbers::pi
                      : v.plane(0, k));
    d.y.push_back(v.distances[k]);
  }
  p.add(d);
  p.add_horizontal_line(v.tolerance, "+tol");
  p.add_horizontal_line(-v.tolerance, "−tol");
  return f;
}

}  // namespace polarform
