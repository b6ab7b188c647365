#include "export/svg_writer.h"

#include "export/xml_escape.h"
#include "src/number_text.h"

namespace polarform {

SvgWriter& SvgWriter::begin(std::string_view name) {
  out_.append("<").append(name);
  pending_ = name;
  return *this;
}

SvgWriter& SvgWriter::attr(std::string_view name, std::string_view value) {
  out_.append(" ").append(name).append("=\"").append(xml_escape(value)).append("\"");
  return *this;
}

SvgWriter& SvgWriter::attr(std::string_view name, double pixels) {
  return attr(name, svg_number(pixels));
}

void SvgWriter::empty() { out_.append("/>\n"); }

void SvgWriter::text(std::string_view content) {
  out_.append(">").append(xml_escape(content)).append("</").append(pending_).append(">\n");
}

void SvgWriter::open() {
  out_.append(">\n");
  open_elements_.push_back(pending_);
}

void SvgWriter::close() {
  out_.append("</").append(open_elements_.back()).append(">\n");
  open_elements_.pop_back();
}

std::string svg_number(double pixels) { return format_trimmed(pixels, 2); }

}  // namespace polarform
