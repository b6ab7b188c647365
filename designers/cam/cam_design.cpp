#include "designers/cam/cam_design.h"

#include <cmath>

#include "designers/cam/plate_groove.h"
#include "src/error.h"

namespace polarform {

std::string_view cam_type_name(CamType type) {
  return type == CamType::Plate ? "plate" : "cylindrical";
}

std::string_view follower_kind_name(FollowerKind kind) {
  switch (kind) {
    case FollowerKind::KnifeEdge: return "knife-edge";
    case FollowerKind::Roller: return "roller";
    case FollowerKind::FlatFaced: return "flat-faced";
    case FollowerKind::OscillatingRoller:
      return "oscillating-roller";
    case FollowerKind::OscillatingFlatFaced:
      return "oscillating-flat-faced";
  }
  return "unknown";
}

std::string_view motion_unit(FollowerKind kind) { return is_oscillating(kind) ? "deg" : "mm"; }

std::string_view motion_unit_symbol(FollowerKind kind) { return is_oscillating(kind) ? "°" : "mm"; }

std::string_view rotation_name(Rotation rotation) {
  return rotation == Rotation::CounterClockwise ? "ccw" : "cw";
}

CamProgram make_program(const CamDesign& design) { return CamProgram(design.segments); }

PlateCam make_plate_cam(const CamDesign& design) {
  if (design.type != CamType::Plate) throw InputError("cam: not a plate cam");
  PlateCam cam(make_program(design), design.follower, design.base_radius, design.rotation);
  if (!std::isfinite(design.groove_depth) || design.groove_depth < 0)
    throw InputError("groove-depth must be a number of mm >= 0");
  if (design.groove_depth > 0 && design.conjugate)
    throw InputError(
        "groove-depth: a grooved cam is already driven both ways; it takes no "
        "<conjugate> second cam");
  if (design.groove_depth > 0) groove_outer_flank(cam);  // a roller follower
  if (design.conjugate) conjugate_roller(cam, *design.conjugate);
  return cam;
}

BarrelCam make_barrel_cam(const CamDesign& design) {
  if (design.type != CamType::Cylindrical) throw InputError("cam: not a cylindrical cam");
  if (design.follower.kind != FollowerKind::Roller)
    throw InputError("cylindrical cam: the follower must be a roller");
  return BarrelCam(make_program(design), design.cylinder_radius, design.z0,
                   design.follower.roller_radius, design.rotation);
}

}  // namespace polarform
