// The vessel project file: a VesselDesign and its conversion tolerance as XML, in the file's units
// (angles in degrees, lengths in mm, pressure in MPa, curvature as κ in 1/mm or as a radius of
// curvature in mm). Reading names file:line:attribute for every bad value and warns about unknown
// fields; writing is atomic, and a saved project loads back exactly.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "designers/convert/polar_conversion.h"
#include "designers/vessel/vessel_design.h"
#include "jobs/project/unknown_names.h"

namespace polarform {

// One <curvature> element as written: theta in degrees and either kappa (1/mm) or radius (mm).
struct CurvatureEntry {
  double theta_deg = 0.0;
  double value = 0.0;
  bool is_radius = false;  // value is a radius of curvature (κ = 1/value)
  double weight = 1.0;
  // Where: theta="deg" (polar angle), s="mm" (arc length from junction A) or phi="deg" (meridian
  // angle of the normal against the axis); position holds s or φ.
  TargetPlace place = TargetPlace::polar_angle;
  double position = 0.0;

  bool operator==(const CurvatureEntry&) const = default;
};

struct VesselProject {
  // The design; its `targets` are derived from `curvatures` by to_design() and not stored here.
  VesselDesign design;
  std::vector<CurvatureEntry> curvatures;
  double tolerance = 1e-3;  // conversion tolerance, mm
  Compaction compaction = Compaction::refit;  // how the converted meridian is made compact

  bool operator==(const VesselProject&) const = default;
};

// The design with the curvature entries converted to radians and 1/mm.
VesselDesign to_design(const VesselProject& project);

// Reads <polarform version="1"><vessel …>…</vessel><conversion tolerance="…"/></polarform>, or a
// bare <vessel> root; units="mm|inch" on either states the unit of every length (converted to mm
// as it is read, κ to 1/mm; the pressure stays in MPa):
//   <vessel radius="mm" (or diameter="mm") length="mm" thickness="mm" pressure="MPa"
//           density="kg/m³">   (radius: inside; density 7850 by default)
//     <code allowable-stress="MPa" joint-efficiency="1" corrosion-allowance="mm"/>
//     <curvature theta="deg" kappa="1/mm" | radius="mm" weight="1"/>…
//     <end at="A|B" r="mm" dr="mm/rad" ddr="mm/rad²"/>   (present attributes are imposed)
//     <head preset="hemispherical|ellipsoidal|torispherical" ratio="2" crown="mm" knuckle="mm"
//           design="exact|curvature|minimum-stress" targets="48" depth="mm"/>   (design: exact
//           unless the vessel has <curvature>, <end> or <synthesis> elements or the head a
//           targets attribute; depth: of a minimum-stress head, or imposed on a curvature head as
//           R(π/2) = depth, its preset then optional)
//     <synthesis degree="5" ordinates="20" smoothing="1e-6" symmetric="false"
//                max-iterations="500"/>
//   </vessel>
// Throws InputError "file:line: <element> attribute 'x': expected …" for bad values, and for
// unknown attributes or elements, which UnknownNames::warn turns into warnings.
VesselProject read_vessel_project(const std::filesystem::path& file,
                                  std::vector<std::string>& warnings,
                                  UnknownNames policy = UnknownNames::refuse);
VesselProject parse_vessel_project(const std::string& text, const std::string& file,
                                   std::vector<std::string>& warnings,
                                   UnknownNames policy = UnknownNames::refuse);

// The project as XML (numbers in their shortest exact form) and saved atomically.
std::string vessel_project_xml(const VesselProject& project);
void write_vessel_project(const VesselProject& project, const std::filesystem::path& file);

}  // namespace polarform
