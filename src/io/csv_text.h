// Delimited text shared by the small CSV readers (boundary, spine, viz grid): the whole file read
// into memory with a clear error, and its data lines — the UTF-8 BOM skipped, '#' comments and
// blank lines dropped, fields split at commas and trimmed — each with "name:line: " for messages.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace polarform {

// Throws InputError "file: cannot open file".
std::string read_text_file(const std::filesystem::path& file);

// The comma-separated fields of a line, blanks around them trimmed.
std::vector<std::string_view> comma_fields(std::string_view line);

// Calls on_line(line, where) for every line with data (comment stripped, trimmed).
void for_each_data_line(std::string_view text, const std::string& name,
                        const std::function<void(std::string_view line, const std::string& where)>&
                            on_line);

}  // namespace polarform
