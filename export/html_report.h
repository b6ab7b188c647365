// A self-contained HTML report (report.html): one file with inline CSS and inline SVG figures,
// built from headings, paragraphs, key figures, tables and plots (export/svg_plot). All text is
// escaped; the markup is also well-formed XML, so the result can be checked by an XML parser.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace polarform {

class HtmlReport {
 public:
  // title: the page title and its top heading; must not be empty.
  explicit HtmlReport(std::string title);

  // A section heading; level 2..4 (level 1 is the report title).
  void add_heading(const std::string& text, int level = 2);
  void add_paragraph(const std::string& text);
  // Prominent label/value pairs, e.g. {"max radial error", "3.1e-4 mm"}.
  void add_key_figures(const std::vector<std::pair<std::string, std::string>>& figures);
  // A table; every row has one cell per header. Cells that are numbers are right-aligned.
  void add_table(const std::vector<std::string>& headers,
                 const std::vector<std::vector<std::string>>& rows);
  // An SVG document (e.g. Figure::svg()) inline, numbered and captioned "Figure n. caption".
  // Throws InputError if svg_text is not a well-formed document with an <svg> root.
  void add_svg(const std::string& svg_text, const std::string& caption);
  // A "Files" heading and the run's output files, comma-separated.
  void add_file_list(const std::vector<std::string>& files);

  std::string html() const;
  // Writes html() to path atomically.
  void save(const std::filesystem::path& path) const;

 private:
  std::string title_;
  std::string body_;
  int figures_ = 0;
};

}  // namespace polarform
