// Cam and follower settings: cam type (plate or cylindrical), follower kind, offset, roller
// radius, base radius (with "smallest for the pressure-angle limit", computed by the library's
// minimum_base_radius), sense of rotation, speed, and the cylindrical cam's pitch radius and z0.
// Edits the CamDesign in place and reports whether it changed.
#pragma once

#include "designers/cam/cam_design.h"
#include "ui/studio/message_log.h"

namespace polarform::studio {

struct CamViewSettings;

class CamSettingsPanel {
 public:
  bool draw(CamDesign& design, CamViewSettings& view, MessageLog& log);

 private:
  bool draw_base_radius_search(CamDesign& design, const CamViewSettings& view, MessageLog& log);
};

}  // namespace polarform::studio
