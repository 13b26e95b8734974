// Ruled faces of the faithful tessellation (step_ruled.h). The doubles compared here (the
// u of boundary points) only decide the tessellation's topology: which points share a
// ruling. That the points of a ruling are then exactly on one line is the lattice
// placement's work (faithful/lattice_placement.h), in integers.
#include "step/step_ruled.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>
#include <ElSLib.hxx>
#include <gp_Lin.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <cmath>
#include <utility>

#include "step/faithful/ruled_strips.h"

namespace gvm::step_internal {
namespace {

// The largest |dS/du| over a grid of the face's parameter box: how far the surface moves
// for a change of u.
double u_speed(const TopoDS_Face& face) {
  BRepAdaptor_Surface s(face, /*R=*/false);
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  double best = 0;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      gp_Pnt p;
      gp_Vec du, dv;
      s.D1(u0 + (u1 - u0) * i / 4, v0 + (v1 - v0) * j / 4, p, du, dv);
      best = std::max(best, du.Magnitude());
    }
  return best;
}

}  // namespace

RuledFace::RuledFace(const TopoDS_Face& face, const Weld& weld, double tolerance, double cap)
    : reversed_face_(face.Orientation() == TopAbs_REVERSED), wires_(face_wires(face, weld)) {
  // A B-rep vertex sits off the curves it joins by up to its tolerance, so its ruling is
  // only known to that: a ruling that close to it is its own (a point added beside the
  // vertex would leave a needle in the neighbouring face), up to `cap`.
  double at_vertex = tolerance;
  for (TopExp_Explorer ex(face, TopAbs_VERTEX); ex.More(); ex.Next())
    at_vertex = std::max(at_vertex, std::min(cap, 4 * BRep_Tool::Tolerance(TopoDS::Vertex(ex.Current()))));
  BRepAdaptor_Surface s(face, /*R=*/false);
  if (s.GetType() == GeomAbs_Cylinder) cylinder_ = s.Cylinder();
  else if (s.GetType() == GeomAbs_Cone) cone_ = s.Cone();
  const double speed = u_speed(face);
  tol_u_ = speed > 0 ? tolerance / speed : 0;
  tol_vertex_u_ = speed > 0 ? at_vertex / speed : 0;
}

const BRepAdaptor_Curve& RuledFace::curve(const Weld& weld, int edge) const {
  auto& c = curves_[edge];
  if (!c) c = std::make_unique<BRepAdaptor_Curve>(TopoDS::Edge(weld.edges(edge + 1)));
  return *c;
}

// Where the point lies on the face: by projection onto a cylinder or cone (the pcurve only
// choosing which turn of u), which an edge's pcurve gives only within the edge's tolerance
// (0.01 mm on some intersection edges); by the pcurve on other surfaces.
std::pair<double, double> RuledFace::uv_at(const EdgeUse& use, double parameter, const gp_Pnt& p) const {
  const gp_Pnt2d uv = use.pcurve->Value(parameter);
  double u, v;
  if (cylinder_) ElSLib::Parameters(*cylinder_, p, u, v);
  else if (cone_ && gp_Lin(cone_->Axis()).Distance(p) > 1e-9 * (1 + std::fabs(cone_->RefRadius())))
    ElSLib::Parameters(*cone_, p, u, v);
  else return {uv.X(), uv.Y()};  // not projectable, or a cone's apex: on every ruling, by its pcurve
  const double turn = 2 * M_PI;
  return {u + turn * std::round((uv.X() - u) / turn), v};
}

std::pair<double, double> RuledFace::uv_of_node(const Weld& weld, const EdgeUse& use, uint32_t node) const {
  const Point3& q = weld.mesh->points[weld.edge_points[use.edge][node]];
  return uv_at(use, weld.edge_params[use.edge][node], gp_Pnt(q.x, q.y, q.z));
}

