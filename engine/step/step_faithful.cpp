// The faithful tessellation (make_faithful in step_internal.h): BRepMesh's triangulation
// rebuilt so that what the B-rep says exactly holds exactly in the mesh.
//
//   1. The B-rep's directions -- plane normals, cylinder and extrusion axes -- get integer
//      vectors and frames (faithful/exact_directions.h).
//   2. Ruled faces (cylinders, cones, extrusions) are meshed along their rulings: points
//      are added on their edges until every boundary segment joins neighbouring rulings
//      (a hole's two rims, discretised apart by BRepMesh, then have points at the same
//      angles), and the face is cut between the rulings (faithful/ruled_strips.h).
//   3. Every point is moved onto integer lattices so that each planar face is exactly on
//      one plane of its class and each ruling exactly on one line along its axis
//      (faithful/lattice_placement.h).
//   4. Planar faces that got new edge points are triangulated again from their boundary
//      (faithful/planar_triangulation.h), exactly, on the moved points; other faces that
//      did keep BRepMesh's triangles, those along a changed edge cut into fans.
// A ruled face whose boundary does not allow rulings keeps BRepMesh's triangles, and the
// report says which and why.
#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_Curve.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <tuple>

#include "sphere/union_find.h"
#include "step/faithful/exact_directions.h"
#include "step/faithful/lattice_placement.h"
#include "step/faithful/planar_triangulation.h"
#include "step/step_ruled.h"

namespace gvm::step_internal {
namespace {

using faithful::IVec;

constexpr int kInsertionRounds = 8;
// Boundary points of a ruled face whose rulings lie closer than this share one ruling
// (mm, relative to the linear deflection): BRepMesh puts the end points of neighbouring
// edges at angles that differ in the last bits.
constexpr double kRulingTolerance = 1e-6, kRulingCap = 1e-4;
// A grid step is 2^-kGridBits of the part's largest coordinate.
constexpr int kGridBits = 50;

enum class Kind { kPlane, kRuled, kOther };

struct FaceInfo {
  Kind kind = Kind::kOther;
  int direction = -1;  // index into the directions given to exact_directions
  gp_Pnt plane_point;
  gp_Dir outward;      // planes: the outward normal
};

faithful::Dir3 dir3(const gp_Dir& d) { return {d.X(), d.Y(), d.Z()}; }

std::vector<FaceInfo> classify(const TopTools_IndexedMapOfShape& faces, std::vector<faithful::Dir3>& dirs,
                               std::vector<uint32_t>& weights) {
  std::vector<FaceInfo> out(faces.Extent());
  for (int i = 1; i <= faces.Extent(); ++i) {
    BRepAdaptor_Surface s(TopoDS::Face(faces(i)), /*R=*/false);
    FaceInfo& info = out[i - 1];
    auto with_direction = [&](const gp_Dir& d, uint32_t weight) {
      info.direction = int(dirs.size());
      dirs.push_back(dir3(d));
      weights.push_back(weight);
    };
    switch (s.GetType()) {
      case GeomAbs_Plane:
        info.kind = Kind::kPlane;
        info.plane_point = s.Plane().Location();
        // X x Y of the plane's frame is the surface normal (minus the main direction when the
        // frame is left-handed).
        info.outward = s.Plane().Position().XDirection().Crossed(s.Plane().Position().YDirection());
        if (faces(i).Orientation() == TopAbs_REVERSED) info.outward.Reverse();
        with_direction(s.Plane().Axis().Direction(), 1);
        break;
      case GeomAbs_Cylinder:
        info.kind = Kind::kRuled;
        with_direction(s.Cylinder().Axis().Direction(), 2);  // rulings: kept first
        break;
      case GeomAbs_SurfaceOfExtrusion:
        info.kind = Kind::kRuled;
        with_direction(s.Direction(), 2);
        break;
      case GeomAbs_Cone: info.kind = Kind::kRuled; break;
      default: break;
    }
  }
  return out;
}

// What make_faithful changes, to start again from it.
struct Snapshot {
  std::vector<std::vector<uint32_t>> edge_points;
  std::vector<std::vector<double>> edge_params;
  std::vector<Point3> points;
  std::vector<uint32_t> parent;
  std::vector<Polygons> per_face;
};

class Faithful {
 public:
  Faithful(const TopTools_IndexedMapOfShape& faces, double linear, Weld& weld, std::vector<Polygons>& per_face,
           StepPart& part)
      : faces_(faces), linear_(linear), weld_(weld), per_face_(per_face), part_(part), n_(uint32_t(faces.Extent())) {}

