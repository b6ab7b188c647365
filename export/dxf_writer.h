// DXF R2000 (AC1015) writer: NURBS curves as SPLINE entities with knots, weights and truthful
// closed / periodic / rational / planar / linear flags, plus LINE, CIRCLE and LWPOLYLINE for
// auxiliary geometry (a base circle, a pitch curve), in a minimal complete drawing (HEADER with
// $INSUNITS = mm, CLASSES, TABLES, BLOCKS, ENTITIES, OBJECTS; handles and owners) that AutoCAD
// and ezdxf's auditor accept.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "src/nurbs/nurbs_curve.h"

namespace polarform {

struct DxfOptions {
  // AutoCAD draws SPLINE entities up to degree 10 (DESIGN.md §4.6); a higher degree throws unless
  // this is raised (for consumers known to accept it).
  int max_spline_degree = 10;
  // mm: the tolerance of the closed, planar and linear flags.
  double resolution = 1e-6;
};

class DxfWriter {
 public:
  explicit DxfWriter(DxfOptions options = {});

  // Layer names: printable ASCII without < > / \ " : ; ? * | = `. A curve throws InputError for
  // degree 0, an interior knot above C0, or a degree above options.max_spline_degree.
  void add(const NurbsCurve2d& curve, const std::string& layer = "0");  // in the plane z = 0
  void add(const NurbsCurve3d& curve, const std::string& layer = "0");
  void add_line(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const std::string& layer = "0");
  // Circle in the plane z = center.z (radius > 0).
  void add_circle(const Eigen::Vector3d& center, double radius, const std::string& layer = "0");
  // LWPOLYLINE in the plane z = 0 (at least two points).
  void add_polyline(const std::vector<Eigen::Vector2d>& points, bool closed,
                    const std::string& layer = "0");

  std::string str() const;
  void save(const std::filesystem::path& path) const;

 private:
  struct Entity {
    std::string layer;
    std::string kind;                                // SPLINE, LINE, CIRCLE, LWPOLYLINE
    std::vector<std::pair<int, std::string>> tags;   // group codes after the layer
    std::vector<Eigen::Vector3d> extent;             // points bounding the entity
  };
  void check_layer(const std::string& layer) const;

  DxfOptions options_;
  std::vector<Entity> entities_;
};

}  // namespace polarform
