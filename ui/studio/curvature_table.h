// The vessel's curvature targets: one row per (θ, κ or radius of curvature, weight), in the
// project file's units (degrees, 1/mm or mm), with add, delete and sort-by-angle. Edits the
// entries in place and reports whether they changed.
#pragma once

#include <vector>

#include "jobs/project/vessel_project.h"

namespace polarform::studio {

class CurvatureTable {
 public:
  bool draw(std::vector<CurvatureEntry>& entries);

 private:
  bool draw_place(CurvatureEntry& e);
  int selected_ = -1;
};

}  // namespace polarform::studio
