// IGES 5.3 writer: fixed-format file structure (80 columns, section letters, sequence numbers,
// DE <-> PD pointers, Terminate counts), Global parameters (units, scale, resolution, maximum
// coordinate), and every number of entities 126 / 128 / 102 / 406 parsed back exactly by an
// independent reader written here.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

#include "export/exchange_geometry.h"
#include "export/iges_writer.h"
#include "src/error.h"
#include "tests/support/export/exchange_fixtures.h"

namespace polarform {
namespace {

using namespace exchange_test;

struct Token {
  std::string text;
  bool hollerith = false;
};

// Splits free-format IGES parameters ("," and ";" delimited, nH strings) into tokens.
std::vector<Token> tokenize(const std::string& data) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < data.size()) {
    while (i < data.size() && data[i] == ' ') ++i;
    if (i >= data.size()) break;
    std::size_t j = i;
    while (j < data.size() && std::isdigit(static_cast<unsigned char>(data[j]))) ++j;
    Token t;
    if (j < data.size() && j > i && data[j] == 'H') {
      const std::size_t n = std::stoul(data.substr(i, j - i));
      t = {data.substr(j + 1, n), true};
      i = j + 1 + n;
    } else {
      j = data.find_first_of(",;", i);
      t = {data.substr(i, j - i), false};
      i = j;
    }
    out.push_back(t);
    if (i >= data.size()) throw std::runtime_error("IGES parameters not terminated");
    const char delimiter = data[i++];
    if (delimiter == ';') break;
    if (delimiter != ',') throw std::runtime_error("bad IGES delimiter '" + std::string(1, delimiter) + "'");
  }
  return out;
}

double real(const Token& t) {
  std::string s = t.text;
  for (char& c : s)
    if (c == 'D') c = 'E';
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (*end != '\0' || s.find('.') == std::string::npos)
    throw std::runtime_error("not an IGES real: '" + t.text + "'");
  return x;
}

int integer(const Token& t) { return std::stoi(t.text); }

struct Entry {
  int type, pointer, line_count, form, de;
  std::string status, label;
  std::vector<Token> params;  // after the entity type
};

struct Iges {
  std::vector<std::string> start;
  std::vector<Token> global;
  std::vector<Entry> entries;
  std::map<char, int> lines;
};

// Parses and checks the fixed-format structure; throws std::runtime_error on any violation.
Iges parse(const std::string& text) {
  Iges f;
  std::istringstream in(text);
  std::string line, global_data;
  std::vector<std::string> d_lines, p_lines;
  const std::string order = "SGDPT";
  std::size_t section = 0;
  while (std::getline(in, line)) {
    if (line.size() != 80) throw std::runtime_error("line of " + std::to_string(line.size()) + " columns");
    const char s = line[72];
    const std::size_t at = order.find(s);
    if (at == std::string::npos || at < section) throw std::runtime_error("section out of order");
    section = at;
    const int seq = std::stoi(line.substr(73));
    if (seq != ++f.lines[s]) throw std::runtime_error("bad sequence number in " + std::string(1, s));
    const std::string data = line.substr(0, 72);
    if (s == 'S') f.start.push_back(data);
    if (s == 'G') global_data += data;
    if (s == 'D') d_lines.push_back(data);
    if (s == 'P') p_lines.push_back(line);
    if (s == 'T') {
      for (int k = 0; k < 4; ++k) {
        const char c = order[k];
        if (line[8 * k] != c || std::stoi(line.substr(8 * k + 1, 7)) != f.lines[c])
          throw std::runtime_error("Terminate count of section " + std::string(1, c));
      }
    }
  }
  if (f.lines['T'] != 1) throw std::runtime_error("missing Terminate section");
  f.global = tokenize(global_data);
  if (d_lines.size() % 2) throw std::runtime_error("odd number of DE lines");
  for (std::size_t k = 0; k < d_lines.size(); k += 2) {
    auto field = [&](int line, int n) { return d_lines[k + line].substr(8 * (n - 1), 8); };
    Entry e{std::stoi(field(0, 1)), std::stoi(field(0, 2)), std::stoi(field(1, 4)),
            std::stoi(field(1, 5)), static_cast<int>(k) + 1, field(0, 9), field(1, 8), {}};
    if (std::stoi(field(1, 1)) != e.type) throw std::runtime_error("DE type mismatch");
    std::string data;
    for (int l = 0; l < e.line_count; ++l) {
      const std::string& pl = p_lines.at(e.pointer - 1 + l);
      if (std::stoi(pl.substr(64, 8)) != e.de) throw std::runtime_error("PD back pointer");
      if (pl[64] != ' ') throw std::runtime_error("PD column 65 not blank");
      data += pl.substr(0, 64);
    }
    const std::vector<Token> all = tokenize(data);
    if (integer(all.at(0)) != e.type) throw std::runtime_error("PD type mismatch");
    e.params.assign(all.begin() + 1, all.end());
    const std::size_t first = e.label.find_first_not_of(' ');
    e.label = first == std::string::npos ? "" : e.label.substr(first);
    f.entries.push_back(e);
  }
  return f;
}

