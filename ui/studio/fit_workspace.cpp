#include "ui/studio/fit_workspace.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <sstream>

#include "export/atomic_file.h"
#include "jobs/fit/fit_outputs.h"
#include "jobs/project/cam_project.h"
#include "jobs/report/report_lines.h"
#include "jobs/scan_cam/scan_cam_outputs.h"
#include "jobs/scan_cam/scan_cam_project.h"
#include "src/number_text.h"
#include "ui/studio/colors.h"
#include "ui/studio/guarded.h"
#include "ui/studio/splitter.h"
#include "ui/studio/widgets.h"

namespace polarform::studio {
namespace {

constexpr float kCloudRgb[3] = {0.25f, 0.35f, 0.55f};
constexpr float kSurfaceRgb[3] = {0.78f, 0.74f, 0.66f};
constexpr float kNetRgb[3] = {0.2f, 0.2f, 0.25f};
constexpr int kThreads = 2;

// The fit job's read and preview stages, and the cloud as the 3D view draws it.
LoadedCloud load_cloud(const std::filesystem::path& file, FitJobOptions options,
                       TaskControl& control) {
  options.skip_bad = true;  // the studio skips bad records and says how many
  options.read_progress = [&control](double f) { control.report(0.8 * f); };
  LoadedCloud c{read_fit_input(file, options), std::nullopt, {}, {}, {}};
  control.report(0.85);
  try {
    c.preview = preview_fit(c.input, options);
  } catch (const TaskCancelled&) {
    throw;
  } catch (...) {
    c.preview_error = failure_text("Fit preview", std::current_exception());
  }
  control.report(0.95);
  c.bounds = bounds_of(c.input.points);
  c.display = make_point_set(c.input.points, c.bounds.center(), kCloudRgb);
  return c;
}

std::string text_of(const Eigen::Vector3d& v) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.4g, %.4g, %.4g)", v.x(), v.y(), v.z());
  return buffer;
}

}  // namespace

FitWorkspace::FitWorkspace(StudioContext& context) : Workspace(context) {}

std::string FitWorkspace::document_name() const {
  if (cloud_) return cloud_->input.file.filename().string();
  return loading_.empty() ? "no point cloud" : loading_.filename().string();
}

bool FitWorkspace::save(const std::filesystem::path& file) {
  if (!cloud_) return false;
  // The scan relative to the project when it lies below the project's folder, else absolute.
  const std::filesystem::path scan = std::filesystem::absolute(cloud_->input.file);
  const std::filesystem::path relative =
      scan.lexically_relative(std::filesystem::absolute(file).parent_path());
  const bool below = !relative.empty() && *relative.begin() != "..";
  if (!guarded(log(), "Save " + file.filename().string(), [&] {
        write_fit_project(fit_project(settings_, below ? relative : scan), file);
      }))
    return false;
  project_path_ = file;
  saved_settings_ = settings_;
  log().info("Saved " + file.string());
  return true;
}

bool FitWorkspace::open(const std::filesystem::path& file, bool) {
  std::filesystem::path cloud = file;
  project_path_.clear();
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".xml") {  // a fit project: its settings, then its scan
    std::vector<std::string> notes;
    FitProject project;
    if (!guarded(log(), "Open " + file.filename().string(),
                 [&] { project = read_fit_project(file, notes); }))
      return false;
    for (const std::string& note : notes) log().warning(note);
    settings_ = fit_settings(project);
    cloud = scan_path(project, file);
    project_path_ = file;
  } else {  // a bare cloud: the options of `polarform fit CLOUD`
    settings_ = FitSettings{};
  }
  saved_settings_ = settings_;
  history_.reset(settings_);
  fit_task_.cancel();
  loading_ = cloud;
  load_task_.start([cloud, options = job_options()](TaskControl& control) {
    return load_cloud(cloud, options, control);
  });
  log().info("Reading " + cloud.string());
  return true;
}

