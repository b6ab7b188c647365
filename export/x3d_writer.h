// X3D 3.3 writer (ISO/IEC 19775-1, XML encoding) for viewing kernel NURBS in any X3D browser:
// curves as NurbsCurve (2D curves in the plane z = 0), surfaces as NurbsPatchSurface, each in a
// Shape with an Appearance, plus a Viewpoint that frames everything, the NURBS component and the
// millimetre length UNIT. Written with tinyxml2.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
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

  std::string str(const std::string& title = "polarform") const;
  void save(const std::filesystem::path& path, const std::string& title = "polarform") const;

 private:
  struct Curve {
    NurbsCurve3d curve;
    std::string name;
    Eigen::Vector3d color;
  };
  struct Surface {
    NurbsSurface surface;
    std::string name;
    Eigen::Vector3d color;
  };
  std::vector<Curve> curves_;
  std::vector<Surface> surfaces_;
};

}  // namespace polarform
