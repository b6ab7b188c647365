// The cam workspace's File ▸ Export, through the job layer the CLI uses (jobs/): every output
// of `polarform cam` into a folder, or one profile file (IGES, STEP, DXF, X3D) — the exact-degree
// profile, or the degree-capped one when the project limits the degree — and the sampled motion
// as CSV. Part of CamWorkspace (cam_workspace.h).
#include <algorithm>
#include <cctype>

#include "export/csv_writer.h"
#include "export/dxf_writer.h"
#include "export/iges_writer.h"
#include "export/step_writer.h"
#include "export/x3d_writer.h"
#include "jobs/cam/cam_job.h"
#include "jobs/cam/cam_outputs.h"
#include "src/number_text.h"
#include "src/units.h"
#include "ui/studio/cam_workspace.h"
#include "ui/studio/guarded.h"

namespace polarform::studio {
namespace {

// One profile file from the job's result.
void write_profile(const CamJobResult& r, const std::string& format,
                   const std::filesystem::path& file, const std::string& name) {
  if (r.plate) {
    const NurbsCurve2d& curve = r.capped ? r.capped->curve : r.profile;
    if (format == "iges") {
      IgesWriter w;
      w.add(curve, "cam profile");
      w.save(file);
    } else if (format == "step") {
      StepWriter w(name);
      w.add(curve, "profile");
      w.save(file);
    } else if (format == "dxf") {
      DxfWriter w(DxfOptions{std::max(10, curve.degree()), 1e-6});
      w.add(curve, "PROFILE");
      w.add_circle(Eigen::Vector3d::Zero(), r.project.cam.base_radius, "BASE_CIRCLE");
      w.save(file);
    } else if (format == "x3d") {
      X3dWriter w;
      w.add(curve, "profile");
      w.save(file, name);
    }
    return;
  }
  if (format == "iges") {
    IgesWriter w;
    w.add(r.track, "cam track");
    w.save(file);
  } else if (format == "step") {
    StepWriter w(name);
    w.add(r.track, "track");
    w.save(file);
  } else if (format == "dxf") {
    DxfWriter w(DxfOptions{std::max(10, r.track.degree()), 1e-6});
    w.add(r.track, "TRACK");
    w.save(file);
  } else if (format == "x3d") {
    X3dWriter w;
    w.add(r.track, "track");
    w.save(file, name);
  }
}

}  // namespace

std::vector<ExportChoice> CamWorkspace::export_choices() const {
  const std::string stem = document_.path().empty() ? "cam" : document_.path().stem().string();
  const bool valid = results_.has_value() && design_error_.empty();
  std::vector<ExportChoice> choices{
      {{"all", "Export all outputs into the folder", "", stem + "_outputs"},
       "All outputs to a folder…",
       valid,
       "What `polarform cam` writes: IGES, STEP, DXF, X3D, SVG plots, SVAJ CSV, report.html and "
       "report.json"}};
  const std::string what = results_ && results_->barrel ? "Track" : "Profile";
  const std::pair<const char*, const char*> formats[] = {
      {"iges", ".igs"}, {"step", ".stp"}, {"dxf", ".dxf"}, {"x3d", ".x3d"}};
  for (const auto& [tag, ext] : formats) {
    std::string upper = tag;
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    choices.push_back({{tag, "Export " + upper, ext, stem + ext}, what + " as " + upper + "…",
                       valid, "", choices.size() == 1});
  }
  choices.push_back({{"csv", "Export motion CSV", ".csv", stem + "_svaj.csv"},
                     "Motion (SVAJ) as CSV…", valid, "", true});
  return choices;
}

void CamWorkspace::export_to(const ExportRequest& request, const std::filesystem::path& file) {
  guarded(log(), "Export " + file.filename().string(), [&] {
    if (request.tag == "csv") {
      const MotionCurves& m = results_->motion;
      CsvWriter csv({"theta [deg]", "s [mm]", "v [mm/rad]", "a [mm/rad^2]", "j [mm/rad^3]",
                     "pressure angle [deg]"});
      for (std::size_t i = 0; i < m.theta_deg.size(); ++i)
        csv.row({m.theta_deg[i], m.s[i], m.v[i], m.a[i], m.j[i], m.pressure_deg[i]});
      csv.save(file);
      log().info("Exported " + file.string());
      return;
    }
    const std::string name = document_.path().empty() ? "cam" : document_.path().stem().string();
    const CamJobResult job = run_cam_job(document_.current());
    if (request.tag == "all") {
      CamOutputOptions options;
      options.design_name = name;
      const std::vector<std::string> files = write_cam_outputs(job, file, options);
      log().info("Wrote " + std::to_string(files.size()) + " files into " + file.string());
      return;
    }
    write_profile(job, request.tag, file, name);
    if (job.capped)
      log().info("Exported " + file.string() + ": degree-" +
                 std::to_string(job.capped->curve.degree()) +
                 " profile (the project caps the degree), measured radial error " +
                 number_text(to_micrometres(job.capped->max_radial_error)) + " µm");
    else
      log().info("Exported " + file.string());
  });
}

}  // namespace polarform::studio
