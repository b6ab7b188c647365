// XmlElementReader: typed attributes with file:line errors and warnings for what nobody read.
#include <gtest/gtest.h>

#include "jobs/project/xml_reader.h"
#include "src/error.h"

namespace polarform {
namespace {

std::string error_of(auto&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(XmlReader, TypedAttributes) {
  const XmlDocument doc("<root>\n<cam r=\"40.5\" n=\"3\" k=\"roller\" v=\"3, 4\" z=\"0\"/>\n</root>",
                        "t.xml");
  const XmlElementReader cam(doc.root()->FirstChildElement("cam"), doc.file());
  EXPECT_EQ(cam.number("r"), 40.5);
  EXPECT_EQ(cam.positive("r"), 40.5);
  EXPECT_EQ(cam.positive("z", true), 0.0);
  EXPECT_EQ(cam.integer("n", 0), 3);
  EXPECT_EQ(cam.number("absent", 7.0), 7.0);
  EXPECT_FALSE(cam.optional_number("absent"));
  EXPECT_EQ(cam.choice("k", {"knife-edge", "roller"}), "roller");
  EXPECT_EQ(cam.numbers("v", 2), (std::vector<double>{3, 4}));
  EXPECT_TRUE(cam.warnings().empty());
}

TEST(XmlReader, ErrorsNameFileLineElementAttribute) {
  const XmlDocument doc(
      "<root>\n<cam r=\"4o\" n=\"2.5\" k=\"wheel\" z=\"-1\" i=\"inf\"/>\n</root>", "t.xml");
  const XmlElementReader cam(doc.root()->FirstChildElement("cam"), doc.file());
  EXPECT_EQ(error_of([&] { cam.number("r"); }),
            "t.xml:2: <cam> attribute 'r': expected a finite number, got '4o'");
  EXPECT_EQ(error_of([&] { cam.number("missing"); }),
            "t.xml:2: <cam> attribute 'missing': expected a number (attribute is missing)");
  EXPECT_EQ(error_of([&] { cam.integer("n", 0); }),
            "t.xml:2: <cam> attribute 'n': expected an integer, got '2.5'");
  EXPECT_EQ(error_of([&] { cam.choice("k", {"knife-edge", "roller"}); }),
            "t.xml:2: <cam> attribute 'k': expected one of knife-edge|roller, got 'wheel'");
  EXPECT_EQ(error_of([&] { cam.positive("z"); }),
            "t.xml:2: <cam> attribute 'z': expected a number > 0, got '-1'");
  EXPECT_EQ(error_of([&] { cam.number("i"); }),
            "t.xml:2: <cam> attribute 'i': expected a finite number, got 'inf'");
}

TEST(XmlReader, WarningsForUnreadAttributesAndElements) {
  const XmlDocument doc("<cam a=\"1\" colour=\"red\">\n  <segment/>\n  <sgement/>\n</cam>", "t.xml");
  const XmlElementReader cam(doc.root(), doc.file());
  cam.number("a");
  cam.children("segment");
  const auto w = cam.warnings();
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0], "t.xml:1: unknown attribute 'colour' on <cam> ignored");
  EXPECT_EQ(w[1], "t.xml:3: unknown element <sgement> in <cam> ignored");
}

TEST(XmlReader, MalformedDocuments) {
  EXPECT_EQ(error_of([] { XmlDocument("<cam>\n<segment>\n</cam>", "bad.xml"); }),
            "bad.xml:2: malformed XML: an element is not closed properly");
  EXPECT_EQ(error_of([] { XmlDocument("<cam a=1/>", "bad.xml"); }),
            "bad.xml:1: malformed XML: cannot parse an attribute");
  EXPECT_EQ(error_of([] { XmlDocument("", "empty.xml"); }),
            "empty.xml:0: malformed XML: the document is empty");
  EXPECT_EQ(error_of([] { XmlDocument(std::filesystem::path("/nonexistent/x.xml")); }),
            "/nonexistent/x.xml: no such file");
}

// A nest 10^5 elements deep is refused at tinyxml2's depth limit, not by exhausting the stack.
TEST(XmlReader, DeepNestsAreRefusedAtTheDepthLimit) {
  std::string deep = "<polarform version=\"1\">\n";
  for (int k = 0; k < 100000; ++k) deep += "<a>";
  for (int k = 0; k < 100000; ++k) deep += "</a>";
  deep += "</polarform>\n";
  EXPECT_EQ(error_of([&] { XmlDocument(deep, "deep.xml"); }),
            "deep.xml:2: malformed XML: elements nested deeper than 100 levels");
}

}  // namespace
}  // namespace polarform
