// The cam project file: a CamDesign with its conversion settings as XML, in the file's units
// (angles in degrees, lengths in mm, endpoint derivatives per radian of cam angle). Reading names
// file:line:attribute for every bad value and warns about unknown fields; writing is atomic, and a
// saved project loads back exactly (angles are written as the degree value that converts back to
// the same radians).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "designers/cam/cam_design.h"
#include "designers/cam/follower_dynamics.h"
#include "designers/convert/polar_conversion.h"
#include "jobs/project/unknown_names.h"

namespace polarform {

struct CamProject {
  CamDesign cam;
  ConversionOptions conversion;
  // Highest spline degree the exported profile files may have; empty = the exact degree.
  std::optional<int> max_degree;
  // The largest acceptable |pressure angle|, rad; empty = the follower's default
  // (default_pressure_angle_limit in jobs/cam/cam_job.h).
  std::optional<double> pressure_angle_limit;
  // The follower's mass, spring and contact (<dynamics>): the contact force, jump speed, camshaft
  // torque and contact stress of a plate cam (designers/cam/follower_dynamics.h).
  std::optional<FollowerLoad> load;

  bool operator==(const CamProject&) const = default;
};

// Reads
//   <polarform version="1" units="mm|inch">   (units: of every length; also on <cam>)
//     <cam type="plate|cylindrical" follower="knife-edge|roller|flat-faced" base-radius="mm"
//          roller-radius="mm" offset="mm" rotation="ccw|cw" rpm="1/min" cylinder-radius="mm"
//          z0="mm" groove-depth="mm, walls at cylinder-radius ± depth/2 (cylindrical); a face
//          groove's depth (plate, roller followers)" pressure-angle-limit="deg, in (0, 90)">
//       <segment kind="dwell|rise|return" law="…" lift="mm" from="deg" to="deg" name="…"
//                degree="5" control-values="10" minimise="1|2|3">   (degree…: law="bspline")
//         <start v="mm/rad" a="mm/rad²" j="mm/rad³"/>  <end …/>   (law="polynomial|bspline")
//       </segment>…
//       <conjugate roller-distance="mm"/>  or  <conjugate arm-angle="deg" arm-length="mm"/>
//     </cam>
//     <conversion tolerance="mm, >= kMinTolerance" base="quasi-uniform|rqb"
//                 alpha="minimax|printed" max-degree=""/>
//   </polarform>
// `from` defaults to the previous segment's `to` (0 for the first); a return's `lift` defaults to
// the level reached so far. A file in inches is converted to mm as it is read (and saved in mm).
// Throws InputError "file:line: <element> attribute 'x': expected …",
// and for unknown attributes or elements, which UnknownNames::warn turns into warnings.
CamProject read_cam_project(const std::filesystem::path& file, std::vector<std::string>& warnings,
                            UnknownNames policy = UnknownNames::refuse);
CamProject parse_cam_project(const std::string& text, const std::string& file,
                             std::vector<std::string>& warnings,
                             UnknownNames policy = UnknownNames::refuse);

// The project as XML (numbers in their shortest exact form) and saved atomically.
std::string cam_project_xml(const CamProject& project);
void write_cam_project(const CamProject& project, const std::filesystem::path& file);

}  // namespace polarform
