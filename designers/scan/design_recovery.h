// The design of a scanned plate cam recovered from its motion: the motion segmented
// (motion_segmentation.h), each rise and return's law identified with least-squares boundaries
// and lift (law_identification.h), and the pieces joined into a cam program — a dwell's level
// is the mean of its two neighbours' fitted levels, a boundary two motions share (no dwell
// between them, or fitted ends that overlap) the mean of their two estimates — with the base
// radius from the lowest level and the scan's follower (scanned_cam.h). CamProgram starts a
// segment at θ = 0, so the design's frame is the scan's with θ = 0 kept when it falls inside a
// dwell (the dwell is split there) and otherwise moved to the start of the segment holding it:
// the design's cam angle is θ − phase. The re-designed cam is then compared with the scan as a
// nominal would be (nominal_comparison.h): that deviation is what the recovery achieved.
#pragma once

#include <vector>

#include "designers/cam/cam_design.h"
#include "designers/scan/law_identification.h"
#include "designers/scan/motion_segmentation.h"
#include "designers/scan/nominal_comparison.h"

namespace polarform {

struct RecoveredDesign {
  MotionSegmentation segmentation;
  std::vector<IdentifiedMotion> motions;  // one per segmentation.motions
  double phase = 0.0;                     // rad in [0, 2π): design angle = scan angle − phase
  CamDesign design;                       // a plate cam in the design's frame
  NominalComparison deviation;            // the scan against the re-designed cam
};

// Throws InputError when the motion cannot be segmented or a motion's window holds too few
// samples, or when the recovered design is not a valid cam (make_plate_cam).
RecoveredDesign recover_design(const ScannedCam& scan);

}  // namespace polarform
