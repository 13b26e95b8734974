// gvm_brep_oracle: checks the GVMs of a STEP part's B-rep faces against rays on the B-rep
// itself -- Open CASCADE's intersector and solid classifier on the exact surfaces, not the
// mesh the engine analysed.
//
//   gvm_brep_oracle PART.stp... [--samples N] [--directions N] [--margin DEG] [--seed S] [--tilt DEG] [--verbose]
//
// For every feature (a B-rep face) points are sampled inside the face (a grid in its
// parameters, kept where the face's classifier says in), and from each a ray leaves along
// a direction u. The ray is blocked when some stretch of it between two crossings of the
// solid's boundary lies inside the solid (the classifier says IN at its middle, beyond the
// B-rep's tolerance): a ray that only grazes a face (along a hole's wall) is not blocked,
// as the paper's Def. 2 says. Directions tested:
//   - every point of the GVM and the middle of every arc: every ray must be free;
//   - random directions inside a 2-cell of the GVM by at least the margin: every ray free;
//   - random directions outside the GVM by at least the margin: some ray blocked;
//   - a feature with an empty GVM: the points and arcs of its own faces' LVM(S),
//     directions inside its 2-cells by the margin, and the B-rep's own axis (both ways)
//     or normal, each blocked for some ray (else the engine calls unreachable what the
//     B-rep shows reachable) -- unless what blocks it on the mesh are only B-rep faces
//     smaller than the depth a ray must go to count as blocked (slivers of a few
//     micrometres overhanging a wall: rays lifted off it pass beside them), which is
//     counted and printed as below the oracle's resolution.
// The margin (default: the tessellation's angular deflection) covers how far the mesh's
// facets turn from the B-rep's surfaces; points and arcs, which hold exactly in the mesh,
// get none. A direction outside the GVM whose rays the samples all find free is counted
// as unconfirmed when no sample lies where it is blocked, and printed with --verbose.
// --tilt turns every point and arc direction by that angle before testing it: a wrong GVM,
// to see that the oracle notices.
// Exit status: 0 no disagreement, 1 some, 2 usage or load errors.
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopoDS_Compound.hxx>
#include <IntCurvesFace_ShapeIntersector.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <Geom2d_Curve.hxx>
#include <gp_Vec2d.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Lin.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "gvm/analysis.h"
#include "gvm/analysis_proto.h"

namespace {

using Vec = std::array<double, 3>;
constexpr double kPi = 3.14159265358979323846;
constexpr double kLift = 1e-5;  // of the part's size

struct Options {
  int samples = 6;      // grid per parameter direction (more for faces that keep few)
  int directions = 6;   // random directions inside and outside each GVM
  double margin_deg = -1;
  uint64_t seed = 1;
  bool verbose = false;
  double tilt_deg = 0;  // turn the points and arcs by this much: a wrong GVM, to see it noticed
};

struct Counts {
  long points = 0, arcs = 0, inside = 0, outside = 0, outside_unconfirmed = 0, unreachable = 0, disagreements = 0;
  long below_lift = 0;
};

class Brep {
 public:
  bool load(const std::string& path) {
    STEPControl_Reader reader;
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return false;
    reader.TransferRoots();
    TopTools_IndexedMapOfShape solids;
    TopExp::MapShapes(reader.OneShape(), TopAbs_SOLID, solids);
    if (solids.Extent() < 1) return false;
    solid_ = solids(1);  // as the reader chooses it (gvm/step.h): the only solid
    TopExp::MapShapes(solid_, TopAbs_FACE, faces_);
    // The boundary as a compound of faces: a point's distance to it is its depth.
    BRep_Builder b;
    TopoDS_Compound boundary;
    b.MakeCompound(boundary);
    for (int i = 1; i <= faces_.Extent(); ++i) b.Add(boundary, faces_(i));
    shell_ = boundary;
    classifier_.Load(solid_);
    intersector_.Load(solid_, 1e-7);
    return true;
  }
  int faces() const { return faces_.Extent(); }
  // The diagonal of B-rep face f's bounding box.
  double extent(int f) const {
    Bnd_Box box;
    BRepBndLib::AddOptimal(faces_(f + 1), box, false, false);
    return box.IsVoid() ? 0 : std::sqrt(box.SquareExtent());
  }
  // How deep a ray must go into the solid to count as blocked (see blocked()).
  double depth_tolerance() const { return 10 * kLift * size_; }
  void set_size(double diagonal) { size_ = diagonal; }

