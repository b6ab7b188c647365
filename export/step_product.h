// The STEP (AP214, AUTOMOTIVE_DESIGN) frame around a shape representation: the geometric
// representation context with its units (millimetre, radian, steradian) and length uncertainty,
// and the product structure (PRODUCT ... SHAPE_DEFINITION_REPRESENTATION) that makes importers
// transfer the representation as a part.
#pragma once

#include <string>

#include "export/step_file.h"

namespace polarform {

// GEOMETRIC_REPRESENTATION_CONTEXT(3) with GLOBAL_UNIT_ASSIGNED_CONTEXT (mm, rad, sr) and
// GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT (uncertainty_mm); returns its id.
int step_context(StepFile& f, double uncertainty_mm);

// AXIS2_PLACEMENT_3D at the origin (the usual first item of a shape representation).
int step_origin_placement(StepFile& f);

// Product `name` whose shape is the representation `representation`.
void step_product(StepFile& f, const std::string& name, int representation);

}  // namespace polarform
