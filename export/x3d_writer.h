// X3D 3.3 writer (ISO/IEC 19775-1, XML encoding) for viewing kernel NURBS in any X3D browser:
// curves as NurbsCurve (2D curves in the plane z = 0), surfaces as NurbsPatchSurface, meshes and
// points coloured per vertex (IndexedFaceSet, PointSet), each in a Shape in the order added;
// shapes may be grouped as alternatives in a Switch. A Viewpoint frames everything; the NURBS
// component and the millimetre length UNIT are declared. Written with tinyxml2.
#pragma once

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

class X3dWriter {
 public:
  // Names become DEF ids (characters outside [A-Za-z0-9_.-] replaced by '_', made unique).
  // Colours are RGB in [0, 1]. Throw InputError for degree 0, an interior knot above C0 or a
  // colour outside [0, 1].
  void add(const NurbsCurve2d& curve, const std::string& name = "",
           const Eigen::Vector3d& color = Eigen::Vector3d(0.1, 0.2, 0.8));
  void add(const NurbsCurve3d& curve, const std::string& name = "",
           const Eigen::Vector3d& color = Eigen::Vector3d(0.1, 0.2, 0.8));
  void add(const NurbsSurface& surface, const std::string& name = "",
           const Eigen::Vector3d& color = Eigen::Vector3d(0.7, 0.7, 0.75));
  // Quadrilaterals over `points` (four indices each) with one colour per point. Throws
  // InputError for an index out of range, a colour count that differs from the point count or a
  // colour outside [0, 1].
  void add_colored_quads(const std::vector<Eigen::Vector3d>& points,
                         const std::vector<Eigen::Vector3d>& colors,
                         const std::vector<std::array<int, 4>>& quads, const std::string& name);
  // Points with one colour each.
  void add_colored_points(const std::vector<Eigen::Vector3d>& points,
                          const std::vector<Eigen::Vector3d>& colors, const std::string& name);
  // The shapes added under these names become the children of a Switch named `name`, the first
  // shown and the others alternatives a browser can select. Throws InputError for a name that
  // was not added or is already in a Switch.
  void add_switch(const std::string& name, const std::vector<std::string>& shapes);

  std::string str(const std::string& title = "polarform") const;
  void save(const std::filesystem::path& path, const std::string& title = "polarform") const;

 private:
  struct ColoredQuads {
    std::vector<Eigen::Vector3d> points, colors;
    std::vector<std::array<int, 4>> quads;
  };
  struct ColoredPoints {
    std::vector<Eigen::Vector3d> points, colors;
  };
  struct Shape {
    std::variant<NurbsCurve3d, NurbsSurface, ColoredQuads, ColoredPoints> geometry;
    std::string name;
    Eigen::Vector3d color;  // NURBS shapes
    int group = -1;         // index into switches_, or -1
  };
  struct Switch {
    std::string name;
    std::vector<int> shapes;
  };
  std::vector<Shape> shapes_;
  std::vector<Switch> switches_;
};

}  // namespace polarform
