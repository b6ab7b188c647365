#include "export/step_file.h"

#include <cmath>
#include <cstdio>

#include "export/exchange_text.h"
#include "polarform_version.h"
#include "src/error.h"

namespace polarform {

int StepFile::add(std::string record) {
  records_.push_back(std::move(record));
  return static_cast<int>(records_.size());
}

std::string StepFile::str(const StepHeader& header) const {
  if (!(header.resolution > 0.0) || !std::isfinite(header.resolution))
    throw InputError("STEP header resolution " + std::to_string(header.resolution) +
                     ": expected a finite length > 0 mm");
  const std::string stamp =
      header.time_stamp.empty() ? utc_time_stamp("%Y-%m-%dT%H:%M:%SZ") : header.time_stamp;
  const std::string system = std::string("polarform ") + POLARFORM_VERSION;
  const std::string name = header.file_name.empty() ? "polarform.stp" : header.file_name;
  std::string out = "ISO-10303-21;\nHEADER;\n";
  // ISO 10303-21 header: the three mandatory entities.
  out += "FILE_DESCRIPTION((" + step_string(header.description, "description") + "),'2;1');\n";
  out += "FILE_NAME(" + step_string(name, "file_name") + "," + step_string(stamp, "time_stamp") +
         ",(" + step_string(header.author, "author") + "),(" +
         step_string(header.organization, "organization") + ")," +
         step_string(system, "preprocessor") + "," + step_string(system, "originating system") +
         ",'');\n";
  out += "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n";
  for (std::size_t i = 0; i < records_.size(); ++i)
    out += "#" + std::to_string(i + 1) + "=" + records_[i] + ";\n";
  out += "ENDSEC;\nEND-ISO-10303-21;\n";
  return out;
}

std::string step_string(std::string_view utf8, std::string_view field) {
  auto bad = [&]() {
    return InputError("STEP " + std::string(field) + " '" + std::string(utf8) +
                      "': invalid UTF-8");
  };
  std::string out = "'";
  std::string pending;  // \X2\ run of UTF-16 code units
  auto flush = [&]() {
    if (!pending.empty()) out += "\\X2\\" + pending + "\\X0\\";
    pending.clear();
  };
  for (std::size_t i = 0; i < utf8.size();) {
    const unsigned char c = utf8[i];
    if (c >= 0x20 && c < 0x7F) {
      flush();
      if (c == '\'') out += "''";
      else if (c == '\\') out += "\\\\";
      else out += static_cast<char>(c);
      ++i;
      continue;
    }
    int len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (len == 0 || i + len > utf8.size()) throw bad();
    char32_t cp = len == 1 ? c : c & (0x7F >> len);
    for (int k = 1; k < len; ++k) {
      const unsigned char cc = utf8[i + k];
      if ((cc >> 6) != 0x2) throw bad();
      cp = (cp << 6) | (cc & 0x3F);
    }
    i += len;
    char buf[16];
    if (cp > 0xFFFF) {  // ISO 10303-21: \X4\ for code points beyond the BMP
      flush();
      std::snprintf(buf, sizeof buf, "%08X", static_cast<unsigned>(cp));
      out += std::string("\\X4\\") + buf + "\\X0\\";
    } else {
      std::snprintf(buf, sizeof buf, "%04X", static_cast<unsigned>(cp));
      pending += buf;
    }
  }
  flush();
  return out + "'";
}

std::string step_real(double x) { return exchange_real(x, 'E'); }

std::string step_list(const std::vector<std::string>& items) {
  std::string out = "(";
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? "," : "") + items[i];
  return out + ")";
}

}  // namespace polarform
