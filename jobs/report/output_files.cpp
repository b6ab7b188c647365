#include "jobs/report/output_files.h"

#include <algorithm>

#include "jobs/report/report_number.h"

namespace polarform {

std::vector<std::string> report_file_list(const std::map<std::string, std::string>& content,
                                          const std::vector<std::string>& reports) {
  std::vector<std::string> files;
  for (const auto& [name, text] : content)
    if (std::find(reports.begin(), reports.end(), name) == reports.end()) files.push_back(name);
  files.insert(files.end(), reports.begin(), reports.end());
  return files;
}

std::string report_json_text(const nlohmann::ordered_json& report) {
  return rounded_for_report(report).dump(2, ' ', false,
                                         nlohmann::ordered_json::error_handler_t::replace) +
         "\n";
}

}  // namespace polarform
