// Atomic file output: content is written to a temporary file beside the target and renamed into
// place only when complete, so a failure never leaves a half-written file or loses the old one.
// Streams use the classic "C" locale, so numbers are locale-independent.
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

// A job's outputs: creates dir if missing (InputError if it cannot), then writes every
// file name → content atomically into it.
void write_files_atomically(const std::filesystem::path& dir,
                            const std::map<std::string, std::string>& files);

}  // namespace polarform
