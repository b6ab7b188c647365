// The cam workspace's File ▸ Export, through the cam job's output bundle (jobs/cam/cam_outputs.h):
// every output of `polarform cam` into a folder, or one of its files — the profile (IGES, STEP,
// DXF, X3D; the degree-capped one when the project caps the degree) or the motion table
// (svaj.csv) — byte for byte what the CLI writes. Part of CamWorkspace (cam_workspace.h).
#include <algorithm>
#include <cctype>

#include "export/atomic_file.h"
#include "jobs/cam/cam_job.h"
#include "jobs/cam/cam_outputs.h"
#include "src/number_text.h"
#include "src/units.h"
#include "ui/studio/cam_workspace.h"
#include "ui/studio/guarded.h"

namespace polarform::studio {

std::vector<ExportChoice> CamWorkspace::export_choices() const {
  const std::string stem = document_.path().empty() ? "cam" : document_.path().stem().string();
  const bool valid = design_.has_value() && design_error_.empty();
  std::vector<ExportChoice> choices{
      {{"all", "Export all outputs into the folder", "", stem + "_outputs"},
       "All outputs to a folder…",
       valid,
       "What `polarform cam` writes: IGES, STEP, DXF, X3D, SVG plots, SVAJ CSV, report.html and "
       "report.json"}};
  const bool plate = design_ && std::holds_alternative<PlateCam>(design_->cam);
  const std::string what = plate || !design_ ? "Profile" : "Track";
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
    CamOutputOptions options;
    options.design_name = document_.path().empty() ? "cam" : document_.path().stem().string();
    const CamJobResult job = run_cam_job(document_.current());
    if (request.tag == "all") {
      const std::vector<std::string> files = write_cam_outputs(job, file, options);
      log().info("Wrote " + std::to_string(files.size()) + " files into " + file.string());
      return;
    }
    const std::string stem = job.plate() ? "profile" : "track";
    const std::map<std::string, std::string> bundle = render_cam_outputs(job, options);
    const std::string name = request.tag == "csv"    ? "svaj.csv"
                             : request.tag == "iges" ? stem + ".igs"
                             : request.tag == "step" ? stem + ".stp"
                                                     : stem + "." + request.tag;
    write_file_atomically(file, bundle.at(name));
    const auto* profile = std::get_if<PlateProfile>(&job.conversion.profile);
    if (request.tag != "csv" && profile && profile->capped)
      log().info("Exported " + file.string() + " (" + name + "): degree-" +
                 std::to_string(profile->capped->curve.degree()) +
                 " profile (the project caps the degree), measured radial error " +
                 number_text(to_micrometres(profile->capped->max_radial_error)) + " µm");
    else
      log().info("Exported " + file.string() + " (" + name + ")");
  });
}

}  // namespace polarform::studio
