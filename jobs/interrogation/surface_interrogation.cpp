#include "jobs/interrogation/surface_interrogation.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "export/atomic_file.h"
#include "export/colormap.h"
#include "export/ply_writer.h"
#include "export/x3d_writer.h"
#include "src/nurbs/tessellation.h"

namespace polarform {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const std::vector<double>& values_of(const InterrogatedSurface& s, CurvatureQuantity q) {
  return q == CurvatureQuantity::gaussian ? s.gaussian
         : q == CurvatureQuantity::mean   ? s.mean
                                          : s.absolute;
}

// The range of the quantity shown.
std::pair<double, double> shown_range(const SurfaceInterrogation& q) {
  switch (q.shown) {
    case CurvatureQuantity::gaussian:
      return {q.min_gaussian, q.max_gaussian};
    case CurvatureQuantity::mean:
      return {q.min_mean, q.max_mean};
    case CurvatureQuantity::absolute:
      break;
  }
  return {q.min_absolute, q.max_absolute};
}

void min_max(const std::vector<double>& v, double& lo, double& hi, bool& first) {
  for (const double x : v) {
    if (!std::isfinite(x)) continue;
    if (first) lo = hi = x, first = false;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
}

struct AreaByClass {
  double elliptic = 0, hyperbolic = 0, parabolic = 0;
};

// -1, 0, +1: hyperbolic, parabolic (|K| <= threshold, or no normal), elliptic.
int curvature_class(const NurbsSurface& s, double u, double v, double threshold) {
  const double k = surface_curvature(s, u, v).gaussian;
  return k > threshold ? 1 : k < -threshold ? -1 : 0;
}

// The area of a parameter rectangle by 2 × 2 Gauss–Legendre on |S_u × S_v|.
double cell_area(const NurbsSurface& s, double u0, double u1, double v0, double v1) {
  const double g = 0.5 / std::sqrt(3.0);
  double a = 0;
  for (const double su : {0.5 - g, 0.5 + g})
    for (const double sv : {0.5 - g, 0.5 + g}) {
      const NurbsSurface::Points d = s.derivatives(u0 + su * (u1 - u0), v0 + sv * (v1 - v0), 1);
      a += 0.25 * d[2].cross(d[1]).norm();
    }
  return a * (u1 - u0) * (v1 - v0);
}

// A cell whose corners and centre agree on the class of K is all of that class; a mixed one is
// quartered, down to `depth` levels, where its centre decides: the K = 0 curves are followed to
// 2^-depth of a cell.
void classify_area(const NurbsSurface& s, double u0, double u1, double v0, double v1,
                   double threshold, int depth, AreaByClass& out) {
  const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
  const int c = curvature_class(s, um, vm, threshold);
  bool same = true;
  for (const double u : {u0, u1})
    for (const double v : {v0, v1}) same = same && curvature_class(s, u, v, threshold) == c;
  if (same || depth == 0) {
    (c > 0 ? out.elliptic : c < 0 ? out.hyperbolic : out.parabolic) += cell_area(s, u0, u1, v0, v1);
    return;
  }
  classify_area(s, u0, um, v0, vm, threshold, depth - 1, out);
  classify_area(s, um, u1, v0, vm, threshold, depth - 1, out);
  classify_area(s, u0, um, vm, v1, threshold, depth - 1, out);
  classify_area(s, um, u1, vm, v1, threshold, depth - 1, out);
}

// Lights from the surfaces' vertices: the plane above them along the mean normal, the lines along
// the direction of largest spread across it, 20 stripes over the size, seen from above.
ReflectionLights choose_lights(const std::vector<InterrogatedSurface>& all) {
  Eigen::Vector3d mean_normal = Eigen::Vector3d::Zero(), centre = Eigen::Vector3d::Zero();
  std::size_t n = 0;
  for (const InterrogatedSurface& s : all)
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      centre += s.points[i];
      ++n;
    }
  centre /= static_cast<double>(std::max<std::size_t>(n, 1));
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  double size = 0;
  for (const InterrogatedSurface& s : all) {
    for (const Eigen::Vector3d& p : s.points) {
      scatter += (p - centre) * (p - centre).transpose();
      size = std::max(size, (p - centre).norm());
    }
    for (const Eigen::Vector3d& nn : s.normals) mean_normal += nn;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
  Eigen::Vector3d m = mean_normal.norm() > 1e-9 * static_cast<double>(n)
                          ? mean_normal.normalized()
                          : Eigen::Vector3d(eig.eigenvectors().col(0));
  Eigen::Vector3d line = eig.eigenvectors().col(2);
  line -= line.dot(m) * m;
  if (line.norm() < 1e-9) line = m.unitOrthogonal();
  ReflectionLights l;
  l.plane_normal = m;
  l.line = line.normalized();
  l.view = -m;
  l.plane_offset = m.dot(centre) + 2 * std::max(size, 1e-9);
  l.spacing = std::max(size, 1e-9) / 10;
  return l;
}

}  // namespace

std::string curvature_quantity_name(CurvatureQuantity q) {
  return q == CurvatureQuantity::gaussian ? "gauss"
         : q == CurvatureQuantity::mean   ? "mean"
                                          : "absolute";
}

SurfaceInterrogation interrogate_surfaces(const std::vector<NurbsSurface>& surfaces,
                                          CurvatureQuantity shown, int steps) {
  SurfaceInterrogation q;
  q.shown = shown;
  for (const NurbsSurface& s : surfaces) {
    InterrogatedSurface is;
    is.surface = s;
    const SurfaceTessellation t = tessellate(s, steps, steps);
    is.u = t.u;
    is.v = t.v;
    is.points = t.points;
    is.normals = t.normals;
    for (std::size_t i = 0; i < t.u.size(); ++i)
      for (std::size_t j = 0; j < t.v.size(); ++j) {
        const SurfaceCurvature c = surface_curvature(s, t.u[i], t.v[j]);
        is.gaussian.push_back(c.gaussian);
        is.mean.push_back(c.mean);
        is.absolute.push_back(c.degenerate ? kNaN : c.absolute());
      }
    q.surfaces.push_back(std::move(is));
  }
  bool fg = true, fm = true, fa = true;
  for (const InterrogatedSurface& s : q.surfaces) {
    min_max(s.gaussian, q.min_gaussian, q.max_gaussian, fg);
    min_max(s.mean, q.min_mean, q.max_mean, fm);
    min_max(s.absolute, q.min_absolute, q.max_absolute, fa);
  }
  const double parabolic = 1e-9 * std::max(std::abs(q.min_gaussian), std::abs(q.max_gaussian));
  AreaByClass areas;
  for (InterrogatedSurface& s : q.surfaces) {
    const std::size_t nv = s.v.size();
    for (std::size_t i = 0; i + 1 < s.u.size(); ++i)
      for (std::size_t j = 0; j + 1 < nv; ++j)
        classify_area(s.surface, s.u[i], s.u[i + 1], s.v[j], s.v[j + 1], parabolic, 6, areas);
  }
  q.area = areas.elliptic + areas.hyperbolic + areas.parabolic;
  const double elliptic = areas.elliptic, hyperbolic = areas.hyperbolic;
  if (q.area > 0) {
    q.elliptic_area_fraction = elliptic / q.area;
    q.hyperbolic_area_fraction = hyperbolic / q.area;
    q.parabolic_area_fraction = 1 - q.elliptic_area_fraction - q.hyperbolic_area_fraction;
  }
  q.lights = choose_lights(q.surfaces);
  for (InterrogatedSurface& s : q.surfaces)
    for (std::size_t k = 0; k < s.points.size(); ++k)
      s.reflection.push_back(reflection_line_value(s.points[k], s.normals[k], q.lights));
  return q;
}

std::map<std::string, std::string> interrogation_x3d(const SurfaceInterrogation& q,
                                                     const std::string& title) {
  X3dWriter curvature, reflection;
  const bool diverging = q.shown != CurvatureQuantity::absolute;
  const auto [lo, hi] = shown_range(q);
  const double limit = std::max({std::abs(lo), std::abs(hi), 1e-300});
  for (std::size_t k = 0; k < q.surfaces.size(); ++k) {
    const InterrogatedSurface& s = q.surfaces[k];
    const std::size_t nv = s.v.size();
    std::vector<std::array<int, 4>> quads;
    for (std::size_t i = 0; i + 1 < s.u.size(); ++i)
      for (std::size_t j = 0; j + 1 < nv; ++j)
        quads.push_back({static_cast<int>(i * nv + j), static_cast<int>((i + 1) * nv + j),
                         static_cast<int>((i + 1) * nv + j + 1), static_cast<int>(i * nv + j + 1)});
    std::vector<Eigen::Vector3d> colors, stripes;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const double x = values_of(s, q.shown)[i];
      colors.push_back(!std::isfinite(x) ? Eigen::Vector3d(0.5, 0.5, 0.5)
                       : diverging       ? diverging_color(x, limit)
                                         : sequential_color(x, lo, hi));
      const double r = s.reflection[i];
      // Black stripes where the value is within 0.15 of an integer, white elsewhere.
      const double f = std::isfinite(r) ? std::abs(r - std::round(r)) : 1.0;
      stripes.push_back(std::isfinite(r) ? (f < 0.15 ? Eigen::Vector3d(0.05, 0.05, 0.05)
                                                     : Eigen::Vector3d(0.97, 0.97, 0.97))
                                         : Eigen::Vector3d(0.6, 0.6, 0.65));
    }
    const std::string id = std::to_string(k + 1);
    curvature.add_colored_quads(s.points, colors, quads, "curvature_" + id);
    curvature.add(s.surface, "surface_" + id);
    curvature.add_switch("views_" + id, {"curvature_" + id, "surface_" + id});
    reflection.add_colored_quads(s.points, stripes, quads, "reflection_" + id);
  }
  return {
      {"curvature.x3d", curvature.str(curvature_quantity_name(q.shown) + " curvature of " + title)},
      {"reflection.x3d", reflection.str("reflection lines of " + title)}};
}

