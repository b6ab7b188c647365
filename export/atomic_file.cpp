#include "export/atomic_file.h"

#include <fstream>
#include <locale>
#include <random>

#include "src/error.h"

namespace polarform {

namespace fs = std::filesystem;

namespace {

fs::path temporary_beside(const fs::path& path) {
  std::random_device rd;
  std::string name(1, '.');
  name.append(path.filename().string()).append(".tmp").append(std::to_string(rd()));
  return path.parent_path() / name;
}

}  // namespace

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  if (path.has_parent_path() && !fs::is_directory(path.parent_path()))
    throw InputError(path.string() + ": directory " + path.parent_path().string() +
                     " does not exist");
  const fs::path tmp = temporary_beside(path);
  try {
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) throw InputError(path.string() + ": cannot create file");
      out.imbue(std::locale::classic());
      write(out);
      out.flush();
      if (!out) throw InputError(path.string() + ": write failed");
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) throw InputError(path.string() + ": cannot replace file: " + ec.message());
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
}

void write_file_atomically(const fs::path& path, std::string_view content) {
  write_file_atomically(path, [&](std::ostream& out) { out << content; });
}

void write_files_atomically(const fs::path& dir, const std::map<std::string, std::string>& files) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir)) throw InputError(dir.string() + ": cannot create the output directory");
  for (const auto& [name, text] : files) write_file_atomically(dir / name, text);
}

}  // namespace polarform
