// Screenshots: the back buffer read with glReadPixels after the frame is rendered, flipped to
// top-down rows and written as an RGB PNG with stb_image_write (the one translation unit that
// compiles its implementation).
#pragma once

#include <filesystem>

namespace polarform::studio {

// Reads width x height pixels of the current framebuffer and writes them to `file` (atomically).
// Throws std::runtime_error naming the file when it cannot be written.
void capture_png(const std::filesystem::path& file, int width, int height);

}  // namespace polarform::studio
