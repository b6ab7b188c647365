// Minimal independent readers for the curves the cam job exports: the SPLINE entities of a DXF
// file (group codes 8, 70-73, 40, 41, 10/20/30), its CIRCLE entities, and the rational B-spline
// curve entities (type 126) of an IGES file (Directory Entry and Parameter Data sections). They
// parse numbers, so tests compare geometry semantically rather than byte for byte.
#pragma once

#include <Eigen/Core>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace polarform::cam_job_test {

struct ReadSpline {
  std::string layer;  // DXF only
  int degree = 0;
  int flags = 0;                       // DXF group 70
  std::vector<double> knots, weights;  // weights empty for a non-rational DXF spline
  std::vector<Eigen::Vector3d> points;
};

inline std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \r\t");
  const auto b = s.find_last_not_of(" \r\t");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

inline double to_double(const std::string& text) {
  std::string s = trimmed(text);
  for (char& c : s)
    if (c == 'D') c = 'E';  // IGES exponent
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0') throw std::runtime_error("not a number: '" + text + "'");
  return x;
}

// The (group code, value) pairs of a DXF file.
inline std::vector<std::pair<int, std::string>> dxf_tags(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::pair<int, std::string>> tags;
  for (std::string code, value; std::getline(in, code) && std::getline(in, value);)
    tags.emplace_back(std::stoi(code), trimmed(value));
  return tags;
}

struct ReadCircle {
  std::string layer;
  double radius = 0;
};

// Every CIRCLE entity of a DXF file (layer, group 40), in file order.
inline std::vector<ReadCircle> read_dxf_circles(const std::string& text) {
  std::vector<ReadCircle> out;
  bool in_circle = false;
  for (const auto& [code, value] : dxf_tags(text)) {
    if (code == 0) in_circle = value == "CIRCLE";
    if (code == 0 && in_circle) out.emplace_back();
    if (in_circle && code == 8) out.back().layer = value;
    if (in_circle && code == 40) out.back().radius = to_double(value);
  }
  return out;
}

// Every SPLINE entity of a DXF file, in file order.
inline std::vector<ReadSpline> read_dxf_splines(const std::string& text) {
  const std::vector<std::pair<int, std::string>> tags = dxf_tags(text);
  std::vector<ReadSpline> out;
  ReadSpline* s = nullptr;
  std::size_t counts[2] = {0, 0};  // declared knot and control-point counts
  auto check = [&] {
    if (s && (s->knots.size() != counts[0] || s->points.size() != counts[1]))
      throw std::runtime_error("DXF SPLINE: counts 72/73 disagree with the data");
  };
  for (const auto& [code, value] : tags) {
    if (code == 0) {
      check();
      s = nullptr;
      if (value == "SPLINE") s = &out.emplace_back();
      continue;
    }
    if (!s) continue;
    switch (code) {
      case 8:
        s->layer = value;
        break;
      case 70:
        s->flags = std::stoi(value);
        break;
      case 71:
        s->degree = std::stoi(value);
        break;
      case 72:
        counts[0] = std::stoul(value);
        break;
      case 73:
        counts[1] = std::stoul(value);
        break;
      case 40:
        s->knots.push_back(to_double(value));
        break;
      case 41:
        s->weights.push_back(to_double(value));
        break;
      case 10:
        s->points.emplace_back(to_double(value), 0.0, 0.0);
        break;
      case 20:
        s->points.back().y() = to_double(value);
        break;
      case 30:
        s->points.back().z() = to_double(value);
        break;
      default:
        break;
    }
  }
  check();
  return out;
}

// Every entity 126 of an IGES file, in Directory Entry order.
inline std::vector<ReadSpline> read_iges_curves(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> d_lines, p_lines;
  for (std::string line; std::getline(in, line);) {
    if (line.size() < 73) throw std::runtime_error("IGES line shorter than 73 columns");
    if (line[72] == 'D') d_lines.push_back(line);
    if (line[72] == 'P') p_lines.push_back(line);
  }
  std::vector<ReadSpline> out;
  for (std::size_t k = 0; k + 1 < d_lines.size(); k += 2) {
    auto field = [&](int line, int n) {
      return std::stoi(d_lines[k + line].substr(8 * (n - 1), 8));
    };
    if (field(0, 1) != 126) continue;
    std::string data;
    for (int l = 0; l < field(1, 4); ++l) data += p_lines.at(field(0, 2) - 1 + l).substr(0, 64);
    std::vector<std::string> params;
    std::stringstream list(data.substr(0, data.find(';')));
    for (std::string item; std::getline(list, item, ',');) params.push_back(trimmed(item));
    // 126, K, M, PROP1..4, knots (K+M+2), weights (K+1), points 3(K+1), V0, V1, normal, then
    // optionally the back-pointer and property-pointer lists.
    const int K = std::stoi(params.at(1)), M = std::stoi(params.at(2));
    const std::size_t nk = K + M + 2, n = K + 1;
    if (params.size() < 7 + nk + 4 * n + 5)
      throw std::runtime_error("IGES 126: too few parameters");
    ReadSpline s;
    s.degree = M;
    std::size_t at = 7;
    for (std::size_t i = 0; i < nk; ++i) s.knots.push_back(to_double(params[at++]));
    for (std::size_t i = 0; i < n; ++i) s.weights.push_back(to_double(params[at++]));
    for (std::size_t i = 0; i < n; ++i, at += 3)
      s.points.emplace_back(to_double(params[at]), to_double(params[at + 1]),
                            to_double(params[at + 2]));
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace polarform::cam_job_test