void FitWorkspace::update() {
  if (auto outcome = load_task_.poll()) {
    if (outcome->value) {
      cloud_ = std::make_shared<const LoadedCloud>(std::move(*outcome->value));
      fit_.reset();
      cam_scan_.reset();
      fit_error_.clear();
      const FitInput& in = cloud_->input;
      log().info("Read " + std::to_string(in.points.cols()) + " points from " +
                 in.file.filename().string() + " in " + number_text(in.read_seconds) + " s" +
                 (in.dropped ? " (" + std::to_string(in.dropped) + " bad records skipped)" : ""));
      if (in.dropped)
        log().warning(in.file.filename().string() + ": skipped " + std::to_string(in.dropped) +
                      " bad records");
      if (!cloud_->preview_error.empty()) log().warning(cloud_->preview_error);
      if (cloud_->preview && !cloud_->preview->frame_error.empty())
        log().warning(cloud_->preview->frame_error);
      show_cloud();
      if (fit_on_open_) start_fit();
    } else if (outcome->error) {
      log().error(failure_text("Open " + loading_.filename().string(), outcome->error));
    }
    loading_.clear();
  }
  cam_scan_.update(log());
  if (auto outcome = fit_task_.poll()) {
    fit_seconds_ = outcome->seconds;
    if (outcome->value) {
      fit_ = std::move(*outcome->value);
      fit_error_.clear();
      show_fit();
      log().info("Fit finished in " + number_text(fit_seconds_) + " s: " + fit_->result.reason);
      for (const std::string& w : fit_->result.warnings) log().warning(w);
    } else if (outcome->cancelled) {
      log().info("Fit cancelled");
    } else if (outcome->error) {
      fit_error_ = failure_text("Fit", outcome->error);
      log().error(fit_error_);
    }
  }
}

FitJobOptions FitWorkspace::job_options() const {
  FitJobOptions options = fit_job_options(fit_project(settings_, {}));
  options.threads = kThreads;
  return options;
}

void FitWorkspace::start_fit() {
  if (!cloud_) return;
  fit_error_.clear();
  fit_task_.start([cloud = cloud_, settings = settings_,
                   options = job_options()](TaskControl& control) mutable {
    options.fit_progress = [&control](double f) { control.report(f); };
    FitRun run{settings, fit_cloud(cloud->input, options), {}, 0.0};
    run.scale = deviation_color_limit(run.result);
    run.deviation = make_point_set(run.result.points, cloud->bounds.center(),
                                   run.result.report().signed_distance, run.scale);
    return run;
  });
}

void FitWorkspace::show_cloud() {
  scene_.layer(SceneLayer::cloud).upload(cloud_->display);
  scene_.layer(SceneLayer::surface).clear();
  scene_.layer(SceneLayer::net).clear();
  LineSet axes;
  const LocalFrame* frame = !cloud_->preview           ? nullptr
                            : cloud_->preview->profile ? &cloud_->preview->plane.frame
                            : cloud_->preview->frame   ? &cloud_->preview->frame->frame
                                                       : nullptr;
  if (frame) {
    const LocalFrame& f = *frame;
    const double length = 0.6 * cloud_->bounds.radius();
    const float rgb[3][3] = {{0.84f, 0.37f, 0.0f}, {0.0f, 0.62f, 0.45f}, {0.0f, 0.45f, 0.7f}};
    for (int k = 0; k < 3; ++k)
      add_segment(axes, f.origin, f.origin + f.axes.col(k) * length, cloud_->bounds.center(),
                  rgb[k]);
  }
  scene_.layer(SceneLayer::extra).upload(axes);
  SceneBounds centred;
  centred.add(cloud_->bounds.min - cloud_->bounds.center());
  centred.add(cloud_->bounds.max - cloud_->bounds.center());
  scene_.set_bounds(centred, true);
}

