#include "ui/studio/fit_workspace.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <sstream>

#include "export/iges_writer.h"
#include "export/step_writer.h"
#include "export/x3d_writer.h"
#include "jobs/fit/fit_outputs.h"
#include "src/io/point_cloud.h"
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

LoadedCloud load_cloud(const std::filesystem::path& file, TaskControl& control) {
  LoadedCloud c;
  c.file = file;
  const auto start = std::chrono::steady_clock::now();
  ReadOptions read;
  read.skip_bad = true;
  read.progress = [&control](double f) { control.report(0.8 * f); };
  PointCloud cloud = read_point_cloud(file, read);
  c.read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  c.points = std::move(cloud.points);
  c.dropped = cloud.dropped;
  control.report(0.85);
  try {
    FrameOptions options;
    options.quadric.threads = kThreads;
    c.frame = estimate_frame(c.points, options);
  } catch (const TaskCancelled&) {
    throw;
  } catch (...) {
    c.frame_error = failure_text("local frame", std::current_exception());
  }
  control.report(0.95);
  c.bounds = bounds_of(c.points);
  c.display = make_point_set(c.points, c.bounds.center(), kCloudRgb);
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
  if (cloud_) return cloud_->file.filename().string();
  return loading_.empty() ? "no point cloud" : loading_.filename().string();
}

bool FitWorkspace::save(const std::filesystem::path& file) {
  if (!cloud_) return false;
  // The scan relative to the project when it lies below the project's folder, else absolute.
  const std::filesystem::path scan = std::filesystem::absolute(cloud_->file);
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
    std::vector<std::string> ignored;
    settings_ = fit_settings(project, ignored);
    for (const std::string& field : ignored)
      log().warning(file.filename().string() + ": not used by the studio: " + field);
    cloud = scan_path(project, file);
    project_path_ = file;
  }
  saved_settings_ = settings_;
  history_.reset(settings_);
  fit_task_.cancel();
  loading_ = cloud;
  load_task_.start([cloud](TaskControl& control) { return load_cloud(cloud, control); });
  log().info("Reading " + cloud.string());
  return true;
}

void FitWorkspace::update() {
  if (auto outcome = load_task_.poll()) {
    if (outcome->value) {
      cloud_ = std::make_shared<const LoadedCloud>(std::move(*outcome->value));
      fit_.reset();
      fit_error_.clear();
      std::ostringstream msg;
      msg << "Read " << cloud_->points.cols() << " points from " << cloud_->file.filename().string()
          << " in " << cloud_->read_seconds << " s";
      if (cloud_->dropped) msg << " (" << cloud_->dropped << " bad records skipped)";
      log().info(msg.str());
      if (cloud_->dropped)
        log().warning(cloud_->file.filename().string() + ": skipped " +
                      std::to_string(cloud_->dropped) + " bad records");
      if (!cloud_->frame_error.empty()) log().warning(cloud_->frame_error);
      show_cloud();
      if (fit_on_open_) start_fit();
    } else if (outcome->error) {
      log().error(failure_text("Open " + loading_.filename().string(), outcome->error));
    }
    loading_.clear();
  }
  if (auto outcome = fit_task_.poll()) {
    fit_seconds_ = outcome->seconds;
    if (outcome->value) {
      fit_ = std::move(*outcome->value);
      fit_error_.clear();
      show_fit();
      log().info("Fit finished in " + number_text(fit_seconds_) + " s: " + fit_->fit.reason);
    } else if (outcome->cancelled) {
      log().info("Fit cancelled");
    } else if (outcome->error) {
      fit_error_ = failure_text("Fit", outcome->error);
      log().error(fit_error_);
    }
  }
}

void FitWorkspace::start_fit() {
  if (!cloud_) return;
  fit_error_.clear();
  fit_task_.start([cloud = cloud_, settings = settings_](TaskControl& control) {
    RotationalFitOptions options = to_fit_options(settings, kThreads);
    const ProgressFn progress = [&control](double f) { control.report(f); };
    options.spherical.function.progress = progress;
    options.cylindrical.function.progress = progress;
    FitRun run;
    run.settings = settings;
    run.fit = fit_rotational(cloud->points, options);
    const FitReport& report = run.fit.report();
    run.scale = std::max(report.error.p99, 1e-12);
    run.deviation =
        make_point_set(cloud->points, cloud->bounds.center(), report.signed_distance, run.scale);
    return run;
  });
}