  // Attempts until no face has to be left to BRepMesh: a ruled face whose rulings would make
  // a planar neighbour's boundary cross itself (a sliver between two close arcs, where a
  // point added on one arc cuts across the other) is left out, and everything starts again.
  Status run() {
    std::vector<faithful::Dir3> dirs;
    std::vector<uint32_t> weights;
    info_ = classify(faces_, dirs, weights);
    directions_ = faithful::exact_directions(dirs, weights);
    const Snapshot start{weld_.edge_points, weld_.edge_params, weld_.mesh->points, weld_.parent, per_face_};
    for (uint32_t attempt = 0;; ++attempt) {
      std::map<uint32_t, std::string> demote;
      const size_t forced = forced_.size();
      const faithful::Placement placement = attempt_once(demote);
      if ((demote.empty() && forced_.size() == forced) || attempt == 2 * n_) {
        finish(placement);
        return Status::Ok();
      }
      if (forced_.size() == forced) {
        demoted_.insert(demote.begin(), demote.end());
        std::erase_if(forced_, [&](const EdgeInsertion& i) { return demoted_.count(i.face) > 0; });
      }
      weld_.edge_points = start.edge_points;
      weld_.edge_params = start.edge_params;
      weld_.mesh->points = start.points;
      weld_.parent = start.parent;
      per_face_ = start.per_face;
    }
  }

 private:
  const TopoDS_Face& face(uint32_t f) const { return TopoDS::Face(faces_(int(f) + 1)); }

  faithful::Placement attempt_once(std::map<uint32_t, std::string>& demote) {
    before_ = edge_chains(weld_);
    asked_by_.clear();
    std::vector<EdgeInsertion> forced = forced_;
    inserted_ = insert_points(forced, weld_, asked_by_);
    mesh_ruled_faces();
    faithful::Placement placement = place();
    merge_coincident(placement);
    triangulate_planes(placement, demote);
    return placement;
  }

  void finish(const faithful::Placement& placement) {
    split_other_faces();
    report(placement);
  }

  // Adds edge points until every ruled face's rulings meet all of its boundary. Faces
  // whose rulings keep asking for more (a ruled face crossing another on another axis: each
  // one's points make new rulings of the other) are left to BRepMesh one by one, the one
  // asking most first, and the points added so far taken back.
  void add_ruling_points() {
    const auto points = weld_.edge_points;
    const auto params = weld_.edge_params;
    const size_t mesh_points = weld_.mesh->points.size(), parents = weld_.parent.size();
    size_t budget = 0;
    for (const auto& chain : points) budget += chain.size();
    for (;;) {
      std::vector<uint32_t> asked(n_, 0);
      uint32_t added = 0, total = 0;
      for (int round = 0; round < kInsertionRounds; ++round) {
        std::vector<EdgeInsertion> insertions;
        for (uint32_t f = 0; f < n_; ++f) {
          if (!ruled_[f]) continue;
          const size_t before = insertions.size();
          ruled_[f]->find_rulings(weld_);
          ruled_[f]->insertions(weld_, f, insertions);
          asked[f] = uint32_t(insertions.size() - before);
        }
        added = insert_points(insertions, weld_, asked_by_);
        total += added;
        if (added == 0 || total > 2 * budget) break;
      }
      if (added == 0) {
        inserted_ += total;
        break;
      }
      const uint32_t worst = uint32_t(std::max_element(asked.begin(), asked.end()) - asked.begin());
      ruled_[worst].reset();
      demoted_[worst] = "its rulings and those of the ruled faces it meets never close up (each adds rulings to the other)";
      weld_.edge_points = points;
      weld_.edge_params = params;
      weld_.mesh->points.resize(mesh_points);
      weld_.parent.resize(parents);
      asked_by_.clear();
    }
    for (uint32_t f = 0; f < n_; ++f)
      if (ruled_[f]) ruled_[f]->find_rulings(weld_);
  }