void FitWorkspace::show_fit() {
  const Eigen::Vector3d origin = cloud_->bounds.center();
  TriangleMesh mesh;
  LineSet net, curve;
  if (const auto* surface = std::get_if<RotationalFit>(&fit_->result.fit)) {
    mesh = make_surface_mesh(surface->surface(), origin, kSurfaceRgb, 96, 96);
    add_control_net(net, surface->surface(), origin, kNetRgb);
    if (const auto* s = std::get_if<SphericalFit>(&surface->fit))
      for (const auto* cap :
           {s->north_cap ? &*s->north_cap : nullptr, s->south_cap ? &*s->south_cap : nullptr})
        if (cap) {
          append_mesh(mesh, make_surface_mesh(cap->surface, origin, kSurfaceRgb, 32, 96));
          add_control_net(net, cap->surface, origin, kNetRgb);
        }
  } else {  // a polar profile: the curve and its control polygon
    const NurbsCurve3d& c = std::get<ProfileFit>(fit_->result.fit).curve;
    std::vector<Eigen::Vector3d> points;
    for (int k = 0; k <= 2000; ++k)
      points.push_back(c(c.front() + (c.back() - c.front()) * k / 2000));
    add_polyline(curve, points, origin, kSurfaceRgb);
    add_polyline(net, c.control_points(), origin, kNetRgb);
  }
  scene_.layer(SceneLayer::surface).upload(mesh);
  scene_.layer(SceneLayer::net).upload(net);
  if (!curve.positions.empty()) scene_.layer(SceneLayer::extra).upload(curve);
  scene_.layer(SceneLayer::cloud).upload(show_deviation_ ? fit_->deviation : cloud_->display);
}

void FitWorkspace::draw() {
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  float& left_fraction = layout("fit.left", 0.28f);
  const float left = split_size(left_fraction, avail.x, ImGui::GetFontSize() * 12);
  ImGui::BeginChild("fit controls", ImVec2(left, avail.y), true);
  draw_controls();
  draw_report();
  ImGui::EndChild();
  history_.settle(settings_, ImGui::IsAnyItemActive());
  ImGui::SameLine(0, 0);
  vertical_splitter("fit split", left_fraction, avail.x);
  ImGui::SameLine(0, 0);
  ImGui::BeginChild("fit view", ImVec2(0, avail.y), false,
                    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  draw_view();
  ImGui::EndChild();
}

void FitWorkspace::draw_controls() {
  section("Point cloud");
  if (load_task_.busy()) {
    ImGui::Text("Reading %s…", loading_.filename().string().c_str());
    ImGui::ProgressBar(static_cast<float>(load_task_.progress()));
  } else if (!cloud_) {
    ImGui::TextWrapped(
        "Open a scan (xyz, csv, PLY, STL, OBJ, OFF) with File ▸ Open (Ctrl+O) or drop it on the "
        "window.");
    return;
  }
  if (cloud_) {
    ImGui::TextWrapped("%s", cloud_->input.file.string().c_str());
    ImGui::Text("%ld points, read in %s s", static_cast<long>(cloud_->input.points.cols()),
                number_text(cloud_->input.read_seconds).c_str());
    const Eigen::Vector3d size = cloud_->bounds.max - cloud_->bounds.min;
    ImGui::Text("extent %s mm", text_of(size).c_str());
  }
  draw_frame();
  section("Fit options");
  draw_fit_options(settings_);
  ImGui::Checkbox("fit when a cloud is opened", &fit_on_open_);
  ImGui::Spacing();
  if (fit_task_.busy()) {
    ImGui::ProgressBar(static_cast<float>(fit_task_.progress()),
                       ImVec2(-ImGui::GetFontSize() * 6, 0));
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) fit_task_.cancel();
  } else {
    ImGui::BeginDisabled(!cloud_);
    if (ImGui::Button("Fit", ImVec2(-FLT_MIN, 0))) start_fit();
    ImGui::EndDisabled();
  }
  if (!fit_error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, color::error);
    ImGui::TextWrapped("%s", fit_error_.c_str());
    ImGui::PopStyleColor();
  }
  if (!planar_profile()) return;
  section("Cam scan (polarform scan-cam)");
  cam_scan_.draw_controls(cloud_->input.file);
  const ScanCamJobResult* scan = cam_scan_.result();
  ImGui::BeginDisabled(!scan || !scan->design);
  if (ImGui::Button("Open the design in the Cam workspace", ImVec2(-FLT_MIN, 0)))
    open_recovered_design();
  ImGui::EndDisabled();
}

