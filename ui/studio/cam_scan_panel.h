// Scanned cams in the fit workspace: a planar profile scan of a plate cam read as `polarform
// scan-cam` reads it — the follower that reads the motion (kind, roller radius, rotation), the
// scan-cam job run in the background, and its results: the annotated SVAJ figure (recovered rises
// and returns shaded with their laws, unresolved derivatives marked), the recovered design's
// segments with their uncertainties, the motion's resolution and the re-designed cam's deviation
// from the scan. The design is exported, or opened in the cam workspace, as the project
// `--write-project` writes.
#pragma once

#include <imgui.h>

#include <filesystem>
#include <optional>
#include <string>

#include "jobs/scan_cam/scan_cam_job.h"
#include "ui/studio/background_task.h"
#include "ui/studio/message_log.h"
#include "ui/studio/plot_canvas.h"

namespace polarform::studio {

class CamScanPanel {
 public:
  // The follower controls and the "Recover the cam design" button for `scan`.
  void draw_controls(const std::filesystem::path& scan);
  // Collects the finished job (errors to the log).
  void update(MessageLog& log);
  bool busy() const { return task_.busy(); }
  // The result for the current follower settings, if computed.
  const ScanCamJobResult* result() const { return result_ ? &*result_ : nullptr; }
  // Runs the job now (scripts and exports) unless its result is there; throws what it throws.
  const ScanCamJobResult& ensure(const std::filesystem::path& scan);
  // The annotated SVAJ figure and the recovered design.
  void draw_result(ImVec2 size);
  // Forgets the result (a new cloud).
  void reset();

 private:
  ScanCamJobOptions options() const;
  void start(const std::filesystem::path& scan);

  int follower_ = 0;  // knife-edge, roller, flat-faced
  double roller_radius_ = 10.0;
  bool clockwise_ = false;
  BackgroundTask<ScanCamJobResult> task_;
  std::optional<ScanCamJobResult> result_;
  std::optional<Figure> figure_;
  FigureView view_;
};

}  // namespace polarform::studio