IgesHeader fixed_header() {
  IgesHeader h;
  h.time_stamp = "20240501.120000";
  h.author = "test author";
  h.organization = "polarform";
  h.file_name = "test.igs";
  return h;
}

// Checks a 126 entity against the curve: counts, flags, and every number bit for bit.
void expect_curve_entity(const Entry& e, const NurbsCurve3d& c, int planar, int closed,
                         int polynomial, int periodic, const Eigen::Vector3d& normal) {
  ASSERT_EQ(e.type, 126);
  const auto& p = e.params;
  const int n = c.size(), deg = c.degree(), nk = static_cast<int>(c.knots().size());
  ASSERT_EQ(static_cast<int>(p.size()), 6 + nk + 4 * n + 5);
  EXPECT_EQ(integer(p[0]), n - 1);
  EXPECT_EQ(integer(p[1]), deg);
  EXPECT_EQ(integer(p[2]), planar);
  EXPECT_EQ(integer(p[3]), closed);
  EXPECT_EQ(integer(p[4]), polynomial);
  EXPECT_EQ(integer(p[5]), periodic);
  for (int i = 0; i < nk; ++i) EXPECT_EQ(real(p[6 + i]), c.knots()[i]);
  for (int i = 0; i < n; ++i) EXPECT_EQ(real(p[6 + nk + i]), c.weight(i));
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(real(p[6 + nk + n + 3 * i + k]), c.control_point(i)[k]);
  EXPECT_EQ(real(p[6 + nk + 4 * n]), c.front());
  EXPECT_EQ(real(p[6 + nk + 4 * n + 1]), c.back());
  for (int k = 0; k < 3; ++k) EXPECT_EQ(real(p[6 + nk + 4 * n + 2 + k]), normal[k]);
}

TEST(IgesWriter, FileStructureAndGlobalSection) {
  IgesWriter w;
  w.add(ellipse(25, 25), "circle");
  w.add(degree12(), "deg12");
  w.add(rational55(), "patch");
  const Iges f = parse(w.str(fixed_header()));
  EXPECT_EQ(f.lines.at('S'), 1);
  EXPECT_EQ(f.start[0].substr(0, 22), "polarform NURBS export");
  const auto& g = f.global;
  ASSERT_EQ(g.size(), 25u);
  EXPECT_EQ(g[0].text, ",");
  EXPECT_EQ(g[1].text, ";");
  EXPECT_EQ(g[3].text, "test.igs");
  EXPECT_EQ(integer(g[6]), 32);
  EXPECT_EQ(integer(g[9]), 308);
  EXPECT_EQ(integer(g[10]), 15);
  EXPECT_EQ(real(g[12]), 1.0);     // model space scale
  EXPECT_EQ(integer(g[13]), 2);    // unit flag: millimetres
  EXPECT_EQ(g[14].text, "MM");
  EXPECT_TRUE(g[14].hollerith);
  EXPECT_EQ(g[17].text, "20240501.120000");
  EXPECT_EQ(real(g[18]), 1e-6);    // resolution
  // Maximum coordinate: the largest |coordinate| of all control points, here x of rational55.
  EXPECT_EQ(real(g[19]), 100 + 12.0 * 7);
  EXPECT_EQ(g[20].text, "test author");
  EXPECT_EQ(integer(g[22]), 11);   // IGES 5.3
  EXPECT_EQ(g[24].text, "20240501.120000");
  ASSERT_EQ(f.entries.size(), 3u);
  EXPECT_EQ(f.entries[0].label, "circle");
  EXPECT_EQ(f.entries[1].label, "deg12");
  EXPECT_EQ(f.entries[0].status, "00000000");
  EXPECT_EQ(f.entries[0].form, 0);
}

