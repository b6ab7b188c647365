#include "ui/studio/scene_geometry.h"

#include "src/nurbs/tessellation.h"
#include "ui/studio/colors.h"

namespace polarform::studio {
namespace {

void push3(std::vector<float>& v, const Eigen::Vector3d& p) {
  v.push_back(static_cast<float>(p.x()));
  v.push_back(static_cast<float>(p.y()));
  v.push_back(static_cast<float>(p.z()));
}

void push_rgb(std::vector<float>& v, const float* rgb) { v.insert(v.end(), rgb, rgb + 3); }

}  // namespace

PointSet make_point_set(const Eigen::Matrix3Xd& points, const Eigen::Vector3d& origin,
                        const float* rgb) {
  PointSet set;
  set.positions.reserve(points.cols() * 3);
  set.colors.reserve(points.cols() * 3);
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    push3(set.positions, points.col(i) - origin);
    push_rgb(set.colors, rgb);
  }
  return set;
}

PointSet make_point_set(const Eigen::Matrix3Xd& points, const Eigen::Vector3d& origin,
                        const Eigen::VectorXd& values, double scale) {
  PointSet set;
  set.positions.reserve(points.cols() * 3);
  set.colors.reserve(points.cols() * 3);
  const double s = scale > 0 ? scale : 1.0;
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    push3(set.positions, points.col(i) - origin);
    float rgb[3];
    diverging_rgb(i < values.size() ? values[i] / s : 0.0, rgb);
    push_rgb(set.colors, rgb);
  }
  return set;
}

TriangleMesh make_surface_mesh(const NurbsSurface& surface, const Eigen::Vector3d& origin,
                               const float* rgb, int samples_u, int samples_v) {
  const SurfaceTessellation grid = tessellate(surface, samples_u, samples_v);
  const int nu = static_cast<int>(grid.u.size()), nv = static_cast<int>(grid.v.size());
  TriangleMesh mesh;
  for (int k = 0; k < nu * nv; ++k) {
    push3(mesh.positions, grid.points[k] - origin);
    push3(mesh.normals, grid.normals[k]);
    push_rgb(mesh.colors, rgb);
  }
  for (int i = 0; i + 1 < nu; ++i)
    for (int j = 0; j + 1 < nv; ++j) {
      const unsigned a = i * nv + j, b = (i + 1) * nv + j, c = (i + 1) * nv + j + 1,
                     d = i * nv + j + 1;
      mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
    }
  return mesh;
}

void append_mesh(TriangleMesh& to, const TriangleMesh& from) {
  const auto base = static_cast<unsigned>(to.positions.size() / 3);
  to.positions.insert(to.positions.end(), from.positions.begin(), from.positions.end());
  to.normals.insert(to.normals.end(), from.normals.begin(), from.normals.end());
  to.colors.insert(to.colors.end(), from.colors.begin(), from.colors.end());
  for (unsigned i : from.indices) to.indices.push_back(base + i);
}

void add_segment(LineSet& lines, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                 const Eigen::Vector3d& origin, const float* rgb) {
  push3(lines.positions, a - origin);
  push3(lines.positions, b - origin);
  push_rgb(lines.colors, rgb);
  push_rgb(lines.colors, rgb);
}

void add_polyline(LineSet& lines, const std::vector<Eigen::Vector3d>& points,
                  const Eigen::Vector3d& origin, const float* rgb) {
  for (std::size_t k = 1; k < points.size(); ++k)
    add_segment(lines, points[k - 1], points[k], origin, rgb);
}

void add_control_net(LineSet& lines, const NurbsSurface& surface, const Eigen::Vector3d& origin,
                     const float* rgb) {
  const int nu = surface.size_u(), nv = surface.size_v();
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const Eigen::Vector3d p = surface.control_point(i, j);
      if (i + 1 < nu) add_segment(lines, p, surface.control_point(i + 1, j), origin, rgb);
      if (j + 1 < nv) add_segment(lines, p, surface.control_point(i, j + 1), origin, rgb);
    }
}

SceneBounds bounds_of(const Eigen::Matrix3Xd& points) {
  SceneBounds b;
  if (points.cols() == 0) return b;
  b.min = points.rowwise().minCoeff();
  b.max = points.rowwise().maxCoeff();
  return b;
}

SceneBounds bounds_of(const NurbsSurface& surface) {
  SceneBounds b;
  for (int i = 0; i < surface.size_u(); ++i)
    for (int j = 0; j < surface.size_v(); ++j) b.add(surface.control_point(i, j));
  return b;
}

}  // namespace polarform::studio
