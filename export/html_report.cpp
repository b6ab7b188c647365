#include "export/html_report.h"

#include <tinyxml2.h>

#include <charconv>

#include "export/atomic_file.h"
#include "export/xml_escape.h"
#include "src/error.h"

namespace polarform {

namespace {

// Kept free of '<' and '&' so that the page stays well-formed XML.
constexpr const char* kStyle = R"(
body { margin: 0; background: #f6f7f9; color: #1f2328; font: 15px/1.5 system-ui, -apple-system,
  "Segoe UI", "DejaVu Sans", Helvetica, Arial, sans-serif; }
main { max-width: 920px; margin: 0 auto; padding: 24px 32px 48px; background: white; }
h1 { font-size: 26px; margin: 8px 0 16px; border-bottom: 2px solid #0072B2; padding-bottom: 6px; }
h2 { font-size: 20px; margin: 28px 0 10px; }
h3 { font-size: 17px; margin: 22px 0 8px; }
h4 { font-size: 15px; margin: 18px 0 6px; }
dl.key-figures { display: flex; flex-wrap: wrap; gap: 12px; margin: 12px 0; }
dl.key-figures div { border: 1px solid #d8dce1; border-radius: 6px; padding: 8px 14px;
  min-width: 150px; }
dl.key-figures dt { font-size: 13px; color: #57606a; }
dl.key-figures dd { margin: 2px 0 0; font-size: 19px; font-weight: 600;
  font-variant-numeric: tabular-nums; }
table { border-collapse: collapse; margin: 12px 0; font-variant-numeric: tabular-nums; }
th, td { padding: 4px 12px; border-bottom: 1px solid #e1e4e8; text-align: left; }
th { border-bottom: 2px solid #8c959f; font-weight: 600; }
td.num { text-align: right; }
figure { margin: 20px 0; }
figure svg { display: block; max-width: 100%; height: auto; }
figcaption { font-size: 14px; color: #57606a; margin-top: 6px; }
@media print { body { background: white; } main { padding: 0; } figure { break-inside: avoid; } }
)";

bool is_number(const std::string& text) {
  double value = 0;
  const char* begin = text.data() + (!text.empty() && text.front() == '+');
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(begin, end, value);
  return !text.empty() && result.ec == std::errc() && result.ptr == end;
}

}  // namespace

HtmlReport::HtmlReport(std::string title) : title_(std::move(title)) {
  if (title_.empty()) throw InputError("HtmlReport: title must not be empty");
}

void HtmlReport::add_heading(const std::string& text, int level) {
  if (level < 2 || level > 4)
    throw InputError("HtmlReport::add_heading: level must be 2, 3 or 4, got " +
                     std::to_string(level));
  const std::string tag = "h" + std::to_string(level);
  body_ += "<" + tag + ">" + xml_escape(text) + "</" + tag + ">\n";
}

void HtmlReport::add_paragraph(const std::string& text) {
  body_ += "<p>" + xml_escape(text) + "</p>\n";
}

void HtmlReport::add_key_figures(const std::vector<std::pair<std::string, std::string>>& figures) {
  if (figures.empty()) throw InputError("HtmlReport::add_key_figures: figures must not be empty");
  body_ += "<dl class=\"key-figures\">\n";
  for (const auto& [label, value] : figures)
    body_ += "<div><dt>" + xml_escape(label) + "</dt><dd>" + xml_escape(value) + "</dd></div>\n";
  body_ += "</dl>\n";
}

void HtmlReport::add_table(const std::vector<std::string>& headers,
                           const std::vector<std::vector<std::string>>& rows) {
  if (headers.empty()) throw InputError("HtmlReport::add_table: headers must not be empty");
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (rows[r].size() != headers.size())
      throw InputError("HtmlReport::add_table: row " + std::to_string(r + 1) + " has " +
                       std::to_string(rows[r].size()) + " cells; expected " +
                       std::to_string(headers.size()) + ", one per header");
  body_ += "<table>\n<thead><tr>";
  for (const std::string& h : headers) body_ += "<th>" + xml_escape(h) + "</th>";
  body_ += "</tr></thead>\n<tbody>\n";
  for (const std::vector<std::string>& row : rows) {
    body_ += "<tr>";
    for (const std::string& cell : row)
      body_ += (is_number(cell) ? "<td class=\"num\">" : "<td>") + xml_escape(cell) + "</td>";
    body_ += "</tr>\n";
  }
  body_ += "</tbody>\n</table>\n";
}

void HtmlReport::add_svg(const std::string& svg_text, const std::string& caption) {
  const std::size_t start = svg_text.find("<svg");
  tinyxml2::XMLDocument doc;
  const bool ok =
      start != std::string::npos &&
      doc.Parse(svg_text.c_str() + start, svg_text.size() - start) == tinyxml2::XML_SUCCESS &&
      doc.RootElement() != nullptr && std::string(doc.RootElement()->Name()) == "svg";
  if (!ok)
    throw InputError(
        "HtmlReport::add_svg: svg_text must be a well-formed SVG document with an "
        "<svg> root element");
  ++figures_;
  body_ += "<figure>\n" + svg_text.substr(start);
  if (body_.back() != '\n') body_ += "\n";
  body_ += "<figcaption>Figure " + std::to_string(figures_) + "." +
           (caption.empty() ? "" : " " + xml_escape(caption)) + "</figcaption>\n</figure>\n";
}

std::string HtmlReport::html() const {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n<title>" +
         xml_escape(title_) + "</title>\n<style>" + kStyle +
         "</style>\n</head>\n<body>\n<main>\n<h1>" + xml_escape(title_) + "</h1>\n" + body_ +
         "</main>\n</body>\n</html>\n";
}

void HtmlReport::save(const std::filesystem::path& path) const {
  write_file_atomically(path, html());
}

void HtmlReport::add_file_list(const std::vector<std::string>& files) {
  add_heading("Files");
  std::string list;
  for (const std::string& f : files) list += (list.empty() ? "" : ", ") + f;
  add_paragraph(list);
}

}  // namespace polarform