TEST(IgesWriter, CurveEntitiesCarryEveryNumberAndTruthfulFlags) {
  IgesWriter w;
  const NurbsCurve2d circle = ellipse(25, 25);
  const NurbsCurve2d closed9 = closed_degree9();
  w.add(circle, "circle");
  w.add(closed9, "closed9");
  w.add(open_cubic(), "cubic");
  w.add(degree12(), "deg12");
  const Iges f = parse(w.str(fixed_header()));
  ASSERT_EQ(f.entries.size(), 4u);
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ(), none = Eigen::Vector3d::Zero();
  expect_curve_entity(f.entries[0], lift_to_3d(circle), 1, 1, 0, 0, z);
  expect_curve_entity(f.entries[1], lift_to_3d(closed9), 1, 1, 0, 0, z);
  expect_curve_entity(f.entries[2], open_cubic(), 0, 0, 1, 0, none);
  expect_curve_entity(f.entries[3], degree12(), 0, 0, 0, 0, none);
}

TEST(IgesWriter, PeriodicFlagForWrappedKnotsAndPoints) {
  IgesWriter w;
  w.add(periodic_cubic());
  const Iges f = parse(w.str(fixed_header()));
  // Not planar: the homogeneous z row (0 2 0 1 ...) lifts some control points off z = 0.
  expect_curve_entity(f.entries[0], periodic_cubic(), 0, 1, 0, 1, Eigen::Vector3d::Zero());
}

TEST(IgesWriter, SurfaceEntityRunsUFastest) {
  const NurbsSurface s = rational55();
  IgesWriter w;
  w.add(s, "patch");
  w.add(sphere(10), "sphere");
  const Iges f = parse(w.str(fixed_header()));
  ASSERT_EQ(f.entries.size(), 2u);
  const Entry& e = f.entries[0];
  ASSERT_EQ(e.type, 128);
  const auto& p = e.params;
  const int nu = s.size_u(), nv = s.size_v();
  const int ku = static_cast<int>(s.knots_u().size()), kv = static_cast<int>(s.knots_v().size());
  ASSERT_EQ(static_cast<int>(p.size()), 9 + ku + kv + 4 * nu * nv + 4);
  EXPECT_EQ(integer(p[0]), nu - 1);
  EXPECT_EQ(integer(p[1]), nv - 1);
  EXPECT_EQ(integer(p[2]), 5);
  EXPECT_EQ(integer(p[3]), 5);
  for (int k = 4; k < 9; ++k) EXPECT_EQ(integer(p[k]), 0);  // open, rational, not periodic
  for (int i = 0; i < ku; ++i) EXPECT_EQ(real(p[9 + i]), s.knots_u()[i]);
  for (int i = 0; i < kv; ++i) EXPECT_EQ(real(p[9 + ku + i]), s.knots_v()[i]);
  const int w0 = 9 + ku + kv, p0 = w0 + nu * nv;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      EXPECT_EQ(real(p[w0 + j * nu + i]), s.weight(i, j));
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(real(p[p0 + 3 * (j * nu + i) + k]), s.control_point(i, j)[k]);
    }
  EXPECT_EQ(real(p[p0 + 3 * nu * nv]), 0.0);
  EXPECT_EQ(real(p[p0 + 3 * nu * nv + 1]), 2.0);
  EXPECT_EQ(real(p[p0 + 3 * nu * nv + 2]), 1.0);
  EXPECT_EQ(real(p[p0 + 3 * nu * nv + 3]), 3.0);
  // The sphere of revolution is closed in v (around z), open in u (pole to pole).
  EXPECT_EQ(integer(f.entries[1].params[4]), 0);
  EXPECT_EQ(integer(f.entries[1].params[5]), 1);
}

