// Random plate-cam designs for the statistics of design recovery from scans: dwell–rise–dwell–
// return programs (two or four motions) with laws drawn from the six standard laws, boundaries at
// random (motions 50°–110°, dwells at least 12°), lifts 6–20 mm, a random follower (knife-edge,
// roller or flat-faced, offset or radial) and rotation; designs whose contour is undercut, not
// single-valued about the centre, or steeper than a 40° pressure angle are drawn again.
// Deterministic for a generator state.
#pragma once

#include <random>

#include "designers/cam/cam_design.h"

namespace polarform::test {

CamDesign random_cam_design(std::mt19937& rng);

}  // namespace polarform::test
