// The fit workspace's options panel: draws FitSettings (ui/studio/fit_settings.h) with ImGui.
#pragma once

#include "ui/studio/fit_settings.h"

namespace polarform::studio {

// Draws the options; true when one changed.
bool draw_fit_options(FitSettings& settings);

}  // namespace polarform::studio