// The recovered design as `--write-project` writes it, saved to a file in the system's temporary
// folder and opened from there as a new, untitled cam project (Save asks where it goes).
void FitWorkspace::open_recovered_design() {
  guarded(log(), "Open the recovered design", [&] {
    const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                       (cloud_->input.file.stem().string() + "_design.xml");
    write_file_atomically(file, cam_project_xml(recovered_cam_project(*cam_scan_.result())));
    if (context_.open_as_template) context_.open_as_template(file);
  });
}

// The plane of a profile, or the local frame of a surface (Bae 2002, §4.3): the fit's once there
// is one, else the preview's.
void FitWorkspace::draw_frame() {
  const FitJobResult* r = fit_ ? &fit_->result : nullptr;
  const FitPreview* p = cloud_ && cloud_->preview ? &*cloud_->preview : nullptr;
  const bool profile = r ? r->profile() : p && p->profile;
  if (profile) {
    section("Profile plane");
    const CloudPlane& plane = r ? r->plane : p->plane;
    ImGui::Text("origin %s", text_of(plane.frame.origin).c_str());
    ImGui::Text("normal %s", text_of(plane.frame.axes.col(2)).c_str());
    ImGui::TextWrapped("points within %s mm (rms) of the plane",
                       number_text(plane.rms_distance).c_str());
    return;
  }
  section("Local frame (Bae 2002, §4.3)");
  const FrameEstimate* frame = r               ? &std::get<RotationalFit>(r->fit).frame()
                               : p && p->frame ? &*p->frame
                                               : nullptr;
  if (frame) {
    if (frame->quadric)
      ImGui::Text("quadric: %s", to_string(frame->quadric->classification.type).c_str());
    ImGui::Text("origin %s", text_of(frame->frame.origin).c_str());
    ImGui::Text("axis k %s", text_of(frame->frame.axes.col(2)).c_str());
    ImGui::TextWrapped("%s", frame->reason.c_str());
  } else if (cloud_) {
    const std::string& why = !cloud_->preview_error.empty() ? cloud_->preview_error
                             : p                            ? p->frame_error
                                                            : "";
    ImGui::TextColored(ImVec4(0.8f, 0.1f, 0.1f, 1), "%s", why.c_str());
  }
}

void FitWorkspace::draw_report() {
  if (!fit_) return;
  const FitJobResult& f = fit_->result;
  const FitReport& r = f.report();
  section("Fit report");
  ImGui::Text("method: %s%s", f.method.c_str(),
              fit_->settings == settings_ ? "" : " (options changed since)");
  ImGui::TextWrapped("%s", f.reason.c_str());
  if (const auto* profile = std::get_if<ProfileFit>(&f.fit)) {
    ImGui::Text("F: degree %d, %d control values, λ = %s", r.degree_v, r.size_v,
                number_text(r.lambda).c_str());
    ImGui::Text("NURBS curve: degree %d, %d control points", profile->curve.degree(),
                profile->curve.size());
  } else {
    ImGui::Text("F: degree (%d, %d), net %d x %d, λ = %s", r.degree_u, r.degree_v, r.size_u,
                r.size_v, number_text(r.lambda).c_str());
    ImGui::Text("NURBS: degree (%d, %d), %d x %d control points", r.nurbs_degree_u,
                r.nurbs_degree_v, r.nurbs_size_u, r.nurbs_size_v);
  }
  if (ImGui::BeginTable("errors", 3, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchSame)) {
    ImGui::TableSetupColumn("distance [mm]");
    ImGui::TableSetupColumn("true (closest point)");
    ImGui::TableSetupColumn("along the ray");
    ImGui::TableHeadersRow();
    const auto row = [](const char* name, double a, double b) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(name);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(number_text(a).c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(number_text(b).c_str());
    };
    row("rms", r.error.rms, r.radial.rms);
    row("mean", r.error.mean, r.radial.mean);
    row("95 %", r.error.p95, r.radial.p95);
    row("99 %", r.error.p99, r.radial.p99);
    row("max", r.error.max, r.radial.max);
    ImGui::EndTable();
  }
  if (r.unconverged)
    ImGui::TextColored(ImVec4(0.7f, 0.4f, 0, 1), "%zu closest-point searches did not converge",
                       r.unconverged);
  ImGui::Text("time %s s (frame %s, sync %s, solve %s, error %s)",
              number_text(fit_seconds_).c_str(), number_text(r.times.frame).c_str(),
              number_text(r.times.sync).c_str(), number_text(r.times.solve).c_str(),
              number_text(r.times.error).c_str());
}