  void mesh_ruled_faces() {
    ruled_.clear();
    ruled_.resize(n_);
    for (uint32_t f = 0; f < n_; ++f)
      if (info_[f].kind == Kind::kRuled && !demoted_.count(f))
        ruled_[f] = std::make_unique<RuledFace>(face(f), weld_, kRulingTolerance * linear_, kRulingCap * linear_);
    add_ruling_points();
    stripped_.assign(n_, false);
    strip_failures_.clear();
    for (uint32_t f = 0; f < n_; ++f) {
      if (!ruled_[f]) continue;
      Polygons tris;
      std::string why;
      if (ruled_[f]->strips(weld_, tris, why)) {
        per_face_[f] = std::move(tris);
        stripped_[f] = true;
      } else {
        strip_failures_[f] = why;
      }
    }
  }

  faithful::PlacementProblem problem() {
    faithful::PlacementProblem p;
    p.directions = &directions_;
    p.target.reserve(weld_.mesh->points.size());
    double largest = 0;
    for (const Point3& q : weld_.mesh->points) {
      p.target.push_back({q.x, q.y, q.z});
      largest = std::max({largest, std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)});
    }
    int e = 0;
    std::frexp(largest, &e);
    p.grid_exponent = e - kGridBits;
    for (uint32_t f = 0; f < n_; ++f) {
      if (info_[f].kind != Kind::kPlane) continue;
      faithful::PlacementProblem::Plane plane;
      plane.cls = directions_.class_of[info_[f].direction];
      plane.point = {info_[f].plane_point.X(), info_[f].plane_point.Y(), info_[f].plane_point.Z()};
      plane.face = f;
      std::set<uint32_t> points;
      for (const auto& poly : per_face_[f])
        for (uint32_t q : poly) points.insert(weld_.find(q));
      for (const auto& wire : face_wires(face(f), weld_))
        for (const EdgeUse& use : wire)
          for (uint32_t q : weld_.edge_points[use.edge]) points.insert(weld_.find(q));
      plane.points.assign(points.begin(), points.end());
      p.planes.push_back(std::move(plane));
    }
    add_rulings(p);
    return p;
  }

  // One ruling per line: the rulings of faces of one class that share a point are one
  // (the two halves of a hole's wall meet on two of them).
  void add_rulings(faithful::PlacementProblem& p) {
    struct Group {
      uint32_t cls, face;
      std::vector<uint32_t> points;
    };
    std::vector<Group> groups;
    for (uint32_t f = 0; f < n_; ++f) {
      if (!stripped_[f] || info_[f].direction < 0) continue;
      const uint32_t cls = directions_.class_of[info_[f].direction];
      for (auto& points : ruled_[f]->ruling_points(weld_)) groups.push_back({cls, f, std::move(points)});
    }
    sphere::UnionFind uf(groups.size());
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> first;
    for (uint32_t g = 0; g < groups.size(); ++g)
      for (uint32_t q : groups[g].points) {
        auto [it, fresh] = first.emplace(std::pair{groups[g].cls, q}, g);
        if (!fresh) uf.unite(g, it->second);
      }
    std::map<uint32_t, uint32_t> ruling_of_root;
    for (uint32_t g = 0; g < groups.size(); ++g) {
      const uint32_t root = uf.find(g);
      auto [it, fresh] = ruling_of_root.emplace(root, uint32_t(p.rulings.size()));
      if (fresh) p.rulings.push_back({groups[g].cls, {}, groups[g].face});
      auto& points = p.rulings[it->second].points;
      points.insert(points.end(), groups[g].points.begin(), groups[g].points.end());
    }
    for (auto& r : p.rulings) {
      std::sort(r.points.begin(), r.points.end());
      r.points.erase(std::unique(r.points.begin(), r.points.end()), r.points.end());
    }
  }

  faithful::Placement place() {
    const faithful::PlacementProblem p = problem();
    faithful::Placement placement = faithful::place_on_lattices(p);
    grid_exponent_ = p.grid_exponent;
    for (size_t q = 0; q < placement.grid.size(); ++q) {
      const IVec& g = placement.grid[q];
      weld_.mesh->points[q] = {std::ldexp(double(g.x), grid_exponent_), std::ldexp(double(g.y), grid_exponent_),
                               std::ldexp(double(g.z), grid_exponent_)};
    }
    return placement;
  }

