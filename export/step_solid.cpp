#include "export/step_solid.h"

#include <cmath>

#include "export/atomic_file.h"
#include "export/step_geometry.h"
#include "export/step_prism.h"
#include "export/step_product.h"
#include "export/step_topology.h"
#include "src/error.h"

namespace polarform {

std::string step_extruded_solid(const NurbsCurve2d& closed_profile, double thickness,
                                std::optional<double> bore_diameter, const std::string& name,
                                const StepHeader& header,
                                const std::optional<Eigen::Isometry3d>& placement) {
  const double tol = header.resolution;
  if (!(thickness > 0.0) || !std::isfinite(thickness))
    throw InputError("STEP solid thickness " + std::to_string(thickness) +
                     " mm: expected a finite value > 0");
  const NurbsCurve2d profile = counter_clockwise_profile(closed_profile, tol, "STEP solid profile");

  const double r = bore_diameter.value_or(0.0) / 2.0;
  if (bore_diameter) {
    if (!(r > 0.0) || !std::isfinite(r))
      throw InputError("STEP solid bore_diameter " + std::to_string(*bore_diameter) +
                       " mm: expected a finite value > 0");
    const auto [winding, clearance] = winding_and_clearance(profile);
    if (winding != 1)
      throw InputError("STEP solid bore: the profile does not enclose the bore axis (the origin)");
    if (r >= clearance - tol)
      throw InputError("STEP solid bore_diameter " + std::to_string(*bore_diameter) +
                       " mm: the bore must lie inside the profile, whose closest point is " +
                       std::to_string(clearance) + " mm from the axis");
  }

  StepFile f;
  StepTopology topo(f, tol);
  const int context = step_context(f, tol);
  f.placement = placement;  // the faces' geometry only, not the representation's origin
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ(), x = Eigen::Vector3d::UnitX();

  // The side face and, with a bore, the bore face (its normal towards the axis).
  const StepWall side = step_profile_wall(f, topo, profile, 0.0, thickness, true, tol);
  std::vector<std::string> faces = {step_ref(side.face)};
  // Bottom face (normal -z) and top face (normal +z); the profile is their outer bound.
  std::vector<StepTopology::Bound> bottom_bounds = {{topo.loop({{side.low, false}}), true}};
  std::vector<StepTopology::Bound> top_bounds = {{topo.loop({{side.high, true}}), true}};
  if (bore_diameter) {
    const StepWall bore = step_circle_wall(f, topo, r, 0.0, thickness, false);
    faces.push_back(step_ref(bore.face));
    bottom_bounds.push_back({topo.loop({{bore.low, true}}), false});
    top_bounds.push_back({topo.loop({{bore.high, false}}), false});
  }
  const int bottom_plane = step_plane(f, step_axis2(f, Eigen::Vector3d::Zero(), z, x));
  const int top_plane = step_plane(f, step_axis2(f, thickness * z, z, x));
  faces.push_back(step_ref(topo.face(bottom_bounds, bottom_plane, false)));
  faces.push_back(step_ref(topo.face(top_bounds, top_plane, true)));
  f.placement.reset();
  return step_solid_file(f, context, faces, name, header);
}

void write_step_extruded_solid(const std::filesystem::path& path, const NurbsCurve2d& closed_profile,
                               double thickness, std::optional<double> bore_diameter,
                               const std::string& name, const StepHeader& header) {
  StepHeader h = header;
  if (h.file_name.empty()) h.file_name = path.filename().string();
  write_file_atomically(path, step_extruded_solid(closed_profile, thickness, bore_diameter, name, h));
}

}  // namespace polarform