void RuledFace::find_rulings(const Weld& weld) {
  std::vector<std::pair<double, bool>> us;  // u, at a B-rep vertex
  for (const auto& wire : wires_)
    for (const EdgeUse& use : wire) {
      if (use.degenerated || use.pcurve.IsNull()) continue;
      const std::vector<double>& params = weld.edge_params[use.edge];
      for (uint32_t k = 0; k < params.size(); ++k)
        if (!std::isnan(params[k])) us.push_back({uv_of_node(weld, use, k).first, k == 0 || k + 1 == params.size()});
    }
  std::sort(us.begin(), us.end());
  rulings_.clear();
  bool vertex = false;  // the last ruling holds a vertex
  for (auto [u, at_vertex] : us) {
    const double gap = rulings_.empty() ? INFINITY : u - rulings_.back().lo;
    if (gap <= tol_u_ || ((vertex || at_vertex) && gap <= tol_vertex_u_)) {
      rulings_.back().hi = u;
      vertex = vertex || at_vertex;
    } else {
      rulings_.push_back({u, u});
      vertex = at_vertex;
    }
  }
}

int RuledFace::ruling_of(double u) const {
  auto it = std::lower_bound(rulings_.begin(), rulings_.end(), u,
                             [](const Cluster& c, double x) { return c.hi < x; });
  if (it != rulings_.end() && u >= it->lo) return int(it - rulings_.begin());
  return -1;
}

// The parameter in (p0, p1) where the edge's point is on the ruling at u, by bisection.
bool RuledFace::parameter_of(const Weld& weld, const EdgeUse& use, double p0, double p1, double u, double& out) const {
  const BRepAdaptor_Curve& c = curve(weld, use.edge);
  auto f = [&](double p) { return uv_at(use, p, c.Value(p)).first - u; };
  double f0 = f(p0), f1 = f(p1);
  if (f0 == 0 || f1 == 0 || (f0 < 0) == (f1 < 0)) return false;
  for (int i = 0; i < 100; ++i) {
    const double m = 0.5 * (p0 + p1);
    if (m == p0 || m == p1) break;
    const double fm = f(m);
    if (fm == 0) {
      out = m;
      return true;
    }
    if ((fm < 0) == (f0 < 0)) p0 = m, f0 = fm;
    else p1 = m, f1 = fm;
  }
  out = std::fabs(f0) < std::fabs(f1) ? p0 : p1;
  return true;
}

void RuledFace::insertions(const Weld& weld, uint32_t face, std::vector<EdgeInsertion>& out) const {
  for (const auto& wire : wires_)
    for (const EdgeUse& use : wire) {
      if (use.degenerated || use.pcurve.IsNull()) continue;
      const std::vector<double>& params = weld.edge_params[use.edge];
      for (size_t k = 0; k + 1 < params.size(); ++k) {
        if (std::isnan(params[k]) || std::isnan(params[k + 1])) continue;
        const int a = ruling_of(uv_of_node(weld, use, uint32_t(k)).first);
        const int b = ruling_of(uv_of_node(weld, use, uint32_t(k + 1)).first);
        if (a < 0 || b < 0) continue;
        for (int r = std::min(a, b) + 1; r < std::max(a, b); ++r) {
          double p;
          if (parameter_of(weld, use, params[k], params[k + 1], rulings_[r].lo, p)) out.push_back({use.edge, p, face});
        }
      }
    }
}

