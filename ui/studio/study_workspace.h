// The study workspace: a tolerance sweep over the cam workspace's current design (the study
// job of jobs/study: quasi-uniform quartic base, RQB base, cubic through sampled points, the
// compacted exact form and the degree-3 profile against Open CASCADE's fits) run in the
// background with progress and cancel, shown as control points and arcs against the tolerance,
// and the max angle deviation of a base arc against its angle (Bae 2002, Fig. 5.4); the study
// files (CSV, SVG, report.json) can be exported into a folder.
#pragma once

#include <optional>
#include <string>

#include "jobs/study/study_job.h"
#include "ui/studio/background_task.h"
#include "ui/studio/cam_workspace.h"
#include "ui/studio/plot_canvas.h"
#include "ui/studio/workspace.h"

namespace polarform::studio {

struct StudySettings {
  double loosest = 1e-2, tightest = 1e-6;  // mm
  int per_decade = 2;
  bool peers = true;  // the peers' fits (Open CASCADE's, SISL's) beside ours, where available
  bool operator==(const StudySettings&) const = default;
};

class StudyWorkspace : public Workspace {
 public:
  StudyWorkspace(StudioContext& context, const CamWorkspace& cam);

  WorkspaceKind kind() const override { return WorkspaceKind::study; }
  void update() override;
  bool busy() const override { return task_.busy(); }
  void draw() override;
  std::string document_name() const override { return cam_.document_name(); }

  std::vector<ExportChoice> export_choices() const override;
  void export_to(const ExportRequest& request, const std::filesystem::path& folder) override;

  std::string numbers() const override;

 private:
  void start();
  void draw_controls();
  void draw_table();
  void draw_peer_table();
  void draw_plots(ImVec2 size);

  const CamWorkspace& cam_;
  BackgroundTask<StudyJobResult> task_;
  StudySettings settings_;
  bool requested_ = false;           // the first run starts when the workspace is shown
  std::optional<CamProject> input_;  // the design of the running or last study
  std::optional<StudyJobResult> result_;
  std::optional<CamProject> result_input_;
  std::string error_;
  std::optional<std::pair<Figure, Figure>> figures_;  // the job's study and deviation figures
  FigureView views_[2];
};

}  // namespace polarform::studio
