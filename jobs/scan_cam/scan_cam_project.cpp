#include "jobs/scan_cam/scan_cam_project.h"

#include "src/error.h"

namespace polarform {

CamProject recovered_cam_project(const ScanCamJobResult& r) {
  if (!r.design)
    throw InputError("--write-project: no design was recovered from " + r.input.string() + ": " +
                     r.design_failure);
  CamProject p;
  if (r.nominal_project) {
    p.conversion = r.nominal_project->conversion;
    p.max_degree = r.nominal_project->max_degree;
  }
  p.cam = r.design->design;
  if (r.nominal_project) p.cam.rpm = r.nominal_project->cam.rpm;
  return p;
}

}  // namespace polarform
