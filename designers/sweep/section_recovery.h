// Free-form sweep recovery by sections and skinning (Kantz 2003, §5.4; spec K12) along a straight
// or curved spine (discrete generalized cylinders, MIT 13.472J §8.6; spec M9): the cloud is sliced
// perpendicular to the spine at stations (section_spine.h gives every point its spine coordinates
// (s, x, y)); each section is fitted as a closed star-shaped curve on one base circle and one knot
// vector (section_curves.h); a curved spine is re-fitted through the section centroids and the
// cloud re-sliced until it moves less than a quarter of the tolerance; the sections are skinned
// (NURBS Book §10.3); stations are inserted where the skin misses the points between them (adaptive
// slicing).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "designers/sweep/recovery_steps.h"
#include "designers/sweep/section_curves.h"
#include "designers/sweep/section_spine.h"
#include "src/fit/principal_frame.h"

namespace polarform {

enum class SpineShape {
  automatic,  // the PCA axis, bent through the section centroids when they leave it by > tolerance
  straight,   // the PCA axis
  curved,     // through the section centroids even when they lie on a line
};

struct SectionOptions {
  // Max distance asked (<= 0: 1e-4 of the size), half for the sections' fits and half for what
  // the skin adds between them; on noisy data the sections' fits leave the noise.
  double tolerance = 0.0;
  int degree = 3;  // of F, the section's radius function
  SpineShape spine = SpineShape::automatic;
  int initial_sections = 5;
  int max_sections = 200;
  int points_per_section = 400;  // the slab around a station holds about this many points
  int max_spine_iterations = 20;
  int threads = 2;
};

struct SectionStation {
  double s = 0.0;                                    // arc length along the spine
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // the section's centroid in space
  std::size_t points = 0;                            // in its slab
  SectionCurve curve;                                // in the station frame's (x, y)
  NurbsCurve3d placed;  // the same curve in space: the skin's row v = s
};

// SweptFit's profile holds the sections in their station frames' (x, y) (one closed loop each),
// its plane every point's (x, y) in its own spine frame, its one surface the skin: u the base
// circle's angle parameter, v the arc length s along the spine.
struct SectionRecovery : SweptFit {
  PrincipalFrame pca;
  std::optional<SectionSpine> spine;
  bool spine_curved = false;
  double spine_length = 0.0;  // from the first station to the last along the spine
  int spine_iterations = 0;   // re-slicings after a spine change
  int rounds = 0;             // skins built (adaptive slicing rounds)
  double slab = 0.0;          // half-width of a station's slab along s
  int spans = 0;              // F's spans, common to all sections
  std::vector<SectionStation> stations;
  Eigen::VectorXd s;  // every point's arc length along the spine
  struct Timings {
    double frame = 0, slicing = 0, sections = 0, skin = 0, error = 0;
  } timings_s;
};

// Needs at least 8 finite points (InputError otherwise); InputError naming the station when a
// section has too few points, is not closed or not star-shaped about its centre.
SectionRecovery recover_sections(const Eigen::Matrix3Xd& points,
                                 const SectionOptions& options = {});

}  // namespace polarform