void FitWorkspace::show_cloud() {
  scene_.layer(SceneLayer::cloud).upload(cloud_->display);
  scene_.layer(SceneLayer::surface).clear();
  scene_.layer(SceneLayer::net).clear();
  LineSet axes;
  if (cloud_->frame) {
    const LocalFrame& f = cloud_->frame->frame;
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
  TriangleMesh mesh = make_surface_mesh(fit_->fit.surface(), origin, kSurfaceRgb, 96, 96);
  LineSet net;
  add_control_net(net, fit_->fit.surface(), origin, kNetRgb);
  if (const auto& s = fit_->fit.spherical)
    for (const auto* cap :
         {s->north_cap ? &*s->north_cap : nullptr, s->south_cap ? &*s->south_cap : nullptr})
      if (cap) {
        append_mesh(mesh, make_surface_mesh(cap->surface, origin, kSurfaceRgb, 32, 96));
        add_control_net(net, cap->surface, origin, kNetRgb);
      }
  scene_.layer(SceneLayer::surface).upload(mesh);
  scene_.layer(SceneLayer::net).upload(net);
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
    ImGui::TextWrapped("%s", cloud_->file.string().c_str());
    ImGui::Text("%ld points, read in %.2f s", static_cast<long>(cloud_->points.cols()),
                cloud_->read_seconds);
    const Eigen::Vector3d size = cloud_->bounds.max - cloud_->bounds.min;
    ImGui::Text("extent %s mm", text_of(size).c_str());
  }
  section("Local frame (Bae 2002, §4.3)");
  const FrameEstimate* frame =
      fit_ ? &fit_->fit.frame() : (cloud_ && cloud_->frame ? &*cloud_->frame : nullptr);
  if (frame) {
    if (frame->quadric)
      ImGui::Text("quadric: %s", to_string(frame->quadric->classification.type).c_str());
    ImGui::Text("origin %s", text_of(frame->frame.origin).c_str());
    ImGui::Text("axis k %s", text_of(frame->frame.axes.col(2)).c_str());
    ImGui::TextWrapped("%s", frame->reason.c_str());
  } else if (cloud_) {
    ImGui::TextColored(ImVec4(0.8f, 0.1f, 0.1f, 1), "%s", cloud_->frame_error.c_str());
  }
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
    if (ImGui::Button("Fit surface", ImVec2(-FLT_MIN, 0))) start_fit();
    ImGui::EndDisabled();
  }
  if (!fit_error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, color::error);
    ImGui::TextWrapped("%s", fit_error_.c_str());
    ImGui::PopStyleColor();
  }
}

void FitWorkspace::draw_report() {
  if (!fit_) return;
  const RotationalFit& f = fit_->fit;
  const FitReport& r = f.report();
  section("Fit report");
  ImGui::Text("method: %s%s", to_string(f.method).c_str(),
              fit_->settings == settings_ ? "" : " (options changed since)");
  ImGui::TextWrapped("%s", f.reason.c_str());
  ImGui::Text("F: degree (%d, %d), net %d x %d, λ = %.3g", r.degree_u, r.degree_v, r.size_u,
              r.size_v, r.lambda);
  ImGui::Text("NURBS: degree (%d, %d), %d x %d control points", r.nurbs_degree_u, r.nurbs_degree_v,
              r.nurbs_size_u, r.nurbs_size_v);
  if (ImGui::BeginTable("errors", 3, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchSame)) {
    ImGui::TableSetupColumn("distance [mm]");
    ImGui::TableSetupColumn("true (closest point)");
    ImGui::TableSetupColumn("along the ray");
    ImGui::TableHeadersRow();
    const auto row = [](const char* name, double a, double b) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(name);
      ImGui::TableNextColumn();
      ImGui::Text("%.4g", a);
      ImGui::TableNextColumn();
      ImGui::Text("%.4g", b);
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
  ImGui::Text("time %.2f s (frame %.2f, sync %.2f, solve %.2f, error %.2f)", fit_seconds_,
              r.times.frame, r.times.sync, r.times.solve, r.times.error);
}

void FitWorkspace::draw_view() {
  if (!cloud_) {
    ImGui::TextDisabled(load_task_.busy() ? "Reading…" : "No point cloud.");
    return;
  }
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
    char text[96];
    std::snprintf(text, sizeof text, "signed distance: −%.3g … +%.3g mm (outside +)", fit_->scale,
                  fit_->scale);
    dl->AddText(ImVec2(o.x, o.y + h + 2), color::text, text);
  }
}

