#include "ui/studio/png_capture.h"

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "export/atomic_file.h"
#include "ui/studio/gl_api.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb_image_write.h>

namespace polarform::studio {
namespace {

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::string*>(context);
  out->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

void capture_png(const std::filesystem::path& file, int width, int height) {
  if (width <= 0 || height <= 0) throw std::runtime_error("screenshot: empty framebuffer");
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  const std::size_t row = static_cast<std::size_t>(width) * 3;
  std::vector<unsigned char> line(row);
  for (int y = 0; y < height / 2; ++y) {  // OpenGL rows run bottom-up
    unsigned char* a = pixels.data() + y * row;
    unsigned char* b = pixels.data() + (height - 1 - y) * row;
    std::memcpy(line.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, line.data(), row);
  }
  std::string png;
  if (!stbi_write_png_to_func(append_bytes, &png, width, height, 3, pixels.data(),
                              static_cast<int>(row)))
    throw std::runtime_error("screenshot: cannot encode " + file.string());
  write_file_atomically(file, png);
}

}  // namespace polarform::studio