  // The face's boundary loops projected along `drop`, counter-clockwise seen from outside:
  // the outer one (the largest) turning as the outward normal says, the others the other way.
  std::vector<faithful::PlanarLoop> plane_loops(uint32_t f, int drop, const faithful::Placement& placement) {
    std::vector<faithful::PlanarLoop> loops;
    std::vector<faithful::i128> area;
    std::vector<std::vector<EdgeUse>> wires = face_wires(face(f), weld_);
    for (const auto& boundary : boundary_loops(wires, weld_, /*by_uv=*/false)) {
      faithful::PlanarLoop loop;
      for (const LoopPoint& p : boundary) {
        const IVec& g = placement.grid[p.id];
        const int64_t c[3] = {g.x, g.y, g.z};
        loop.ids.push_back(p.id);
        loop.xy.push_back({c[(drop + 1) % 3], c[(drop + 2) % 3]});
      }
      faithful::i128 a = 0;
      for (size_t k = 0; k < loop.xy.size(); ++k) {
        const auto &p = loop.xy[k], &q = loop.xy[(k + 1) % loop.xy.size()];
        a += faithful::i128(p[0]) * q[1] - faithful::i128(q[0]) * p[1];
      }
      area.push_back(a < 0 ? -a : a);
      if ((a > 0) != (info_[f].outward.Coord(drop + 1) > 0)) {
        std::reverse(loop.ids.begin(), loop.ids.end());
        std::reverse(loop.xy.begin(), loop.xy.end());
      }
      loops.push_back(std::move(loop));
    }
    // Every loop now turns as the outward normal says; the holes turn back.
    const size_t outer = size_t(std::max_element(area.begin(), area.end()) - area.begin());
    for (size_t l = 0; l < loops.size(); ++l)
      if (l != outer) {
        std::reverse(loops[l].ids.begin(), loops[l].ids.end());
        std::reverse(loops[l].xy.begin(), loops[l].xy.end());
      }
    std::swap(loops[0], loops[outer]);
    return loops;
  }

  // Planar faces that got new edge points (or none from BRepMesh) triangulated from their
  // boundary. One whose boundary the added points make cross itself asks for the ruled
  // faces that added them to be left out.
  void triangulate_planes(const faithful::Placement& placement, std::map<uint32_t, std::string>& demote) {
    planes_done_.assign(n_, false);
    planar_failures_.clear();
    for (uint32_t f = 0; f < n_; ++f) {
      if (info_[f].kind != Kind::kPlane) continue;
      if (!per_face_[f].empty() && !touches_splits(face(f), weld_, before_)) continue;
      const IVec& n = directions_.classes[directions_.class_of[info_[f].direction]].exact;
      int drop = 0;
      for (int k = 1; k < 3; ++k)
        if (std::llabs(n[k]) > std::llabs(n[drop])) drop = k;
      const std::vector<faithful::PlanarLoop> loops = plane_loops(f, drop, placement);
      std::vector<std::array<uint32_t, 3>> tris;
      std::string why;
      if (faithful::triangulate_planar(loops, tris, why)) {
        per_face_[f].clear();
        for (const auto& t : tris) per_face_[f].push_back({t[0], t[1], t[2]});
        planes_done_[f] = true;
        continue;
      }
      planar_failures_[f] = why;
      if (!companions_tried_.count(f) && add_companions(f, loops)) continue;
      // One at a time, so that a face whose partner across the sliver is left out can stay.
      for (const auto& loop : loops)
        for (uint32_t q : loop.ids)
          if (auto it = asked_by_.find(q); it != asked_by_.end() && !demoted_.count(it->second) && demote.empty())
            demote[it->second] = "its rulings put points on the boundary of face " + std::to_string(f) +
                                 " (a plane) that make it cross itself";
    }
  }

