// The cam job's output bundle: CAD files (IGES, STEP, DXF, X3D, optionally a STEP solid), plots
// (SVG), the SVAJ table (CSV) and the reports (report.json, report.html) into one directory.
// Every file is written atomically; nothing is written before everything has been computed.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "jobs/cam/cam_job.h"
#include "jobs/cam/cam_report.h"

namespace polarform {

struct CamOutputOptions {
  std::string design_name = "cam";        // shown in reports and file headers
  std::optional<double> solid_thickness;  // mm: also write the plate cam as a solid
  std::optional<double> bore_diameter;    // mm, with the solid
};

// Every output of the job rendered in memory, file name → content: the CAD files, figures, CSV and
// both reports. The studio exports single files from it, so they equal the CLI's byte for byte.
std::map<std::string, std::string> render_cam_outputs(const CamJobResult& r,
                                                      const CamOutputOptions& options = {});

// Writes every output into dir (created if missing) and returns the file names written.
std::vector<std::string> write_cam_outputs(const CamJobResult& r, const std::filesystem::path& dir,
                                           const CamOutputOptions& options = {});

// What an infeasible design (an undercut contour) still shows: svaj.csv, svaj.svg, analysis.svg
// (the undercut shaded), report.json ("feasible": false) and report.html (marked INFEASIBLE); no
// CAD file.
std::map<std::string, std::string> render_infeasible_cam_outputs(
    const InfeasibleCam& cam, const CamOutputOptions& options = {});

// Where those go for `--out out`: out itself when it does not exist or is empty, else the sibling
// "out.infeasible", so that a failed run never alters an earlier run's outputs.
std::filesystem::path infeasible_outputs_dir(const std::filesystem::path& out);

std::vector<std::string> write_infeasible_cam_outputs(const InfeasibleCam& cam,
                                                      const std::filesystem::path& dir,
                                                      const CamOutputOptions& options = {});

}  // namespace polarform
