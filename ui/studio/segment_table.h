// The cam's segment table: one row per dwell / rise / return with its kind, motion law, start and
// end angles (degrees; editing an end moves the shared boundary) and lift; buttons to add, delete
// and reorder; and, for the selected segment, its name and the endpoint constraints of polynomial
// and B-spline laws. Edits the segment list in place and reports whether it changed; an edit
// that cannot be made goes to the log.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "designers/cam/motion_segment.h"
#include "ui/studio/message_log.h"

namespace polarform::studio {

class SegmentTable {
 public:
  // `unit`: of the lifts and endpoint derivatives, "mm" or "°" (an oscillating follower's swing).
  bool draw(std::vector<SegmentSpec>& segments, MessageLog& log, std::string_view unit = "mm");
  int selected() const { return selected_; }
  void select(int index) { selected_ = index; }

 private:
  bool draw_row(std::vector<SegmentSpec>& segments, int i);
  bool draw_buttons(std::vector<SegmentSpec>& segments, MessageLog& log);
  bool draw_details(SegmentSpec& segment);

  int selected_ = 0;
  std::string unit_ = "mm";
};

}  // namespace polarform::studio