void FitWorkspace::draw_view() {
  if (!cloud_) {
    ImGui::TextDisabled(load_task_.busy() ? "Reading…" : "No point cloud.");
    return;
  }
  if (!planar_profile() || (!cam_scan_.result() && !cam_scan_.busy())) {
    draw_scene();
    return;
  }
  if (!ImGui::BeginTabBar("fit views")) return;
  if (ImGui::BeginTabItem("Cloud and fit")) {
    draw_scene();
    ImGui::EndTabItem();
  }
  if (ImGui::BeginTabItem("Cam motion")) {
    cam_scan_.draw_result(ImGui::GetContentRegionAvail());
    ImGui::EndTabItem();
  }
  ImGui::EndTabBar();
}

void FitWorkspace::draw_scene() {
  ImGui::Checkbox("points", &scene_.visible(SceneLayer::cloud));
  ImGui::SameLine();
  ImGui::Checkbox("surface", &scene_.visible(SceneLayer::surface));
  ImGui::SameLine();
  ImGui::Checkbox("control net", &scene_.visible(SceneLayer::net));
  ImGui::SameLine();
  ImGui::Checkbox("frame", &scene_.visible(SceneLayer::extra));
  ImGui::SameLine();
  ImGui::BeginDisabled(!fit_);
  if (ImGui::Checkbox("deviation colours", &show_deviation_) && fit_)
    scene_.layer(SceneLayer::cloud).upload(show_deviation_ ? fit_->deviation : cloud_->display);
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6);
  ImGui::SliderFloat("point size", &scene_.point_size, 1.0f, 8.0f, "%.0f px");
  ImGui::SameLine();
  if (ImGui::Button("Fit view")) scene_.fit();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  scene_.draw(ImGui::GetContentRegionAvail());
  if (fit_ && show_deviation_) {  // colour legend of the deviation map
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float fh = ImGui::GetFontSize(), w = fh * 12, h = fh * 0.7f;
    const ImVec2 o(origin.x + fh, origin.y + fh);
    for (int i = 0; i < 40; ++i)
      dl->AddRectFilled(ImVec2(o.x + w * i / 40, o.y), ImVec2(o.x + w * (i + 1) / 40, o.y + h),
                        diverging_color(-1.0 + 2.0 * (i + 0.5) / 40));
    const std::string text = "signed distance: −" + number_text(fit_->scale) + " … +" +
                             number_text(fit_->scale) + " mm (outside +)";
    dl->AddText(ImVec2(o.x, o.y + h + 2), color::text, text.c_str());
  }
}