  // Points inside face f: a grid in its parameter box, kept where the face's 2D classifier
  // says in, refined until there are a few; each lifted off the face by a hair along its
  // outward normal. A ray along the face itself (a hole's axis along its wall) then runs
  // beside it in the air, where the classifier can answer, and still meets anything that
  // blocks the face (a hole's bottom).
  std::vector<gp_Pnt> samples(int f, int grid) const {
    const TopoDS_Face& face = TopoDS::Face(faces_(f + 1));
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    BRepGProp_Face normals(face);
    BRepTopAdaptor_FClass2d inside(face, 1e-9);
    std::vector<gp_Pnt> out;
    auto add = [&](const gp_Pnt2d& uv) {
      if (inside.Perform(uv) != TopAbs_IN) return false;
      gp_Pnt p;
      gp_Vec normal;
      normals.Normal(uv.X(), uv.Y(), p, normal);
      if (normal.Magnitude() == 0) return false;
      out.push_back(p.Translated(normal.Normalized() * (kLift * size_)));
      return true;
    };
    for (int n = grid; n <= 8 * grid && out.size() < 8; n *= 2) {
      out.clear();
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) add(gp_Pnt2d(u0 + (u1 - u0) * (i + 0.5) / n, v0 + (v1 - v0) * (j + 0.5) / n));
    }
    // Beside every edge, just inside the face: where a neighbour across a concave edge
    // blocks, it blocks first.
    const double step = 1e-3 * std::max(u1 - u0, v1 - v0);
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
      const TopoDS_Edge& edge = TopoDS::Edge(ex.Current());
      if (BRep_Tool::Degenerated(edge)) continue;
      double first, last;
      const Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(edge, face, first, last);
      if (pc.IsNull()) continue;
      for (int k = 1; k < 2 * grid; ++k) {
        gp_Pnt2d uv;
        gp_Vec2d d;
        pc->D1(first + (last - first) * k / (2 * grid), uv, d);
        if (d.Magnitude() == 0) continue;
        const gp_Vec2d side = gp_Vec2d(-d.Y(), d.X()).Normalized() * step;
        if (!add(uv.Translated(side))) add(uv.Translated(-side));
      }
    }
    return out;
  }

  // Some stretch of the ray p + t u, t > 0, lies inside the solid.
  // Some stretch of the ray p + t u, t > 0, lies inside the solid, deeper than ten times
  // the lift (a ray lifted off a face and grazing a curved neighbour tangent to the face's
  // plane dips into it by no more than the lift: that is the lift, not a block).
  bool blocked(const gp_Pnt& p, const Vec& u) {
    const gp_Dir d(u[0], u[1], u[2]);
    const double tol = depth_tolerance(), far = 4 * size_;
    intersector_.Perform(gp_Lin(p, d), 1e-7 * size_, far);
    std::vector<double> t = {0};
    if (intersector_.IsDone())
      for (int i = 1; i <= intersector_.NbPnt(); ++i) t.push_back(intersector_.WParameter(i));
    t.push_back(far);
    std::sort(t.begin(), t.end());
    for (size_t i = 0; i + 1 < t.size(); ++i) {
      if (t[i + 1] - t[i] < tol) continue;
      const double m = 0.5 * (t[i] + t[i + 1]);
      const gp_Pnt q = p.Translated(gp_Vec(d) * m);
      classifier_.Perform(q, 1e-7 * size_);
      if (classifier_.State() != TopAbs_IN) continue;
      BRepExtrema_DistShapeShape depth(BRepBuilderAPI_MakeVertex(q).Vertex(), shell_);
      if (depth.IsDone() && depth.Value() > tol) return true;
    }
    return false;
  }

 private:
  TopoDS_Shape solid_, shell_;
  TopTools_IndexedMapOfShape faces_;
  BRepClass3d_SolidClassifier classifier_;
  IntCurvesFace_ShapeIntersector intersector_;
  double size_ = 1;
};

