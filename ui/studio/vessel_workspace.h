// The vessel workspace: edit a pressure-vessel design (settings, preset, curvature targets, end
// conditions), see the vessel job's stages re-run in the background after every edit — the NLopt
// synthesis with its residuals, then the conversion and the revolved surfaces — with the job's
// meridian, curvature and stress figures and the revolved NURBS vessel in 3D; save the project
// and export the job's outputs.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "jobs/project/vessel_project.h"
#include "jobs/vessel/vessel_job.h"
#include "ui/studio/background_task.h"
#include "ui/studio/curvature_table.h"
#include "ui/studio/plot_canvas.h"
#include "ui/studio/project_document.h"
#include "ui/studio/scene_view.h"
#include "ui/studio/vessel_design_panel.h"
#include "ui/studio/workspace.h"

namespace polarform::studio {

// What a background run of the vessel job's stages hands the workspace: the solve, its conversion
// (or why there is none, so the solve still shows), the report's fields and the job's figures.
struct VesselRun {
  VesselSolveStage solved;
  std::optional<VesselConversionStage> converted;
  std::string conversion_error;
  nlohmann::ordered_json fields;  // vessel_report_fields of the stages
  Figure meridian, curvature, stresses;
  std::optional<Figure> same_depth;  // a minimum-stress head beside the standard heads of its depth
};

class VesselWorkspace : public Workspace {
 public:
  explicit VesselWorkspace(StudioContext& context);

  WorkspaceKind kind() const override { return WorkspaceKind::vessel; }
  void update() override;
  bool busy() const override { return task_.busy(); }
  void draw() override;

  bool accepts(const std::filesystem::path& file) const override;
  bool open(const std::filesystem::path& file, bool as_template) override;
  std::string template_folder() const override { return "vessels"; }
  bool can_save() const override { return has_document_; }
  bool save(const std::filesystem::path& file) override;
  std::filesystem::path document_path() const override { return document_.path(); }
  std::string document_name() const override { return document_.name(); }
  bool dirty() const override { return document_.dirty(); }
  bool can_undo() const override { return document_.can_undo(); }
  bool can_redo() const override { return document_.can_redo(); }
  void undo() override { document_.undo(); }
  void redo() override { document_.redo(); }

  std::vector<ExportChoice> export_choices() const override;
  void export_to(const ExportRequest& request, const std::filesystem::path& file) override;

  void bench_step(int frame, int frames) override;
  // The whole benchmark edit at once: the pressure rises by 50 %.
  bool scripted_edit() override {
    bench_step(0, 1);
    return true;
  }
  std::string numbers() const override;

 private:
  void draw_editor();
  void draw_summary();
  void draw_views();
  void rebuild_scene();

  ProjectDocument<VesselProject> document_;
  BackgroundTask<VesselRun> task_;
  std::optional<VesselProject> requested_;  // the input of the running or last solve
  std::optional<VesselRun> results_;        // the last successful solve
  std::string error_;                       // why the latest input could not be solved
  double solve_seconds_ = 0.0;
  double bench_pressure_ = 0.0;
  VesselDesignPanel design_panel_;
  CurvatureTable curvature_table_;
  FigureView meridian_view_, curvature_view_, stress_view_, same_depth_view_;
  bool show_same_depth_ = true;  // a minimum-stress head: the comparison in the stresses cell
  SceneView scene_;
  bool scene_dirty_ = false;
  bool has_document_ = false;
};

}  // namespace polarform::studio