std::vector<ExportChoice> FitWorkspace::export_choices() const {
  const std::string stem = cloud_ ? cloud_->input.file.stem().string() + "_fit" : "fit";
  const bool ready = fit_.has_value();
  const std::string what = fit_ && fit_->result.profile() ? "Curve" : "Surface";
  const std::string needs = ready ? "" : "fit first";
  return {
      {{"all", "Export all outputs into the folder", "", stem + "_outputs"},
       "All outputs to a folder…",
       ready,
       "What `polarform fit` writes: the fitted surface or curve as IGES, STEP and X3D, "
       "deviation.ply, preview.svg, report.html and report.json"},
      {{"iges", "Export IGES", ".igs", stem + ".igs"}, what + " as IGES…", ready, needs, true},
      {{"step", "Export STEP", ".stp", stem + ".stp"}, what + " as STEP…", ready, needs},
      {{"x3d", "Export X3D", ".x3d", stem + ".x3d"}, what + " as X3D…", ready, needs},
      {{"scan-cam", "Export the scan-cam outputs into the folder", "", stem + "_scan_cam"},
       "Cam scan outputs to a folder…",
       planar_profile(),
       "What `polarform scan-cam` writes for this profile with the follower chosen under Cam scan "
       "(the job runs first if it has not)",
       true},
      {{"design", "Export the recovered cam design", ".xml", stem + "_design.xml"},
       "Recovered cam design as a project…",
       planar_profile(),
       "The project `polarform scan-cam --write-project` writes"}};
}

void FitWorkspace::export_to(const ExportRequest& request, const std::filesystem::path& file) {
  if (request.tag == "scan-cam" || request.tag == "design") {
    guarded(log(), "Export " + file.filename().string(), [&] {
      const ScanCamJobResult& r = cam_scan_.ensure(cloud_->input.file);
      if (request.tag == "design") {
        write_file_atomically(file, cam_project_xml(recovered_cam_project(r)));
        log().info("Exported the recovered design to " + file.string());
        return;
      }
      const auto files = write_scan_cam_outputs(r, file);
      log().info("Wrote " + std::to_string(files.size()) + " files into " + file.string());
    });
    return;
  }
  if (!fit_) return;
  guarded(log(), "Export " + file.filename().string(), [&] {
    if (request.tag == "all") {
      const auto files = write_fit_outputs(fit_->result, file);
      log().info("Wrote " + std::to_string(files.size()) + " files into " + file.string());
      return;
    }
    // One file of the job's bundle, byte for byte what `polarform fit` writes.
    const std::string name = std::string(fit_->result.profile() ? "curve" : "surface") +
                             (request.tag == "iges"   ? ".igs"
                              : request.tag == "step" ? ".stp"
                                                      : ".x3d");
    write_file_atomically(file, render_fit_outputs(fit_->result).at(name));
    log().info("Exported " + file.string() + " (" + name + ")");
  });
}

void FitWorkspace::bench_step(int, int frames) {
  // Scripted view: one full turn of the camera over the benchmark.
  scene_.turn(2.0f * std::numbers::pi_v<float> / static_cast<float>(frames));
}

bool FitWorkspace::scripted_edit() {
  if (!cloud_) return false;
  settings_.use_tolerance = false;
  settings_.size_u = std::max(4, settings_.size_u - 4);
  settings_.size_v = std::max(4, settings_.size_v - 4);
  history_.settle(settings_, false);
  start_fit();
  return true;
}

std::string FitWorkspace::numbers() const {
  std::ostringstream out;
  out << "points=" << (cloud_ ? cloud_->input.points.cols() : 0) << "\n";
  out << "net_setting="
      << (settings_.use_tolerance ? "tolerance"
                                  : std::to_string(settings_.size_u) + "x" +
                                        std::to_string(settings_.size_v))
      << "\n";
  if (cloud_ && cloud_->preview && cloud_->preview->frame && cloud_->preview->frame->quadric)
    out << "quadric=" << to_string(cloud_->preview->frame->quadric->classification.type) << "\n";
  out << "fitted=" << (fit_ ? 1 : 0) << "\n";
  // The fields of report.json for the fit shown, from the job's own report builder.
  if (fit_) out << report_lines(fit_report_fields(fit_->result));
  // The scan-cam job's report.json fields, when it ran on this profile.
  if (const ScanCamJobResult* scan = cam_scan_.result())
    out << report_lines(scan_cam_report_json(*scan, {}), "scan_cam.");
  return out.str();
}

}  // namespace polarform::studio
