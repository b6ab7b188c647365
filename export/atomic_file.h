// Atomic file output: content is written to a temporary file beside the target and renamed into
// place only when complete, so a failure never leaves a half-written file or loses the old one.
// A job's outputs are one transaction: all of them written first, then all renamed into place,
// and on any failure the folder restored as it was. Streams use the classic "C" locale, so
// numbers are locale-independent.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <string_view>

namespace polarform {

// Calls write(stream) on a temporary file, then renames it to path. If write throws or the stream
// fails, the temporary is removed, path is untouched and an InputError names the path.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

// Same, for content already in memory.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

// The outputs of a job as one transaction. The constructor creates dir if missing (InputError if
// it cannot); add writes each file to a temporary beside its target (InputError naming the file
// if it cannot, the disk full included); commit checks that nothing but a regular file stands at
// a target, then renames every file into place, keeping each file it replaces until all are in.
// If any step fails, every new file is removed and every replaced one restored: the folder is as
// before (and removed again if the transaction made it and it is empty). Without commit, the
// destructor removes the temporaries.
class OutputTransaction {
 public:
  explicit OutputTransaction(std::filesystem::path dir);
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  void add(const std::string& name, std::string_view content);
  void add(const std::string& name, const std::function<void(std::ostream&)>& write);
  void commit();

 private:
  void discard() noexcept;

  std::filesystem::path dir_;
  bool made_dir_ = false;
  bool committed_ = false;
  std::map<std::string, std::filesystem::path> temporaries_;  // file name → its temporary
};

// A job's outputs, file name → content, as one OutputTransaction.
void write_files_atomically(const std::filesystem::path& dir,
                            const std::map<std::string, std::string>& files);

}  // namespace polarform
