#include "jobs/project/xml_reader.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "src/error.h"

namespace polarform {

namespace {

// What tinyxml2's error means, in words a user can act on.
std::string describe(tinyxml2::XMLError error) {
  switch (error) {
    case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT:
      return "an element is not closed properly (a closing tag is missing or misspelt)";
    case tinyxml2::XML_ERROR_PARSING_ELEMENT:
      return "cannot parse an element (a tag is not closed with '>', or a '<' stands in text: "
             "write &lt;)";
    case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE:
      return "cannot parse an attribute (write name=\"value\" with quotes, each name once)";
    case tinyxml2::XML_ERROR_PARSING_TEXT:
      return "text outside the elements (the file must start with '<')";
    case tinyxml2::XML_ERROR_PARSING_CDATA:
      return "a <![CDATA[ section without its ]]>";
    case tinyxml2::XML_ERROR_PARSING_COMMENT:
      return "a comment <!-- without its -->";
    case tinyxml2::XML_ERROR_PARSING_DECLARATION:
      return "a declaration <?…?> that is not closed";
    case tinyxml2::XML_ERROR_PARSING_UNKNOWN:
      return "a <!…> markup that is not closed";
    case tinyxml2::XML_ERROR_PARSING:
      return "unrecognised markup (an element name must start with a letter or '_'; no <!DOCTYPE> "
             "inside an element)";
    case tinyxml2::XML_ERROR_EMPTY_DOCUMENT: return "the document is empty";
    case tinyxml2::XML_ERROR_FILE_NOT_FOUND:
    case tinyxml2::XML_ERROR_FILE_COULD_NOT_BE_OPENED: return "cannot open the file";
    case tinyxml2::XML_ERROR_FILE_READ_ERROR:
      return "cannot read the file";
    case tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED:
      return "elements nested deeper than " + std::to_string(TINYXML2_MAX_ELEMENT_DEPTH) +
             " levels";
    default: return tinyxml2::XMLDocument::ErrorIDToName(error);
  }
}

void check_parsed(const tinyxml2::XMLDocument& doc, const std::string& file) {
  if (doc.Error())
    throw InputError(file +
                     (doc.ErrorLineNum() > 0 ? ":" + std::to_string(doc.ErrorLineNum()) : "") +
                     ": malformed XML: " + describe(doc.ErrorID()));
  if (!doc.RootElement()) throw InputError(file + ": no root element");
}

std::optional<double> parse_number(const char* s) {
  while (*s == ' ') ++s;
  const char* end = s + std::char_traits<char>::length(s);
  while (end > s && end[-1] == ' ') --end;
  if (*s == '+') ++s;
  double value;
  const auto [ptr, ec] = std::from_chars(s, end, value);
  if (ec != std::errc() || ptr != end || s == end || !std::isfinite(value)) return std::nullopt;
  return value;
}

// "1,2.5,3" as numbers; nullopt when an item is not a finite number.
std::optional<std::vector<double>> split_numbers(const char* text) {
  std::vector<double> out;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ',');) {
    const auto x = parse_number(item.c_str());
    if (!x) return std::nullopt;
    out.push_back(*x);
  }
  return out;
}