InterrogationCloud interrogation_cloud(const SurfaceInterrogation& q) {
  InterrogationCloud c;
  std::size_t n = 0;
  for (const InterrogatedSurface& s : q.surfaces) n += s.points.size();
  c.points.resize(3, static_cast<Eigen::Index>(n));
  const auto [lo, hi] = shown_range(q);
  const double limit = std::max({std::abs(lo), std::abs(hi), 1e-300});
  Eigen::Index k = 0;
  for (const InterrogatedSurface& s : q.surfaces)
    for (std::size_t i = 0; i < s.points.size(); ++i, ++k) {
      c.points.col(k) = s.points[i];
      const double x = values_of(s, q.shown)[i];
      const double shown = std::isfinite(x) ? x : 0.0;  // PLY values must be finite
      c.values.push_back(shown);
      c.colors.push_back(to_rgb8(q.shown == CurvatureQuantity::absolute
                                     ? sequential_color(shown, lo, hi)
                                     : diverging_color(shown, limit)));
    }
  return c;
}

void add_interrogation_ply(OutputTransaction& outputs, const std::filesystem::path& dir,
                           const SurfaceInterrogation& q) {
  const InterrogationCloud cloud = interrogation_cloud(q);
  outputs.add("curvature.ply", ply_writer(dir / "curvature.ply", cloud.points, &cloud.colors,
                                          &cloud.values, curvature_quantity_name(q.shown)));
}

