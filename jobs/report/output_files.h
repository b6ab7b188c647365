// The files of a job's output bundle as its report lists them — every rendered file by name, then
// the reports themselves (report.json, report.html), which are rendered last because they list
// the others — and report.json's text.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace polarform {

// The names of `content` other than the reports, in order, followed by `reports`.
std::vector<std::string> report_file_list(const std::map<std::string, std::string>& content,
                                          const std::vector<std::string>& reports = {
                                              "report.json", "report.html"});

// report.json's text: two-space indents and a final newline, numbers to 12 significant digits
// (report_number.h); bytes of the input that are not UTF-8 (a Latin-1 name in a project file)
// are written as U+FFFD instead of failing the run.
std::string report_json_text(const nlohmann::ordered_json& report);

}  // namespace polarform