TEST(IgesWriter, CompositeCurveAndLongNames) {
  IgesWriter w;
  const std::string long_name = "cam profile, degree 9 (closed)";
  w.add_composite(std::vector<NurbsCurve2d>{closed_degree9()}, long_name);
  // Two halves of the circle joined end to start.
  const NurbsCurve2d circle = ellipse(20, 20);
  const NurbsCurve2d::Points points = circle.control_points();
  const NurbsCurve2d::Points upper(points.begin(), points.begin() + 5);
  const NurbsCurve2d::Points lower(points.begin() + 4, points.end());
  const std::vector<double> wts = circle.weights();
  const NurbsCurve2d a(2, {0, 0, 0, 0.5, 0.5, 1, 1, 1}, upper, {wts.begin(), wts.begin() + 5});
  const NurbsCurve2d b(2, {1, 1, 1, 1.5, 1.5, 2, 2, 2}, lower, {wts.begin() + 4, wts.end()});
  w.add_composite(std::vector<NurbsCurve2d>{a, b}, "halves");
  const Iges f = parse(w.str(fixed_header()));
  ASSERT_EQ(f.entries.size(), 6u);  // 126, 102, 406 | 126, 126, 102
  EXPECT_EQ(f.entries[0].type, 126);
  EXPECT_EQ(f.entries[0].status, "00010000");  // physically dependent
  const Entry& composite = f.entries[1];
  EXPECT_EQ(composite.type, 102);
  EXPECT_EQ(composite.label, long_name.substr(0, 8));
  ASSERT_EQ(composite.params.size(), 5u);  // N, DE, no associativities, 1 property, its DE
  EXPECT_EQ(integer(composite.params[0]), 1);
  EXPECT_EQ(integer(composite.params[1]), f.entries[0].de);
  EXPECT_EQ(integer(composite.params[2]), 0);
  EXPECT_EQ(integer(composite.params[3]), 1);
  EXPECT_EQ(integer(composite.params[4]), f.entries[2].de);
  EXPECT_EQ(f.entries[2].type, 406);
  EXPECT_EQ(f.entries[2].form, 15);
  EXPECT_EQ(integer(f.entries[2].params[0]), 1);
  EXPECT_EQ(f.entries[2].params[1].text, long_name);
  const Entry& halves = f.entries[5];
  EXPECT_EQ(halves.type, 102);
  ASSERT_EQ(halves.params.size(), 3u);
  EXPECT_EQ(integer(halves.params[1]), f.entries[3].de);
  EXPECT_EQ(integer(halves.params[2]), f.entries[4].de);
  EXPECT_EQ(halves.label, "halves");
}

TEST(IgesWriter, RejectsBadInput) {
  IgesWriter w;
  EXPECT_THROW(w.add(NurbsCurve2d(3, clamped_knots(3, 0, 1, {0.5, 0.5, 0.5, 0.5}),
                                  NurbsCurve2d::Points(8, Eigen::Vector2d(1, 2)))),
               InputError);
  EXPECT_THROW(w.add(ellipse(1, 1), "Nocken\xc3\xa4"), InputError);
  EXPECT_THROW(w.add_composite(std::vector<NurbsCurve2d>{}, "empty"), InputError);
  IgesWriter gap;
  gap.add_composite(std::vector<NurbsCurve2d>{ellipse(20, 20), ellipse(10, 10)}, "gap");
  EXPECT_THROW(gap.str(fixed_header()), InputError);
  IgesHeader bad = fixed_header();
  bad.time_stamp = "2024-05-01";
  EXPECT_THROW(w.str(bad), InputError);
  bad = fixed_header();
  bad.resolution = 0.0;
  EXPECT_THROW(w.str(bad), InputError);
}

}  // namespace
}  // namespace polarform
