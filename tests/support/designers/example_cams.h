// The bundled example cams (examples/cams/*.xml) built in code with designers/cam alone, for the
// tests of designers/, which may not read project files. The cam-project tests check that every
// example file reads to exactly the design built here (segment starts to rounding).
#pragma once

#include <string>
#include <vector>

#include "designers/cam/cam_design.h"

namespace polarform::test {

// "roller", "flat_faced", "offset_roller", "polynomial", "cylindrical": the file names without
// ".xml".
const std::vector<std::string>& example_cam_names();

// The design examples/cams/<name>.xml describes; std::invalid_argument for any other name.
CamDesign example_cam_design(const std::string& name);

}  // namespace polarform::test
