// STEP (ISO 10303-21, AP214 AUTOMOTIVE_DESIGN) writer for kernel NURBS as one part: curves as
// B_SPLINE_CURVE_WITH_KNOTS (rational ones as complex instances) in a GEOMETRIC_CURVE_SET of a
// GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION; surfaces as ADVANCED_FACEs sewn along
// shared boundaries into shells (one per connected set of faces: CLOSED_SHELL when every edge
// bounds two faces, else OPEN_SHELL) of a SHELL_BASED_SURFACE_MODEL in a
// MANIFOLD_SURFACE_SHAPE_REPRESENTATION.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "export/step_file.h"
#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

class StepWriter {
 public:
  explicit StepWriter(std::string product_name = "part") : product_(std::move(product_name)) {}

  // Throw InputError (naming the item) for degree 0 or an interior knot above C0.
  void add(const NurbsCurve2d& curve, const std::string& name = "");  // in the plane z = 0
  void add(const NurbsCurve3d& curve, const std::string& name = "");
  // Each surface becomes one face bounded by its four boundary iso-curves (a boundary that
  // collapses to a point, a pole, is left out). Faces share an edge where their boundary curves
  // have the same representation (degree, knots, points and weights, in either direction) and a
  // vertex where their corners coincide within the header resolution. Face normals are the
  // surfaces' own (S_u x S_v).
  void add(const NurbsSurface& surface, const std::string& name = "");

  std::string str(const StepHeader& header = {}) const;
  void save(const std::filesystem::path& path, const StepHeader& header = {}) const;

 private:
  std::string product_;
  std::vector<std::pair<NurbsCurve3d, std::string>> curves_;
  std::vector<std::pair<NurbsSurface, std::string>> surfaces_;
};

}  // namespace polarform