// A loop's points on their rulings; a degenerated edge (a cone's apex) becomes the apex on
// every ruling between its neighbours'.
bool RuledFace::strip_loop(const std::vector<LoopPoint>& loop, const std::vector<EdgeUse>& wire, Weld& weld,
                           std::vector<faithful::StripPoint>& out, std::string& why) const {
  std::vector<faithful::StripPoint> points;
  std::vector<bool> apex;
  for (const LoopPoint& p : loop) {
    const EdgeUse& use = wire[p.use];
    if (use.pcurve.IsNull()) {
      why = "an edge has no curve on the face";
      return false;
    }
    if (!use.degenerated && std::isnan(weld.edge_params[use.edge][p.node])) {
      why = "an edge point has no parameter";
      return false;
    }
    const gp_Pnt2d at_apex = use.pcurve->Value(use.first);
    auto [u, v] = use.degenerated ? std::pair{at_apex.X(), at_apex.Y()} : uv_of_node(weld, use, p.node);
    const int r = use.degenerated ? 0 : ruling_of(u);
    if (r < 0) {
      why = "a boundary point is on no ruling";
      return false;
    }
    points.push_back({p.id, uint32_t(r), v});
    apex.push_back(use.degenerated);
  }
  const size_t n = points.size();
  for (size_t i = 0; i < n; ++i) {
    if (!apex[i]) {
      if (out.empty() || out.back().id != points[i].id || out.back().ruling != points[i].ruling) out.push_back(points[i]);
      continue;
    }
    const faithful::StripPoint &prev = points[(i + n - 1) % n], &next = points[(i + 1) % n];
    if (apex[(i + n - 1) % n] || apex[(i + 1) % n]) {
      why = "two degenerated edges in a row";
      return false;
    }
    const int step = next.ruling >= prev.ruling ? 1 : -1;
    for (int r = int(prev.ruling) + step; r != int(next.ruling); r += step) out.push_back({points[i].id, uint32_t(r), points[i].v});
  }
  while (out.size() > 1 && out.front().id == out.back().id && out.front().ruling == out.back().ruling) out.pop_back();
  return true;
}

bool RuledFace::strips(Weld& weld, std::vector<std::vector<uint32_t>>& out, std::string& why) const {
  std::vector<std::vector<EdgeUse>> wires = wires_;
  const std::vector<std::vector<LoopPoint>> boundary = boundary_loops(wires, weld, /*by_uv=*/true);
  std::vector<std::vector<faithful::StripPoint>> loops(boundary.size());
  std::vector<double> area(boundary.size(), 0);
  for (size_t l = 0; l < boundary.size(); ++l) {
    if (!strip_loop(boundary[l], wires[l], weld, loops[l], why)) return false;
    const auto& loop = loops[l];
    for (size_t k = 0; k < loop.size(); ++k) {
      const faithful::StripPoint &a = loop[k], &b = loop[(k + 1) % loop.size()];
      area[l] += rulings_[a.ruling].lo * b.v - rulings_[b.ruling].lo * a.v;
    }
  }
  // The face lies left of its loops: the outer one (the largest) counter-clockwise in
  // (u, v), the others clockwise, whatever the wires stated.
  const size_t outer = size_t(std::max_element(area.begin(), area.end(), [](double a, double b) {
                                return std::fabs(a) < std::fabs(b);
                              }) - area.begin());
  for (size_t l = 0; l < loops.size(); ++l)
    if ((area[l] > 0) != (l == outer)) std::reverse(loops[l].begin(), loops[l].end());
  std::vector<std::array<uint32_t, 3>> tris;
  if (!faithful::ruled_strips(loops, uint32_t(rulings_.size()), tris, why)) return false;
  for (auto& t : tris) {
    if (reversed_face_) std::swap(t[1], t[2]);
    out.push_back({t[0], t[1], t[2]});
  }
  return true;
}

std::vector<std::vector<uint32_t>> RuledFace::ruling_points(Weld& weld) const {
  std::vector<std::vector<uint32_t>> out(rulings_.size());
  for (const auto& wire : wires_)
    for (const EdgeUse& use : wire) {
      if (use.degenerated || use.pcurve.IsNull()) continue;
      const std::vector<uint32_t>& points = weld.edge_points[use.edge];
      const std::vector<double>& params = weld.edge_params[use.edge];
      for (size_t k = 0; k < points.size(); ++k) {
        if (std::isnan(params[k])) continue;
        const int r = ruling_of(uv_of_node(weld, use, uint32_t(k)).first);
        if (r >= 0) out[r].push_back(weld.find(points[k]));
      }
    }
  for (auto& points : out) {
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
  }
  return out;
}

}  // namespace gvm::step_internal
