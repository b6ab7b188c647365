// The vessel's settings: cylinder radius, length, wall thickness and pressure; the head preset
// (hemispherical, ellipsoidal, torispherical, with the 100 %/6 % and 80 %/10 % shortcuts) and how
// many of its curvatures to sample; the endpoint conditions (5.5) at both junctions; the synthesis
// space; and the conversion tolerance. Edits the project in place.
#pragma once

#include "jobs/project/vessel_project.h"

namespace polarform::studio {

class VesselDesignPanel {
 public:
  bool draw(VesselProject& project);

 private:
  bool draw_preset(VesselDesign& design);
  bool draw_design(VesselDesign& design);  // curvature, exact or minimum-stress, with its inputs
  bool draw_end(const char* title, std::optional<EndCondition>& end, double radius);
  bool draw_synthesis(SynthesisSettings& settings);
};

}  // namespace polarform::studio
