// The fit workspace: open a point cloud or a fit project (dialog or drag-and-drop), read and
// previewed by the fit job's first stages in the background with a progress bar — the cloud in 3D
// with its profile plane or estimated local frame and quadric type — choose the fit options (every
// method of `polarform fit`: automatic, polar profile, spherical, cylindrical), run the job's fit
// stage in the background with progress and cancel, and inspect the fitted surface (shaded,
// control net) or profile curve, the deviation colour map on the points, and the fit report;
// export the job's outputs.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "jobs/fit/fit_job.h"
#include "ui/studio/background_task.h"
#include "ui/studio/cam_scan_panel.h"
#include "ui/studio/fit_options_panel.h"
#include "ui/studio/scene_view.h"
#include "ui/studio/undo_history.h"
#include "ui/studio/workspace.h"

namespace polarform::studio {

// The fit job's first stages on an opened cloud, with what the 3D view draws of it.
struct LoadedCloud {
  FitInput input;
  std::optional<FitPreview> preview;  // with the options at opening
  std::string preview_error;          // why there is none
  SceneBounds bounds;
  PointSet display;  // relative to bounds.center()
};

struct FitRun {
  FitSettings settings;
  FitJobResult result;
  PointSet deviation;  // points coloured by signed distance
  double scale = 0.0;  // |distance| at the ends of the colour map, mm (deviation_color_limit)
};

class FitWorkspace : public Workspace {
 public:
  explicit FitWorkspace(StudioContext& context);

  WorkspaceKind kind() const override { return WorkspaceKind::fit; }
  void update() override;
  bool busy() const override { return load_task_.busy() || fit_task_.busy() || cam_scan_.busy(); }
  void draw() override;

  bool open(const std::filesystem::path& file, bool as_template) override;
  // The fit project's path; empty for a cloud opened directly, so that Save asks where (it never
  // writes over the cloud).
  std::filesystem::path document_path() const override { return project_path_; }
  std::string document_name() const override;
  bool can_save() const override { return cloud_ != nullptr; }
  // Writes a fit project: the current options and the cloud's path relative to `file`.
  bool save(const std::filesystem::path& file) override;
  // The options are the document: edited since opened or saved, and undone step by step (the
  // shown fit stays until the next fit).
  bool dirty() const override { return cloud_ && !(settings_ == saved_settings_); }
  bool can_undo() const override { return history_.can_undo(settings_); }
  bool can_redo() const override { return history_.can_redo(); }
  void undo() override { settings_ = history_.undo(settings_); }
  void redo() override { settings_ = history_.redo(settings_); }

  std::vector<ExportChoice> export_choices() const override;
  void export_to(const ExportRequest& request, const std::filesystem::path& file) override;

  void bench_step(int frame, int frames) override;
  // A coarser net (4 fewer control values each way, at least 4) and a new fit; false without a
  // cloud.
  bool scripted_edit() override;
  std::string numbers() const override;

 private:
  void start_fit();
  void draw_controls();
  void draw_frame();
  void draw_report();
  void draw_view();
  void draw_scene();
  bool planar_profile() const { return cloud_ && cloud_->preview && cloud_->preview->profile; }
  void open_recovered_design();
  void show_cloud();
  void show_fit();
  FitJobOptions job_options() const;

  BackgroundTask<LoadedCloud> load_task_;
  BackgroundTask<FitRun> fit_task_;
  std::shared_ptr<const LoadedCloud> cloud_;
  std::optional<FitRun> fit_;
  FitSettings settings_, saved_settings_;
  UndoHistory<FitSettings> history_;
  std::filesystem::path loading_;
  std::filesystem::path project_path_;
  std::string fit_error_;
  double fit_seconds_ = 0.0;
  bool fit_on_open_ = true;
  bool show_deviation_ = true;
  SceneView scene_;
  CamScanPanel cam_scan_;  // planar profiles: the scan-cam job
};

}  // namespace polarform::studio
