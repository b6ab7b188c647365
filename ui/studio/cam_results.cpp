#include "ui/studio/cam_results.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/units.h"

namespace polarform::studio {
namespace {

// Angles over [a, b] (ends included) at roughly `per_revolution` samples per 2π.
std::vector<double> segment_angles(double a, double b, int per_revolution) {
  const int n =
      std::max(8, static_cast<int>(std::ceil((b - a) / (2 * std::numbers::pi) * per_revolution)));
  std::vector<double> t(n + 1);
  for (int i = 0; i <= n; ++i) t[i] = a + (b - a) * i / n;
  t[n] = b;
  return t;
}

void sample_plate(CamResults& r, int samples) {
  const PlateCam& cam = *r.plate;
  const auto& segments = cam.program().segments();
  for (int k = 0; k < static_cast<int>(segments.size()); ++k)
    for (double t : segment_angles(segments[k].start(), segments[k].end(), samples)) {
      const CamSample c = cam.sample_in_segment(k, t);
      r.motion.theta_deg.push_back(t * kDegreesPerRadian);
      r.motion.s.push_back(c.s);
      r.motion.v.push_back(c.v);
      r.motion.a.push_back(c.a);
      r.motion.j.push_back(c.j);
      r.motion.pressure_deg.push_back(c.pressure_angle * kDegreesPerRadian);
      Eigen::Vector2d contour[2], pitch[1];
      cam.contour_in_segment(k, t, 1, contour);
      cam.pitch(t, 0, pitch);
      // A contour single-valued about the centre has its outward normal on the side of the radius.
      Eigen::Vector2d n(-contour[1].y(), contour[1].x());
      if (n.dot(contour[0]) < 0) n = -n;
      r.profile.theta.push_back(t);
      r.profile.contour.push_back(contour[0]);
      r.profile.pitch.push_back(pitch[0]);
      r.profile.normal.push_back(n.norm() > 0 ? n.normalized() : contour[0].normalized());
      r.profile.pressure.push_back(c.pressure_angle);
      r.profile.curvature.push_back(c.contour_curvature);
    }
}

void sample_barrel(CamResults& r, int samples) {
  const BarrelCam& cam = *r.barrel;
  const auto& segments = cam.program().segments();
  for (const MotionSegment& seg : segments)
    for (double t : segment_angles(seg.start(), seg.end(), samples)) {
      double d[4];
      seg.derivatives(t, 3, d);
      r.motion.theta_deg.push_back(t * kDegreesPerRadian);
      r.motion.s.push_back(d[0]);
      r.motion.v.push_back(d[1]);
      r.motion.a.push_back(d[2]);
      r.motion.j.push_back(d[3]);
      r.motion.pressure_deg.push_back(cam.pressure_angle(t, cam.pitch_radius()) *
                                      kDegreesPerRadian);
    }
}

}  // namespace

CamResults compute_cam_results(const CamDesign& design, int samples) {
  CamResults r;
  r.design = design;
  r.program.emplace(make_program(design));
  if (design.type == CamType::Plate) {
    r.plate.emplace(make_plate_cam(design));
    sample_plate(r, samples);
    CamAnalysis analysis = analyse(*r.plate, uniform_angles(samples));
    analysis.samples.clear();
    r.extrema = analysis.motion;
    r.analysis = std::move(analysis);
  } else {
    r.barrel.emplace(make_barrel_cam(design));
    sample_barrel(r, samples);
    r.extrema = motion_extrema(*r.program, uniform_angles(samples));
  }
  r.issues = check_continuity(*r.program, 3);
  const auto& segments = r.program->segments();
  for (std::size_t k = 1; k < segments.size(); ++k)
    r.boundaries_deg.push_back(segments[k].start() * kDegreesPerRadian);
  return r;
}

}  // namespace polarform::studio