  // A thin planar face (a crescent between two arcs that touch) whose boundary the added
  // points make cross itself: each added point gets a companion on the face's other edges
  // nearby (closer than the deflection), so that both sides of the sliver have points
  // across from each other and their chords do not cross. True when any was found; they are
  // added from the next attempt on.
  bool add_companions(uint32_t f, const std::vector<faithful::PlanarLoop>& loops) {
    companions_tried_.insert(f);
    std::vector<std::vector<EdgeUse>> wires = face_wires(face(f), weld_);
    bool any = false;
    for (const auto& loop : loops)
      for (uint32_t q : loop.ids) {
        if (!asked_by_.count(q)) continue;
        const Point3& p = weld_.mesh->points[q];
        for (const auto& wire : wires)
          for (const EdgeUse& use : wire) {
            const std::vector<uint32_t>& chain = weld_.edge_points[use.edge];
            if (use.degenerated || std::find(chain.begin(), chain.end(), q) != chain.end()) continue;
            const TopoDS_Edge& edge = TopoDS::Edge(weld_.edges(use.edge + 1));
            double first, last;
            const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
            if (curve.IsNull()) continue;
            gp_Pnt at(p.x, p.y, p.z);
            if (!edge.Location().IsIdentity()) at.Transform(edge.Location().Transformation().Inverted());
            GeomAPI_ProjectPointOnCurve projection(at, curve, first, last);
            if (projection.NbPoints() == 0 || projection.LowerDistance() > linear_) continue;
            const double t = projection.LowerDistanceParameter();
            if (t <= first || t >= last) continue;
            forced_.push_back({use.edge, t, asked_by_.at(q)});
            any = true;
          }
      }
    return any;
  }

  void split_other_faces() {
    const Splits splits = splits_of(before_, weld_);
    if (splits.empty()) return;
    for (uint32_t f = 0; f < n_; ++f)
      if (!stripped_[f] && !planes_done_[f] && !per_face_[f].empty()) per_face_[f] = fan_split(per_face_[f], splits, weld_);
  }

  // Points the lattices put at one place are one point.
  void merge_coincident(const faithful::Placement& placement) {
    std::map<std::array<int64_t, 3>, uint32_t> at;
    for (uint32_t q = 0; q < placement.grid.size(); ++q) {
      if (weld_.find(q) != q) continue;
      const IVec& g = placement.grid[q];
      auto [it, fresh] = at.emplace(std::array<int64_t, 3>{g.x, g.y, g.z}, q);
      if (!fresh) weld_.unite(it->second, q);
    }
  }

  void report(const faithful::Placement& placement) {
    StepTessellation& t = part_.tessellation;
    t.faithful = true;
    t.grid = std::ldexp(1.0, grid_exponent_);
    t.inserted_points = inserted_;
    t.max_node_displacement = placement.max_displacement_mm;
    t.ruled_faces = uint32_t(std::count(stripped_.begin(), stripped_.end(), true));
    std::vector<uint32_t> faces_of(directions_.classes.size(), 0);
    for (const FaceInfo& i : info_)
      if (i.direction >= 0) ++faces_of[directions_.class_of[i.direction]];
    for (size_t c = 0; c < directions_.classes.size(); ++c) {
      const faithful::DirectionClass& cls = directions_.classes[c];
      t.directions.push_back({cls.brep, {cls.exact.x, cls.exact.y, cls.exact.z}, cls.angle, faces_of[c]});
      t.max_direction_angle = std::max(t.max_direction_angle, cls.angle);
    }
    for (const faithful::Miss& m : placement.misses) t.inexact.push_back({m.face, m.ruling, m.points, m.distance_mm});
    std::map<uint32_t, std::string> left = demoted_;
    for (auto& [f, why] : strip_failures_) left[f] = why;
    for (auto& [f, why] : planar_failures_) left[f] = "planar triangulation: " + why;
    t.brepmesh_faces.assign(left.begin(), left.end());
  }

  const TopTools_IndexedMapOfShape& faces_;
  double linear_;
  Weld& weld_;
  std::vector<Polygons>& per_face_;
  StepPart& part_;
  uint32_t n_;
  std::vector<FaceInfo> info_;
  faithful::ExactDirections directions_;
  std::vector<std::vector<uint32_t>> before_;
  std::vector<std::unique_ptr<RuledFace>> ruled_;
  std::vector<bool> stripped_, planes_done_;
  std::map<uint32_t, std::string> demoted_, strip_failures_, planar_failures_;
  std::map<uint32_t, uint32_t> asked_by_;  // added point -> the face whose rulings asked for it
  std::vector<EdgeInsertion> forced_;      // companions across thin planar faces
  std::set<uint32_t> companions_tried_;
  uint32_t inserted_ = 0;
  int grid_exponent_ = 0;
};

}  // namespace

Status make_faithful(const TopoDS_Shape& /*solid*/, const TopTools_IndexedMapOfShape& faces, double linear,
                     Weld& weld, std::vector<Polygons>& per_face, StepPart& part) {
  return Faithful(faces, linear, weld, per_face, part).run();
}

}  // namespace gvm::step_internal