Vec unit(const Vec& v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

// u turned by `angle` towards a direction perpendicular to it.
Vec tilted(const Vec& u, double angle) {
  if (angle == 0) return u;
  const Vec a = std::fabs(u[0]) < 0.9 ? Vec{1, 0, 0} : Vec{0, 1, 0};
  const Vec p = unit({u[1] * a[2] - u[2] * a[1], u[2] * a[0] - u[0] * a[2], u[0] * a[1] - u[1] * a[0]});
  const double c = std::cos(angle), s = std::sin(angle);
  return unit({c * u[0] + s * p[0], c * u[1] + s * p[1], c * u[2] + s * p[2]});
}

double angle(const Vec& a, const Vec& b) {
  const Vec x = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  return std::atan2(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

// The point at angle t along the minor arc from a to b.
Vec along(const Vec& a, const Vec& b, double t) {
  const double w = angle(a, b);
  if (w == 0) return a;
  const double sa = std::sin(w - t) / std::sin(w), sb = std::sin(t) / std::sin(w);
  return unit({sa * a[0] + sb * b[0], sa * a[1] + sb * b[1], sa * a[2] + sb * b[2]});
}

// The directions of a GVM that must be free: its points, and on each arc the points at
// quarter lengths that are at least `margin` from its ends (where an arc ends, it grazes an
// occluder, whose facets the margin allows for; the arc itself lies in an exact plane).
std::vector<Vec> exact_cells(const gvm::DirectionSet& set, double margin, long& points, long& arcs) {
  gvm::v1::SphericalImage image;
  gvm::to_proto(set, &image);
  std::vector<Vec> out;
  for (const auto& p : image.points()) out.push_back({p.x(), p.y(), p.z()}), ++points;
  for (const auto& arc : image.arcs()) {
    std::vector<Vec> v;
    for (const auto& p : arc.vertices()) v.push_back({p.x(), p.y(), p.z()});
    double length = 0;
    for (size_t i = 0; i + 1 < v.size(); ++i) length += angle(v[i], v[i + 1]);
    ++arcs;
    for (double at : {0.25, 0.5, 0.75}) {
      double t = at * length;
      if (t < margin || length - t < margin) continue;
      for (size_t i = 0; i + 1 < v.size(); ++i) {
        const double w = angle(v[i], v[i + 1]);
        if (t <= w) {
          out.push_back(along(v[i], v[i + 1], t));
          break;
        }
        t -= w;
      }
    }
  }
  return out;
}

// The B-rep faces whose mesh faces keep u from the feature on the mesh: neighbours across
// its concave edges that face away from u, and the faces that rays along u cross. Empty
// when none is found.
std::vector<uint32_t> mesh_blockers(const gvm::Analysis& analysis, const gvm::Surface& f, const Vec& u) {
  const gvm::SolidMesh& mesh = analysis.mesh();
  std::vector<uint32_t> faces;
  for (uint32_t face : analysis.neighbor_faces(f.faces)) {
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
      if (mesh.triangle_face[t] != face) continue;
      const gvm::Point3 &a = mesh.points[mesh.triangles[t][0]], &b = mesh.points[mesh.triangles[t][1]],
                        &c = mesh.points[mesh.triangles[t][2]];
      const Vec e = {b.x - a.x, b.y - a.y, b.z - a.z}, g = {c.x - a.x, c.y - a.y, c.z - a.z};
      const Vec n = unit({e[1] * g[2] - e[2] * g[1], e[2] * g[0] - e[0] * g[2], e[0] * g[1] - e[1] * g[0]});
      if (n[0] * u[0] + n[1] * u[1] + n[2] * u[2] < -1e-12) faces.push_back(face);
    }
  }
  const std::vector<uint32_t> crossed = analysis.blocking_faces(f.faces, gvm::Direction(u[0], u[1], u[2]));
  faces.insert(faces.end(), crossed.begin(), crossed.end());
  std::vector<uint32_t> out;
  for (const gvm::Surface& other : analysis.features()) {
    if (!other.cad_face) continue;
    for (uint32_t face : faces) {
      if (std::binary_search(other.faces.begin(), other.faces.end(), face)) {
        out.push_back(other.cad_face->index);
        break;
      }
    }
  }
  return out;
}

int check_part(const std::string& path, const Options& o, Counts& total) {
  gvm::AnalyzeRequest request;
  request.part_path = path;
  request.options.set_threads(2);
  auto analysis = gvm::analyze(request);
  if (!analysis.ok()) {
    std::fprintf(stderr, "%s: %s\n", path.c_str(), analysis.status().message().c_str());
    return 2;
  }
  Brep brep;
  if (!brep.load(path)) {
    std::fprintf(stderr, "%s: Open CASCADE cannot read it\n", path.c_str());
    return 2;
  }
  const gvm::PartSummary& part = analysis->part();
  brep.set_size(std::sqrt(std::pow(part.box_max.x - part.box_min.x, 2) + std::pow(part.box_max.y - part.box_min.y, 2) +
                          std::pow(part.box_max.z - part.box_min.z, 2)));
  const double margin = (o.margin_deg >= 0 ? o.margin_deg : part.angular_deflection_degrees) * kPi / 180;
  std::mt19937_64 rng(o.seed);
  std::normal_distribution<double> g;
  Counts c;
  for (const gvm::Surface& f : analysis->features()) {
    if (!f.cad_face || !f.maps.gvm) continue;
    const std::vector<gp_Pnt> pts = brep.samples(int(f.cad_face->index), o.samples);
    if (pts.empty()) continue;
    auto free_from_all = [&](const Vec& u) {
      for (const gp_Pnt& p : pts)
        if (brep.blocked(p, u)) return false;
      return true;
    };
    auto disagree = [&](const char* what, const Vec& u) {
      ++c.disagreements;
      std::printf("%s: %s: %s (%.6f, %.6f, %.6f)\n", path.c_str(), f.name.c_str(), what, u[0], u[1], u[2]);
    };
    for (const Vec& cell : exact_cells(*f.maps.gvm, margin, c.points, c.arcs)) {
      const Vec u = tilted(cell, o.tilt_deg * kPi / 180);
      if (!free_from_all(u)) disagree("GVM point or arc blocked on the B-rep", u);
    }
    // An empty GVM: the directions its own faces allow must all be blocked on the B-rep
    // too, or the part is reachable where the engine says it is not (a false undercut).
    // The B-rep's own candidates as well: a cylinder's or cone's axis both ways, a plane's
    // normal (an own LVM the mesh made empty by facets that lean would offer none).
    if (f.maps.gvm->is_empty()) {
      std::vector<Vec> candidates;
      const gvm::StatusOr<gvm::DirectionSet> own = analysis->own_lvm(f.faces);
      if (own.ok() && !own->is_empty()) {
        long ignored = 0;
        candidates = exact_cells(*own, margin, ignored, ignored);
        for (int k = 0; k < 200 && candidates.size() < 12; ++k) {
          const Vec u = unit({g(rng), g(rng), g(rng)});
          if (own->approx_signed_clearance(u) >= margin) candidates.push_back(u);
        }
      }
      if (f.cad_face->axis) {
        const Vec a = unit(*f.cad_face->axis);
        candidates.push_back(a);
        if (f.cad_face->type != gvm::CadSurfaceType::kPlane) candidates.push_back({-a[0], -a[1], -a[2]});
      }
      for (const Vec& u : candidates) {
        ++c.unreachable;
        if (!free_from_all(u)) continue;
        // Rays lifted off the face cannot meet what overhangs it by less than the lift: a
        // mesh blocked only by B-rep faces smaller than the depth that counts is below
        // what this oracle resolves (a CAD sliver), not a disagreement.
        const std::vector<uint32_t> blockers = mesh_blockers(*analysis, f, u);
        const bool tiny = !blockers.empty() && std::all_of(blockers.begin(), blockers.end(), [&](uint32_t b) {
          return brep.extent(int(b)) <= brep.depth_tolerance();
        });
        if (!tiny) {
          disagree("unreachable, but the B-rep sees it", u);
          for (uint32_t b : blockers) std::printf("    blocked on the mesh by face %u (%.3g mm)\n", b, brep.extent(int(b)));
          continue;
        }
        ++c.below_lift;
        std::printf("%s: %s: unreachable along (%.6f, %.6f, %.6f), blocked on the mesh only by B-rep faces smaller "
                    "than the oracle resolves (%.3g mm):", path.c_str(), f.name.c_str(), u[0], u[1], u[2],
                    brep.depth_tolerance());
        for (uint32_t b : blockers) std::printf(" face %u (%.3g mm)", b, brep.extent(int(b)));
        std::printf("\n");
      }
    }
    int inside = 0, outside = 0;
    for (int tries = 0; tries < 400 && (inside < o.directions || outside < o.directions); ++tries) {
      const Vec u = unit({g(rng), g(rng), g(rng)});
      const double clearance = f.maps.gvm->approx_signed_clearance(u);
      if (clearance >= margin && inside < o.directions) {
        ++inside, ++c.inside;
        if (!free_from_all(u)) disagree("inside the GVM but blocked on the B-rep", u);
      } else if (clearance <= -margin && outside < o.directions) {
        ++outside, ++c.outside;
        if (free_from_all(u)) {
          ++c.outside_unconfirmed;
          if (o.verbose)
            std::printf("%s: %s: outside the GVM, no sample blocked (%.6f, %.6f, %.6f)\n", path.c_str(), f.name.c_str(),
                        u[0], u[1], u[2]);
        }
      }
    }
  }
  std::printf("%s: %zu features, %ld points, %ld arcs, %ld directions inside, %ld outside (%ld unconfirmed), %ld of "
              "unreachable features (%ld below the oracle's resolution): %ld disagreements\n",
              path.c_str(), analysis->features().size(), c.points, c.arcs, c.inside, c.outside, c.outside_unconfirmed,
              c.unreachable, c.below_lift, c.disagreements);
  total.points += c.points, total.arcs += c.arcs, total.inside += c.inside, total.outside += c.outside;
  total.outside_unconfirmed += c.outside_unconfirmed, total.unreachable += c.unreachable;
  total.disagreements += c.disagreements, total.below_lift += c.below_lift;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  std::vector<std::string> parts;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--samples") o.samples = std::atoi(next());
    else if (a == "--directions") o.directions = std::atoi(next());
    else if (a == "--margin") o.margin_deg = std::atof(next());
    else if (a == "--seed") o.seed = std::strtoull(next(), nullptr, 10);
    else if (a == "--verbose") o.verbose = true;
    else if (a == "--tilt") o.tilt_deg = std::atof(next());
    else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "unknown option %s\n", a.c_str());
      return 2;
    } else parts.push_back(a);
  }
  if (parts.empty()) {
    std::fprintf(stderr, "usage: gvm_brep_oracle PART.stp... [--samples N] [--directions N] [--margin DEG] [--seed S] [--tilt DEG] [--verbose]\n");
    return 2;
  }
  Counts total;
  for (const std::string& p : parts)
    if (int s = check_part(p, o, total); s != 0) return s;
  std::printf("all: %ld points, %ld arcs, %ld inside, %ld outside (%ld unconfirmed), %ld of unreachable features (%ld "
              "below the oracle's resolution): %ld disagreements\n",
              total.points, total.arcs, total.inside, total.outside, total.outside_unconfirmed, total.unreachable,
              total.below_lift, total.disagreements);
  return total.disagreements == 0 ? 0 : 1;
}
