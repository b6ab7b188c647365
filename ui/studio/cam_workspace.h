// The cam workspace, the heart of the app: the segment table, follower and cam settings and the
// conversion settings on the left; live SVAJ and pressure-angle plots, the profile view with the
// follower, and the conversion result with its measured error on the right. Every edit runs the
// cam job's stages again at once (the design is small): design and analyses, then the conversion;
// undo/redo, save and export (the job's output bundle) work on the project.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "jobs/cam/cam_job.h"
#include "jobs/project/cam_project.h"
#include "ui/studio/cam_settings_panel.h"
#include "ui/studio/cam_view_settings.h"
#include "ui/studio/conversion_panel.h"
#include "ui/studio/dynamics_panel.h"
#include "ui/studio/profile_view.h"
#include "ui/studio/project_document.h"
#include "ui/studio/segment_table.h"
#include "ui/studio/svaj_panel.h"
#include "ui/studio/workspace.h"

namespace polarform::studio {

class CamWorkspace : public Workspace {
 public:
  explicit CamWorkspace(StudioContext& context);

  WorkspaceKind kind() const override { return WorkspaceKind::cam; }
  void update() override;
  void draw() override;

  bool open(const std::filesystem::path& file, bool as_template) override;
  std::string template_folder() const override { return "cams"; }
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
  // The whole benchmark edit at once: the end of the first segment moves back over half of it.
  bool scripted_edit() override {
    bench_step(0, 1);
    return true;
  }
  std::string numbers() const override;
  double last_compute_ms() const override { return compute_ms_; }

  // The project being edited (the study workspace sweeps its conversion).
  const CamProject& current() const { return document_.current(); }
  bool has_document() const { return has_document_; }

 private:
  static CamJobOptions live_options();
  void recompute();
  void draw_editor();
  void draw_plots();
  void draw_profile_and_conversion();
  void draw_banner();

  ProjectDocument<CamProject> document_;
  bool has_document_ = false;
  std::optional<CamProject> computed_;  // the input of the stages / the last attempt
  // The cam job's stages of the last valid design (design and analyses) and conversion.
  std::optional<CamDesignStage> design_;
  std::optional<CamAnalysisStage> analysis_;
  std::optional<CamConversionStage> conversion_;
  std::uint64_t revision_ = 0;  // counts the recomputed stages (the figures follow it)
  std::string design_error_, conversion_error_;
  bool design_stale_ = false, conversion_stale_ = false;
  double compute_ms_ = 0.0;
  double animation_clock_ = -1.0;
  SegmentTable segment_table_;
  CamSettingsPanel settings_panel_;
  ConversionPanel conversion_panel_;
  SvajPanel svaj_;
  DynamicsPlots dynamics_;
  ProfileView profile_;
  CamViewSettings view_;
  double bench_boundary_ = 0.0;
};

}  // namespace polarform::studio
