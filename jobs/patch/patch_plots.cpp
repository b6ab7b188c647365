#include "jobs/patch/patch_plots.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

namespace polarform {

namespace {

// At most about 20 000 points in a figure (evenly strided).
Eigen::Index figure_stride(Eigen::Index n) { return std::max<Eigen::Index>(1, n / 20000); }

// Two unit vectors spanning the plane normal to n.
std::pair<Eigen::Vector3d, Eigen::Vector3d> plane_axes(const Eigen::Vector3d& n) {
  const Eigen::Vector3d a =
      (std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY()).cross(n);
  const Eigen::Vector3d e1 = a.normalized();
  return {e1, n.cross(e1).normalized()};
}

}  // namespace

Figure patch_decomposition_figure(const PatchJobResult& r) {
  const SurfaceBlanket& b = r.patch.decomposition.blanket;
  Figure f(1100, 520);
  f.title = "crack-free quad blanket of the " + base_kind_name(r.patch.base.kind) +
            " base surface: " + std::to_string(b.quads()) + " quads";
  Plot& domain = f.add_panel();
  domain.title = "parameter lines U × V";
  domain.x_label = "u";
  domain.y_label = "v";
  domain.x_range = AxisRange{0, 1};
  domain.y_range = AxisRange{0, 1};
  Series lines{"", {}, {}, Series::Style::line, "#14c"};
  for (const double u : b.u) {
    lines.x.insert(lines.x.end(), {u, u, NAN});
    lines.y.insert(lines.y.end(), {b.v.front(), b.v.back(), NAN});
  }
  for (const double v : b.v) {
    lines.x.insert(lines.x.end(), {b.u.front(), b.u.back(), NAN});
    lines.y.insert(lines.y.end(), {v, v, NAN});
  }
  domain.add(lines);
  Plot& plane = f.add_panel();
  plane.title = "blanket seen along the maximum-area normal";
  plane.x_label = "e1 [mm]";
  plane.y_label = "e2 [mm]";
  plane.equal_aspect = true;
  const auto [e1, e2] = plane_axes(r.patch.plane.normal);
  // The points under the edges, at most about 3000 of them, so the blanket stays visible.
  Series pts{"points", {}, {}, Series::Style::markers, "#e80"};
  const Eigen::Index stride = std::max<Eigen::Index>(1, r.points.cols() / 3000);
  for (Eigen::Index k = 0; k < r.points.cols(); k += stride) {
    pts.x.push_back(r.points.col(k).dot(e1));
    pts.y.push_back(r.points.col(k).dot(e2));
  }
  plane.add(pts);
  Series quads{"quad edges", {}, {}, Series::Style::line, "#14c"};
  const int nu = static_cast<int>(b.u.size()), nv = static_cast<int>(b.v.size());
  const auto add_polyline = [&](auto vertex_of, int count) {
    for (int k = 0; k < count; ++k) {
      const Eigen::Vector3d p = b.points.col(vertex_of(k));
      quads.x.push_back(p.dot(e1));
      quads.y.push_back(p.dot(e2));
    }
    quads.x.push_back(NAN);
    quads.y.push_back(NAN);
  };
  for (int a = 0; a < nu; ++a) add_polyline([&](int k) { return b.vertex(a, k); }, nv);
  for (int c = 0; c < nv; ++c) add_polyline([&](int k) { return b.vertex(k, c); }, nu);
  plane.add(quads);
  return f;
}

Figure patch_preview_figure(const PatchJobResult& r) {
  const PatchFit& p = r.patch;
  Figure f(1100, 450);
  f.title = "signed distance of every point from the fitted surface";
  for (const bool along_u : {true, false}) {
    Plot& plot = f.add_panel();
    plot.x_label = along_u ? "u" : "v";
    plot.y_label = "signed distance [mm]";
    Series d{"points", {}, {}, Series::Style::markers, "#14c"};
    const Eigen::VectorXd& t = along_u ? p.u : p.v;
    for (Eigen::Index k = 0; k < p.distances.size(); k += figure_stride(p.distances.size())) {
      d.x.push_back(t[k]);
      d.y.push_back(p.distances[k]);
    }
    plot.add(d);
    if (r.patch.fit.rounds.size() > 0 && p.error.max > 0) {
      plot.add_horizontal_line(p.error.rms, "+rms");
      plot.add_horizontal_line(-p.error.rms, "−rms");
    }
  }
  return f;
}

}  // namespace polarform
