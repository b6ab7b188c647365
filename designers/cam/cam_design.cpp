#include "designers/cam/cam_design.h"

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
  return PlateCam(make_program(design), design.follower, design.base_radius, design.rotation);
}

BarrelCam make_barrel_cam(const CamDesign& design) {
  if (design.type != CamType::Cylindrical) throw InputError("cam: not a cylindrical cam");
  if (design.follower.kind != FollowerKind::Roller)
    throw InputError("cylindrical cam: the follower must be a roller");
  return BarrelCam(make_program(design), design.cylinder_radius, design.z0,
                   design.follower.roller_radius, design.rotation);
}

}  // namespace polarform