FitJobResult FitWorkspace::job_result() const {
  FitJobResult r;
  r.input = cloud_->file;
  r.points = cloud_->points;
  r.dropped = cloud_->dropped;
  r.method = to_string(fit_->fit.method);
  r.reason = fit_->fit.reason;  // r.plane: only profiles (polar fits) report it
  r.surface = fit_->fit;
  r.fairness = static_cast<FairnessOptions::Mode>(fit_->settings.fairness);
  r.fairness_weight = fit_->settings.fairness_weight;
  r.base = fit_->settings.quartic_base ? ArcKind::quartic : ArcKind::rqb;
  r.seconds = cloud_->read_seconds + fit_seconds_;
  return r;
}

std::vector<ExportChoice> FitWorkspace::export_choices() const {
  const std::string stem = cloud_ ? cloud_->file.stem().string() + "_fit" : "fit";
  const bool ready = fit_.has_value();
  const std::string needs = ready ? "" : "fit a surface first";
  return {{{"all", "Export all outputs into the folder", "", stem + "_outputs"},
           "All outputs to a folder…",
           ready,
           "What `polarform fit` writes: the surface as IGES, STEP and X3D, deviation.ply, "
           "preview.svg and report.json"},
          {{"iges", "Export IGES", ".igs", stem + ".igs"}, "Surface as IGES…", ready, needs, true},
          {{"step", "Export STEP", ".stp", stem + ".stp"}, "Surface as STEP…", ready, needs},
          {{"x3d", "Export X3D", ".x3d", stem + ".x3d"}, "Surface as X3D…", ready, needs}};
}

void FitWorkspace::export_to(const ExportRequest& request, const std::filesystem::path& file) {
  if (!fit_) return;
  guarded(log(), "Export " + file.filename().string(), [&] {
    if (request.tag == "all") {
      const auto files = write_fit_outputs(job_result(), file);
      log().info("Wrote " + std::to_string(files.size()) + " files into " + file.string());
      return;
    }
    const NurbsSurface& s = fit_->fit.surface();
    if (request.tag == "iges") {
      IgesWriter w;
      w.add(s, "fitted surface");
      w.save(file);
    } else if (request.tag == "step") {
      StepWriter w("fitted surface");
      w.add(s, "surface");
      w.save(file);
    } else if (request.tag == "x3d") {
      X3dWriter w;
      w.add(s, "surface");
      w.save(file, document_name());
    }
    log().info("Exported " + file.string());
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
  out << "points=" << (cloud_ ? cloud_->points.cols() : 0) << "\n";
  out << "net_setting="
      << (settings_.use_tolerance ? "tolerance"
                                  : std::to_string(settings_.size_u) + "x" +
                                        std::to_string(settings_.size_v))
      << "\n";
  if (cloud_ && cloud_->frame && cloud_->frame->quadric)
    out << "quadric=" << to_string(cloud_->frame->quadric->classification.type) << "\n";
  out << "fitted=" << (fit_ ? 1 : 0) << "\n";
  if (fit_) {
    const FitReport& r = fit_->fit.report();
    out << "method=" << to_string(fit_->fit.method) << "\nrms_mm=" << r.error.rms
        << "\nmax_mm=" << r.error.max << "\nnurbs_degree=" << r.nurbs_degree_u << "x"
        << r.nurbs_degree_v << "\ncontrol_points=" << r.nurbs_size_u << "x" << r.nurbs_size_v
        << "\n";
  }
  return out.str();
}

}  // namespace polarform::studio
