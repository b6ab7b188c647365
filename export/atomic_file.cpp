#include "export/atomic_file.h"

#include <fstream>
#include <locale>
#include <random>
#include <vector>

#include "src/error.h"

namespace polarform {

namespace fs = std::filesystem;

namespace {

// A hidden name beside path: ".<name><kind><random>".
fs::path beside(const fs::path& path, const char* kind) {
  std::random_device rd;
  std::string name(1, '.');
  name.append(path.filename().string()).append(kind).append(std::to_string(rd()));
  return path.parent_path() / name;
}

fs::path temporary_beside(const fs::path& path) { return beside(path, ".tmp"); }

// Writes `write`'s bytes to `file` (created or truncated); InputError naming `target` if the file
// cannot be created or written.
void write_stream(const fs::path& file, const fs::path& target,
                  const std::function<void(std::ostream&)>& write) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(target.string() + ": cannot create file");
  out.imbue(std::locale::classic());
  write(out);
  out.flush();
  if (!out) throw InputError(target.string() + ": write failed");
}

}  // namespace

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  if (path.has_parent_path() && !fs::is_directory(path.parent_path()))
    throw InputError(path.string() + ": directory " + path.parent_path().string() +
                     " does not exist");
  const fs::path tmp = temporary_beside(path);
  try {
    write_stream(tmp, path, write);
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

OutputTransaction::OutputTransaction(fs::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  made_dir_ = !fs::exists(dir_, ec);
  fs::create_directories(dir_, ec);
  if (!fs::is_directory(dir_))
    throw InputError(dir_.string() + ": cannot create the output directory" +
                     (fs::exists(dir_) ? " (a file of that name is in the way)" : ""));
}

OutputTransaction::~OutputTransaction() {
  if (!committed_) discard();
}

void OutputTransaction::add(const std::string& name, std::string_view content) {
  add(name, [content](std::ostream& out) { out << content; });
}

void OutputTransaction::add(const std::string& name,
                            const std::function<void(std::ostream&)>& write) {
  if (committed_) throw InputError((dir_ / name).string() + ": the outputs were already written");
  const fs::path target = dir_ / name;
  const fs::path tmp = temporary_beside(target);
  temporaries_[name] = tmp;
  write_stream(tmp, target, write);
}

void OutputTransaction::discard() noexcept {
  std::error_code ignored;
  for (const auto& [name, tmp] : temporaries_) fs::remove(tmp, ignored);
  temporaries_.clear();
  if (made_dir_ && fs::is_empty(dir_, ignored)) fs::remove(dir_, ignored);
}

void OutputTransaction::commit() {
  for (const auto& [name, tmp] : temporaries_) {
    const fs::path target = dir_ / name;
    std::error_code ec;
    const fs::file_status status = fs::symlink_status(target, ec);
    if (fs::exists(status) && !fs::is_regular_file(status)) {
      discard();
      throw InputError(target.string() + ": cannot replace it, it is not a regular file");
    }
  }
  // Each step done, to undo in reverse: the target renamed to a backup, the temporary to the
  // target.
  struct Step {
    fs::path target, backup;  // backup empty: there was no file to keep
  };
  std::vector<Step> done;
  try {
    for (const auto& [name, tmp] : temporaries_) {
      Step step{dir_ / name, {}};
      std::error_code ec;
      if (fs::exists(step.target)) {
        step.backup = beside(step.target, ".old");
        fs::rename(step.target, step.backup, ec);
        if (ec) throw InputError(step.target.string() + ": cannot replace file: " + ec.message());
      }
      fs::rename(tmp, step.target, ec);
      if (ec) {
        if (!step.backup.empty()) fs::rename(step.backup, step.target, ec);
        throw InputError(step.target.string() + ": cannot write file: " + ec.message());
      }
      done.push_back(std::move(step));
    }
  } catch (...) {
    std::error_code ignored;
    for (auto it = done.rbegin(); it != done.rend(); ++it) {
      fs::remove(it->target, ignored);
      if (!it->backup.empty()) fs::rename(it->backup, it->target, ignored);
    }
    discard();
    throw;
  }
  std::error_code ignored;
  for (const Step& step : done)
    if (!step.backup.empty()) fs::remove(step.backup, ignored);
  temporaries_.clear();
  committed_ = true;
}

void write_files_atomically(const fs::path& dir, const std::map<std::string, std::string>& files) {
  OutputTransaction outputs(dir);
  for (const auto& [name, text] : files) outputs.add(name, text);
  outputs.commit();
}

}  // namespace polarform
