// Open CASCADE as the independent reader of our IGES and STEP output: collecting the reader's
// fail and warning messages, the edges and faces of a transferred shape, and comparing an edge's
// B-spline curve / a face's B-spline surface with the kernel's (degree, knots, weights, poles, and
// points at 200 parameters). Only compiled with POLARFORM_HAVE_OCCT.
#pragma once

#include <gtest/gtest.h>

#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <STEPControl_Reader.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/export/exchange_fixtures.h"

namespace polarform::exchange_test {

// The fail (and unless fails_only, warning) messages of a check list, one per line; "" if clean.
inline std::string messages(const Interface_CheckIterator& checks, bool fails_only = false) {
  std::string out;
  for (Interface_CheckIterator it = checks; it.More(); it.Next()) {
    const Handle(Interface_Check)& ch = it.Value();
    for (int i = 1; i <= ch->NbFails(); ++i) out += std::string("fail: ") + ch->CFail(i) + "\n";
    for (int i = 1; !fails_only && i <= ch->NbWarnings(); ++i)
      out += std::string("warning: ") + ch->CWarning(i) + "\n";
  }
  return out;
}

// Load and transfer messages of a reader's work session.
inline std::string reader_messages(const Handle(XSControl_WorkSession)& ws, bool fails_only = false) {
  return messages(ws->ModelCheckList(), fails_only) +
         messages(ws->TransferReader()->TransientProcess()->CheckList(Standard_False), fails_only);
}

inline std::vector<TopoDS_Edge> edges_of(const TopoDS_Shape& s) {
  std::vector<TopoDS_Edge> out;
  for (TopExp_Explorer ex(s, TopAbs_EDGE); ex.More(); ex.Next()) out.push_back(TopoDS::Edge(ex.Current()));
  return out;
}

inline std::vector<TopoDS_Face> faces_of(const TopoDS_Shape& s) {
  std::vector<TopoDS_Face> out;
  for (TopExp_Explorer ex(s, TopAbs_FACE); ex.More(); ex.Next()) out.push_back(TopoDS::Face(ex.Current()));
  return out;
}

// The shape Open CASCADE transfers from an IGES (.igs) or a STEP (.stp) file, expecting the
// reader to report no fails.
inline TopoDS_Shape read_exchange_file(const std::filesystem::path& file) {
  if (file.extension() == ".igs") {
    IGESControl_Reader reader;
    EXPECT_EQ(reader.ReadFile(file.c_str()), IFSelect_RetDone) << file;
    reader.TransferRoots();
    EXPECT_EQ(reader_messages(reader.WS(), true), "") << file;
    return reader.OneShape();
  }
  STEPControl_Reader reader;
  EXPECT_EQ(reader.ReadFile(file.c_str()), IFSelect_RetDone) << file;
  reader.TransferRoots();
  EXPECT_EQ(reader_messages(reader.WS(), true), "") << file;
  return reader.OneShape();
}

// Each edge's curve sampled at equal parameter steps, `total` points over all edges, as (x, y).
inline std::vector<std::vector<Eigen::Vector2d>> sampled_edges(const TopoDS_Shape& s, int total) {
  std::vector<std::vector<Eigen::Vector2d>> out;
  const std::vector<TopoDS_Edge> edges = edges_of(s);
  for (const TopoDS_Edge& e : edges) {
    double a = 0, b = 0;
    const Handle(Geom_Curve) c = BRep_Tool::Curve(e, a, b);
    const int n = total / static_cast<int>(edges.size());
    std::vector<Eigen::Vector2d>& points = out.emplace_back();
    for (int i = 0; i < n; ++i) {
      const gp_Pnt q = c->Value(a + (b - a) * i / n);
      points.emplace_back(q.X(), q.Y());
    }
  }
  return out;
}

// The same, all edges in the file's order in one list.
inline std::vector<Eigen::Vector2d> sampled_points(const TopoDS_Shape& s, int total) {
  std::vector<Eigen::Vector2d> out;
  for (const auto& edge : sampled_edges(s, total)) out.insert(out.end(), edge.begin(), edge.end());
  return out;
}

inline double relative_gap(double a, double b) {
  return std::abs(a - b) / std::max(1.0, std::max(std::abs(a), std::abs(b)));
}

// The edge's curve against ours: degree, knots (with multiplicities), weights and poles to 1e-15
// relative, the edge's parameter range, and 200 points to 1e-9 mm.
inline void expect_same_curve(const TopoDS_Edge& edge, const NurbsCurve3d& c, double* worst = nullptr) {
  double first = 0, last = 0;
  Handle(Geom_Curve) g = BRep_Tool::Curve(edge, first, last);
  ASSERT_FALSE(g.IsNull());
  if (auto t = Handle(Geom_TrimmedCurve)::DownCast(g); !t.IsNull()) g = t->BasisCurve();
  Handle(Geom_BSplineCurve) b = Handle(Geom_BSplineCurve)::DownCast(g);
  ASSERT_FALSE(b.IsNull()) << "edge curve is a " << g->DynamicType()->Name();
  ASSERT_EQ(b->Degree(), c.degree());
  EXPECT_LT(relative_gap(first, c.front()), 1e-15);
  EXPECT_LT(relative_gap(last, c.back()), 1e-15);
  // Open CASCADE keeps only the knots of the domain [front, back] when it makes a closed curve
  // periodic (STEP) or re-clamps an unclamped one at its domain (IGES): poles and weights of a
  // re-clamped curve are new, its points are compared.
  const bool clamped = c.knots().front() == c.front() && c.knots().back() == c.back();
  const bool reclamped = !clamped && !b->IsPeriodic();
  std::vector<Breakpoint> ours = breakpoints(c.knots());
  if (!clamped || b->IsPeriodic())
    std::erase_if(ours, [&](const Breakpoint& k) { return k.value < c.front() || k.value > c.back(); });
  ASSERT_EQ(b->NbKnots(), static_cast<int>(ours.size()));
  for (int i = 1; i <= b->NbKnots(); ++i) EXPECT_LT(relative_gap(b->Knot(i), ours[i - 1].value), 1e-15);
  if (b->IsPeriodic()) {
    // The poles that do not repeat: all but the last of a clamped closed curve, all but the last
    // degree ones of a wrapped periodic curve.
    EXPECT_EQ(b->NbPoles(), c.size() - (clamped ? 1 : c.degree()));
  } else if (clamped) {
    ASSERT_EQ(b->NbPoles(), c.size());
    for (int i = 1; i <= b->NbKnots(); ++i) EXPECT_EQ(b->Multiplicity(i), ours[i - 1].multiplicity);
  } else {
    EXPECT_EQ(b->Multiplicity(1), c.degree() + 1);
  }
  EXPECT_EQ(b->IsRational(), c.is_rational());
  for (int i = 1; !reclamped && i <= b->NbPoles(); ++i) {
    const Eigen::Vector3d p = c.control_point(i - 1);
    const gp_Pnt q = b->Pole(i);
    EXPECT_LT((Eigen::Vector3d(q.X(), q.Y(), q.Z()) - p).norm(), 1e-15 * std::max(1.0, p.norm()));
    if (c.is_rational()) {
      EXPECT_LT(relative_gap(b->Weight(i), c.weight(i - 1)), 1e-15);
    }
  }
  double max_d = 0.0;
  for (double u : linspace(c.front(), c.back(), 200)) {
    const gp_Pnt q = b->Value(u);
    max_d = std::max(max_d, (Eigen::Vector3d(q.X(), q.Y(), q.Z()) - c.point(u)).norm());
  }
  EXPECT_LT(max_d, 1e-9) << "largest distance OCCT vs polarform over 200 parameters";
  if (worst) *worst = std::max(*worst, max_d);
}

// The face's surface against ours: degrees, knots, weights, poles, and 20 x 10 points.
inline void expect_same_surface(const TopoDS_Face& face, const NurbsSurface& s, bool exact_form = true,
                                double* worst = nullptr) {
  Handle(Geom_Surface) g = BRep_Tool::Surface(face);
  ASSERT_FALSE(g.IsNull());
  if (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(g); !t.IsNull()) g = t->BasisSurface();
  Handle(Geom_BSplineSurface) b = Handle(Geom_BSplineSurface)::DownCast(g);
  ASSERT_FALSE(b.IsNull()) << "face surface is a " << g->DynamicType()->Name();
  ASSERT_EQ(b->UDegree(), s.degree_u());
  ASSERT_EQ(b->VDegree(), s.degree_v());
  if (exact_form) {
    ASSERT_EQ(b->NbUPoles(), s.size_u());
    ASSERT_EQ(b->NbVPoles(), s.size_v());
    TColStd_Array1OfReal uk(1, b->NbUPoles() + s.degree_u() + 1), vk(1, b->NbVPoles() + s.degree_v() + 1);
    b->UKnotSequence(uk);
    b->VKnotSequence(vk);
    for (int i = 1; i <= uk.Length(); ++i) EXPECT_LT(relative_gap(uk(i), s.knots_u()[i - 1]), 1e-15);
    for (int i = 1; i <= vk.Length(); ++i) EXPECT_LT(relative_gap(vk(i), s.knots_v()[i - 1]), 1e-15);
    for (int i = 1; i <= s.size_u(); ++i)
      for (int j = 1; j <= s.size_v(); ++j) {
        const gp_Pnt q = b->Pole(i, j);
        const Eigen::Vector3d p = s.control_point(i - 1, j - 1);
        EXPECT_LT((Eigen::Vector3d(q.X(), q.Y(), q.Z()) - p).norm(), 1e-15 * std::max(1.0, p.norm()));
        EXPECT_LT(relative_gap(b->Weight(i, j), s.weight(i - 1, j - 1)), 1e-15);
      }
  }
  double max_d = 0.0;
  for (double u : linspace(s.front_u(), s.back_u(), 20))
    for (double v : linspace(s.front_v(), s.back_v(), 10)) {
      const gp_Pnt q = b->Value(u, v);
      max_d = std::max(max_d, (Eigen::Vector3d(q.X(), q.Y(), q.Z()) - s.point(u, v)).norm());
    }
  EXPECT_LT(max_d, 1e-9) << "largest distance OCCT vs polarform over 200 parameters";
  if (worst) *worst = std::max(*worst, max_d);
}

}  // namespace polarform::exchange_test
