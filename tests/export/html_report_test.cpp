// report.html: well-formed, escapes text, embeds figures inline, aligns numbers, rejects non-SVG.
#include "export/html_report.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include "export/svg_plot.h"
#include "src/error.h"
#include "tests/export/svg_test_support.h"

namespace polarform {
namespace {

using test::XMLElement;

std::string small_figure() {
  Figure figure(400, 250);
  Plot& plot = figure.add_panel();
  plot.add({"R", {0, 1, 2}, {1, 2, 1.5}});
  return svg_document(figure);
}

TEST(HtmlReport, IsWellFormedWithEscapedTextAndInlineFigures) {
  HtmlReport report("Cam <A> & \"B\"");
  report.add_heading("1. Motion & law", 2);
  report.add_paragraph("Use <script>alert(1)</script> nowhere.");
  report.add_key_figures({{"max error", "3.1e-4 mm"}, {"control points", "142"}});
  report.add_table({"segment", "angle [deg]"}, {{"rise", "120"}, {"dwell & <b>", "-0.5"}});
  report.add_svg("<?xml version=\"1.0\"?>\n" + small_figure(), "SVAJ & more");
  report.add_svg(small_figure(), "");
  const std::string html = report.html();
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_EQ(html.find("<?xml"), std::string::npos);  // the prolog is dropped inside HTML

  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(html.c_str(), html.size()), tinyxml2::XML_SUCCESS) << doc.ErrorStr();
  const XMLElement* main = doc.RootElement()->FirstChildElement("body")->FirstChildElement("main");
  ASSERT_NE(main, nullptr);
  EXPECT_STREQ(doc.RootElement()->FirstChildElement("head")->FirstChildElement("title")->GetText(),
               "Cam <A> & \"B\"");
  EXPECT_STREQ(main->FirstChildElement("h1")->GetText(), "Cam <A> & \"B\"");
  EXPECT_STREQ(main->FirstChildElement("h2")->GetText(), "1. Motion & law");
  EXPECT_STREQ(main->FirstChildElement("p")->GetText(), "Use <script>alert(1)</script> nowhere.");

  const auto values = test::by_class(main, "key-figures");
  ASSERT_EQ(values.size(), 1u);
  EXPECT_STREQ(values[0]->FirstChildElement("div")->FirstChildElement("dd")->GetText(),
               "3.1e-4 mm");

  const XMLElement* body = main->FirstChildElement("table")->FirstChildElement("tbody");
  const XMLElement* second_row = body->FirstChildElement("tr")->NextSiblingElement("tr");
  EXPECT_STREQ(second_row->FirstChildElement("td")->GetText(), "dwell & <b>");
  EXPECT_EQ(second_row->FirstChildElement("td")->Attribute("class"), nullptr);
  EXPECT_STREQ(second_row->LastChildElement("td")->Attribute("class"), "num");

  int figures = 0;
  for (const XMLElement* f = main->FirstChildElement("figure"); f;
       f = f->NextSiblingElement("figure")) {
    ++figures;
    const XMLElement* svg = f->FirstChildElement("svg");
    ASSERT_NE(svg, nullptr);
    EXPECT_EQ(test::by_class(svg, "plot-area").size(), 1u);
    EXPECT_EQ(test::subpaths(test::by_class(svg, "series")[0]->Attribute("d"))[0].size(), 3u);
    EXPECT_STREQ(f->FirstChildElement("figcaption")->GetText(),
                 figures == 1 ? "Figure 1. SVAJ & more" : "Figure 2.");
  }
  EXPECT_EQ(figures, 2);
}

TEST(HtmlReport, RejectsBadInput) {
  EXPECT_THROW(HtmlReport(""), InputError);
  HtmlReport report("r");
  EXPECT_THROW(report.add_heading("x", 1), InputError);
  EXPECT_THROW(report.add_heading("x", 5), InputError);
  EXPECT_THROW(report.add_table({"a", "b"}, {{"1"}}), InputError);
  EXPECT_THROW(report.add_svg("<html><body/></html>", "not svg"), InputError);
  EXPECT_THROW(report.add_svg("<svg><g></svg>", "broken"), InputError);
  EXPECT_THROW(report.add_svg("plain text", "none"), InputError);
  EXPECT_THROW(report.add_key_figures({}), InputError);
  // Nothing was added by the failed calls.
  EXPECT_EQ(report.html().find("<figure>"), std::string::npos);
}

}  // namespace
}  // namespace polarform
