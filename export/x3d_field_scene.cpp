#include "export/x3d_field_scene.h"

#include <array>
#include <vector>

#include "export/colormap.h"
#include "export/x3d_writer.h"
#include "src/error.h"
#include "src/nurbs/tessellation.h"

namespace polarform {

std::string field_x3d(const ScalarFieldSurface& f, const std::string& title, int rows, int cols) {
  if (rows < 1 || cols < 1)
    throw InputError("field X3D: the tessellation needs at least 1 x 1 quads");
  const double lo = f.min_value, hi = f.max_value;
  const NurbsSurface& S = f.surface;
  // The surface tessellated, each vertex coloured by the value F there (Bae 2002, §5.3).
  const SurfaceTessellation grid = tessellate(S, rows, cols);
  const int nu = static_cast<int>(grid.u.size()), nv = static_cast<int>(grid.v.size());
  std::vector<Eigen::Vector3d> points, colors;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      double value = 0.0;
      f.F.point(grid.u[i], grid.v[j], &value);
      points.push_back(grid.points[i * nv + j]);
      colors.push_back(sequential_color(value, lo, hi));
    }
  std::vector<std::array<int, 4>> quads;
  for (int i = 0; i + 1 < nu; ++i)
    for (int j = 0; j + 1 < nv; ++j) {
      const int a = i * nv + j, b = a + nv;
      quads.push_back({a, b, b + 1, a + 1});
    }
  // The control net as points coloured by the value each control point carries.
  std::vector<Eigen::Vector3d> net, net_colors;
  for (int i = 0; i < S.size_u(); ++i)
    for (int j = 0; j < S.size_v(); ++j) {
      net.push_back(S.control_point(i, j));
      net_colors.push_back(sequential_color(f.control_values[i * S.size_v() + j], lo, hi));
    }
  X3dWriter writer;
  writer.add_colored_quads(points, colors, quads, "field_colored");
  writer.add(S, "field_nurbs");
  writer.add_switch("views", {"field_colored", "field_nurbs"});
  writer.add_colored_points(net, net_colors, "control_values");
  return writer.str(title);
}

}  // namespace polarform
