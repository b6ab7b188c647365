// XmlElementReader: typed attributes with file:line errors, and unknown names refused or warned.
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
  std::vector<UnknownName> unknown;
  cam.collect_unknown_names(unknown);
  EXPECT_TRUE(unknown.empty());
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

TEST(XmlReader, UnreadAttributesAndElementsAreUnknownNamesWithTheKnownOnes) {
  const XmlDocument doc("<cam a=\"1\"\n colour=\"red\">\n  <segment/>\n  <sgement/>\n</cam>",
                        "t.xml");
  const XmlElementReader cam(doc.root(), doc.file());
  cam.number("a");
  cam.has("b");
  cam.children("segment");
  cam.child("conversion");
  std::vector<UnknownName> unknown;
  cam.collect_unknown_names(unknown);
  ASSERT_EQ(unknown.size(), 2u);
  EXPECT_EQ(unknown[0].what, "t.xml:2: unknown attribute 'colour' on <cam>");
  EXPECT_EQ(unknown[0].known, "a, b");
  EXPECT_EQ(unknown[1].what, "t.xml:4: unknown element <sgement> in <cam>");
  EXPECT_EQ(unknown[1].known, "conversion, segment");

  std::vector<std::string> warnings;
  EXPECT_EQ(error_of([&] { settle_unknown_names(unknown, UnknownNames::refuse, warnings); }),
            "t.xml:2: unknown attribute 'colour' on <cam> (known here: a, b); "
            "t.xml:4: unknown element <sgement> in <cam> (known here: conversion, segment) - "
            "a misspelt or unsupported name would build another part than the one written "
            "(--lenient ignores unknown names with a warning)");
  EXPECT_TRUE(warnings.empty());
  settle_unknown_names(unknown, UnknownNames::warn, warnings);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0], "t.xml:2: unknown attribute 'colour' on <cam> ignored (known here: a, b)");
  EXPECT_EQ(
      warnings[1],
      "t.xml:4: unknown element <sgement> in <cam> ignored (known here: conversion, segment)");
  settle_unknown_names({}, UnknownNames::refuse, warnings);  // nothing unknown: no error
}

TEST(XmlReader, NewerProjectVersionsOnlyLeniently) {
  std::vector<std::string> warnings;
  for (const char* version : {"1", "1.0"}) {
    const XmlDocument doc(std::string("<polarform version=\"") + version + "\"/>", "p.xml");
    check_project_version(XmlElementReader(doc.root(), doc.file()), UnknownNames::refuse, warnings);
  }
  const XmlDocument v2("<polarform version=\"2\"/>", "p.xml");
  const XmlElementReader root(v2.root(), v2.file());
  EXPECT_NE(error_of([&] {
              check_project_version(root, UnknownNames::refuse, warnings);
            }).find("p.xml:1: <polarform> attribute 'version': expected 1"),
            std::string::npos);
  EXPECT_TRUE(warnings.empty());
  check_project_version(root, UnknownNames::warn, warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "p.xml:1: <polarform>: project version 2 is newer than this polarform's "
            "(1): read leniently");
  const XmlDocument v0("<polarform version=\"0\"/>", "p.xml");
  EXPECT_THROW(
      check_project_version(XmlElementReader(v0.root(), v0.file()), UnknownNames::warn, warnings),
      InputError);
}

TEST(XmlReader, MalformedDocumentsAreDescribedInWords) {
  const struct {
    const char* xml;
    const char* expected;
  } cases[] = {
      {"<cam>\n<segment>\n</cam>",
       "bad.xml:2: malformed XML: an element is not closed properly (a closing tag is missing or "
       "misspelt)"},
      {"<cam a=1/>",
       "bad.xml:1: malformed XML: cannot parse an attribute (write name=\"value\" with quotes, "
       "each name once)"},
      {"<cam a=\"1\" a=\"2\"/>", "cannot parse an attribute"},
      {"<cam>\nx < y</cam>", "bad.xml:2: malformed XML: cannot parse an element"},
      {"base-radius = 40", "bad.xml:1: malformed XML: text outside the elements"},
      {"<cam><!-- a note </cam>", "a comment <!-- without its -->"},
      {"<cam><![CDATA[ x </cam>", "a <![CDATA[ section without its ]]>"},
      {"<?xml version", "a declaration <?…?> that is not closed"},
      {"<cam>\n\n<1segment/></cam>", "bad.xml:3: malformed XML: unrecognised markup"},
      {"", "bad.xml: malformed XML: the document is empty"},
  };
  for (const auto& c : cases) {
    const std::string error = error_of([&] { XmlDocument(c.xml, "bad.xml"); });
    EXPECT_NE(error.find(c.expected), std::string::npos) << c.xml << " -> " << error;
    EXPECT_EQ(error.find("XML_"), std::string::npos) << error;  // no tinyxml2 identifiers
  }
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