void add_interrogation_files(OutputTransaction& outputs, const std::filesystem::path& dir,
                             const SurfaceInterrogation& q, const std::string& title) {
  for (const auto& [name, text] : interrogation_x3d(q, title)) outputs.add(name, text);
  add_interrogation_ply(outputs, dir, q);
}

std::vector<std::string> interrogation_file_names() {
  return {"curvature.ply", "curvature.x3d", "reflection.x3d"};
}

nlohmann::ordered_json surface_interrogation_json(const SurfaceInterrogation& q) {
  return {{"shown", curvature_quantity_name(q.shown)},
          {"min_gaussian_per_mm2", q.min_gaussian},
          {"max_gaussian_per_mm2", q.max_gaussian},
          {"min_mean_per_mm", q.min_mean},
          {"max_mean_per_mm", q.max_mean},
          {"min_absolute_per_mm", q.min_absolute},
          {"max_absolute_per_mm", q.max_absolute},
          {"elliptic_area_fraction", q.elliptic_area_fraction},
          {"hyperbolic_area_fraction", q.hyperbolic_area_fraction},
          {"parabolic_area_fraction", q.parabolic_area_fraction},
          {"area_mm2", q.area},
          {"tessellation", "64 steps per direction plus every knot"}};
}

}  // namespace polarform
