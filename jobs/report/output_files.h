// The files of a job's output bundle as its report lists them: every rendered file by name, then
// the reports themselves (report.json, report.html), which are rendered last because they list
// the others.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace polarform {

// The names of `content` other than the reports, in order, followed by `reports`.
std::vector<std::string> report_file_list(const std::map<std::string, std::string>& content,
                                          const std::vector<std::string>& reports = {
                                              "report.json", "report.html"});

}  // namespace polarform