// "a, b, c".
std::string joined(const std::set<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

XmlDocument::XmlDocument(const std::filesystem::path& file)
    : doc_(std::make_unique<tinyxml2::XMLDocument>()), file_(file.string()) {
  if (!std::filesystem::exists(file)) throw InputError(file_ + ": no such file");
  doc_->LoadFile(file_.c_str());
  check_parsed(*doc_, file_);
}

XmlDocument::XmlDocument(const std::string& text, std::string file)
    : doc_(std::make_unique<tinyxml2::XMLDocument>()), file_(std::move(file)) {
  doc_->Parse(text.c_str(), text.size());
  check_parsed(*doc_, file_);
}

XmlElementReader::XmlElementReader(const tinyxml2::XMLElement* element, std::string file)
    : e_(element), file_(std::move(file)) {}

std::string XmlElementReader::where() const {
  return file_ + ":" + std::to_string(e_->GetLineNum()) + ": <" + e_->Name() + ">";
}

bool XmlElementReader::has(const char* name) const {
  read_attributes_.insert(name);
  const char* v = e_->Attribute(name);
  return v && *v;
}

const char* XmlElementReader::raw(const char* name) const {
  read_attributes_.insert(name);
  const char* v = e_->Attribute(name);
  return v && *v ? v : nullptr;
}

void XmlElementReader::fail(const char* attribute, const std::string& expected) const {
  std::string msg = where() + " attribute '" + attribute + "': expected " + expected;
  if (const char* v = e_->Attribute(attribute)) msg += ", got '" + std::string(v) + "'";
  throw InputError(msg);
}

double XmlElementReader::number(const char* name) const {
  const char* v = raw(name);
  if (!v) fail(name, "a number (attribute is missing)");
  const auto x = parse_number(v);
  if (!x) fail(name, "a finite number");
  return *x;
}

double XmlElementReader::number(const char* name, double fallback) const {
  return raw(name) ? number(name) : fallback;
}

std::optional<double> XmlElementReader::optional_number(const char* name) const {
  if (!raw(name)) return std::nullopt;
  return number(name);
}

double XmlElementReader::positive(const char* name, bool allow_zero) const {
  const double x = number(name);
  if (allow_zero ? x < 0 : x <= 0) fail(name, allow_zero ? "a number >= 0" : "a number > 0");
  return x;
}

double XmlElementReader::positive(const char* name, double fallback, bool allow_zero) const {
  return raw(name) ? positive(name, allow_zero) : fallback;
}

int XmlElementReader::integer(const char* name, int fallback) const {
  if (!raw(name)) return fallback;
  const double x = number(name);
  if (x != std::floor(x) || std::abs(x) > 1e9) fail(name, "an integer");
  return static_cast<int>(x);
}

std::string XmlElementReader::choice(const char* name,
                                     std::initializer_list<const char*> allowed) const {
  const char* v = raw(name);
  std::string options;
  for (const char* a : allowed) {
    if (v && std::string(v) == a) return v;
    options += (options.empty() ? "" : "|") + std::string(a);
  }
  fail(name, "one of " + options + (v ? "" : " (attribute is missing)"));
}

std::string XmlElementReader::choice(const char* name, std::initializer_list<const char*> allowed,
                                     const char* fallback) const {
  return raw(name) ? choice(name, allowed) : fallback;
}

std::string XmlElementReader::text(const char* name, const char* fallback) const {
  const char* v = raw(name);
  return v ? v : fallback;
}

std::vector<double> XmlElementReader::number_list(const char* name) const {
  const char* v = raw(name);
  if (!v) fail(name, "comma-separated numbers (attribute is missing)");
  const auto out = split_numbers(v);
  if (!out || out->empty()) fail(name, "comma-separated numbers");
  return *out;
}

std::vector<double> XmlElementReader::numbers(const char* name, std::size_t count) const {
  const char* v = raw(name);
  if (!v) fail(name, std::to_string(count) + " comma-separated numbers (attribute is missing)");
  const auto out = split_numbers(v);
  if (!out || out->size() != count) fail(name, std::to_string(count) + " comma-separated numbers");
  return *out;
}

std::vector<const tinyxml2::XMLElement*> XmlElementReader::children(const char* name) const {
  asked_children_.insert(name);
  std::vector<const tinyxml2::XMLElement*> out;
  for (auto* c = e_->FirstChildElement(name); c; c = c->NextSiblingElement(name)) {
    read_children_.insert(c);
    out.push_back(c);
  }
  return out;
}

const tinyxml2::XMLElement* XmlElementReader::child(const char* name) const {
  asked_children_.insert(name);
  const auto* c = e_->FirstChildElement(name);
  if (c) read_children_.insert(c);
  return c;
}

void XmlElementReader::collect_unknown_names(std::vector<UnknownName>& out) const {
  for (auto* a = e_->FirstAttribute(); a; a = a->Next())
    if (!read_attributes_.count(a->Name()))
      out.push_back({file_ + ":" + std::to_string(a->GetLineNum()) + ": unknown attribute '" +
                         a->Name() + "' on <" + e_->Name() + ">",
                     joined(read_attributes_)});
  for (auto* c = e_->FirstChildElement(); c; c = c->NextSiblingElement())
    if (!read_children_.count(c))
      out.push_back({file_ + ":" + std::to_string(c->GetLineNum()) + ": unknown element <" +
                         c->Name() + "> in <" + e_->Name() + ">",
                     joined(asked_children_)});
}

void check_project_version(const XmlElementReader& root, UnknownNames policy,
                           std::vector<std::string>& warnings) {
  const int version = root.integer("version", 1);
  if (version == 1) return;
  if (version < 1 || policy == UnknownNames::refuse)
    root.fail("version",
              "1 (the project version this polarform reads; --lenient reads a newer "
              "one as far as it knows it)");
  warnings.push_back(root.where() + ": project version " + std::to_string(version) +
                     " is newer than this polarform's (1): read leniently");
}

double read_length_unit(const XmlElementReader& root, const XmlElementReader& design) {
  const auto unit = [](const XmlElementReader& r) {
    return r.choice("units", {"mm", "inch"}, "mm") == "inch" ? 25.4 : 1.0;
  };
  const double on_root = unit(root);
  if (design.element() == root.element()) return on_root;
  const double on_design = unit(design);
  if (root.has("units") && design.has("units") && on_root != on_design)
    design.fail("units", "the units of the root element <" + std::string(root.element()->Name()) +
                             ">, or no units here");
  return design.has("units") ? on_design : on_root;
}

void settle_unknown_names(const std::vector<UnknownName>& unknown, UnknownNames policy,
                          std::vector<std::string>& warnings) {
  const auto known = [](const UnknownName& u) {
    return u.known.empty() ? std::string(" (none known here)") : " (known here: " + u.known + ")";
  };
  if (unknown.empty()) return;
  if (policy == UnknownNames::warn) {
    for (const UnknownName& u : unknown) warnings.push_back(u.what + " ignored" + known(u));
    return;
  }
  std::string message;
  for (const UnknownName& u : unknown) message += (message.empty() ? "" : "; ") + u.what + known(u);
  throw InputError(message +
                   " - a misspelt or unsupported name would build another part than the "
                   "one written (--lenient ignores unknown names with a warning)");
}

}  // namespace polarform
