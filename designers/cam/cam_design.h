// CamDesign: everything a cam project describes — cam type, follower, radii, rotation, speed and
// the motion segments — as one plain value, and the evaluable objects built from it. Project
// files, the CLI and the studio all edit this one struct. Lengths in mm, angles in radians.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "designers/cam/barrel_cam.h"
#include "designers/cam/conjugate_cam.h"
#include "designers/cam/plate_cam.h"

namespace polarform {

enum class CamType { Plate, Cylindrical };

std::string_view cam_type_name(CamType type);  // "plate", "cylindrical"
// "knife-edge", "roller", "flat-faced", "oscillating-roller", "oscillating-flat-faced"
std::string_view follower_kind_name(FollowerKind kind);
// The unit of the follower motion s: "mm" for translating followers, "deg" (the arm's swing) for
// oscillating ones; motion_unit_symbol gives "mm" or "°" for text.
std::string_view motion_unit(FollowerKind kind);
std::string_view motion_unit_symbol(FollowerKind kind);
std::string_view rotation_name(Rotation rotation);  // "ccw", "cw"

struct CamDesign {
  CamType type = CamType::Plate;
  Follower follower;
  double base_radius = 40.0;  // Rb: smallest circle tangent to the contour (plate cams)
  Rotation rotation = Rotation::CounterClockwise;
  double rpm = 300.0;
  double cylinder_radius = 0.0;  // Rc: pitch cylinder of the track centre (cylindrical cams)
  double z0 = 0.0;               // track height at s = 0 (cylindrical cams)
  // Cylindrical cams: radial depth of the groove walls, centred on the pitch cylinder: they span
  // Rc ± depth/2. Plate cams: axial depth of a face groove in which the roller rides
  // (plate_groove.h). 0 = no groove.
  double groove_depth = 0.0;
  // Plate cams: a second cam driving a second roller on the same follower (conjugate_cam.h).
  std::optional<ConjugateFollower> conjugate;
  std::vector<SegmentSpec> segments;

  bool operator==(const CamDesign&) const = default;
};

// The validated program and cams; InputError names what is wrong.
CamProgram make_program(const CamDesign& design);
PlateCam make_plate_cam(const CamDesign& design);
BarrelCam make_barrel_cam(const CamDesign& design);

}  // namespace polarform
