#include "support/test_parts.h"

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <numeric>

namespace gvm::test {
namespace {

using I3 = std::array<int64_t, 3>;

// A part as a union of cells of a rectilinear grid (cell (i, j, k) spans
// [xs[i], xs[i+1]] x [ys[j], ys[j+1]] x [zs[k], zs[k+1]]). Boundary faces are cell faces,
// so the surface is conforming without T-junctions.
struct GridModel {
  std::string name;
  std::vector<int64_t> g[3];
  std::function<bool(int, int, int)> filled;
  std::map<std::string, std::string> rename;
  // Optional exact move of grid vertices (in the part's units) before scaling, e.g. to
  // draft walls; must keep every planar face planar and convex.
  std::function<void(I3&)> move;
};

constexpr int64_t kScale = 12;

I3 rotate(const I3& p, int rotation) {
  if (rotation == 0) return p;
  // M = [[3,4,0],[-4,3,0],[0,0,5]]
  I3 q{3 * p[0] + 4 * p[1], -4 * p[0] + 3 * p[1], 5 * p[2]};
  if (rotation == 1) return q;
  // Rx = [[5,0,0],[0,3,4],[0,-4,3]]
  return {5 * q[0], 3 * q[1] + 4 * q[2], -4 * q[1] + 3 * q[2]};
}

struct Quad {
  int axis, dir;
  int plane;                 // grid index of the face's plane along axis
  int cu, cv;                // cell indices along axes (axis+1)%3, (axis+2)%3
  std::array<I3, 4> corners; // grid indices, counter-clockwise seen from outside
};

// A grid vertex where the model puts it (before scaling).
I3 placed(const GridModel& gm, const I3& gi) {
  I3 p{gm.g[0][gi[0]], gm.g[1][gi[1]], gm.g[2][gi[2]]};
  if (gm.move) gm.move(p);
  return p;
}

// Whether two quads still lie in one plane once the model's move has bent its walls.
bool coplanar_after_move(const GridModel& gm, const Quad& a, const Quad& b) {
  const I3 o = placed(gm, a.corners[0]);
  auto d = [&](const I3& gi) {
    const I3 p = placed(gm, gi);
    return I3{p[0] - o[0], p[1] - o[1], p[2] - o[2]};
  };
  const I3 u = d(a.corners[1]), v = d(a.corners[3]);
  const I3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  for (const auto* q : {&a, &b}) {
    for (const I3& c : q->corners) {
      const I3 w = d(c);
      if (n[0] * w[0] + n[1] * w[1] + n[2] * w[2] != 0) return false;
    }
  }
  return true;
}

RawMesh build(const GridModel& gm, const TestPartOptions& o) {
  const int n[3] = {static_cast<int>(gm.g[0].size()) - 1, static_cast<int>(gm.g[1].size()) - 1,
                    static_cast<int>(gm.g[2].size()) - 1};
  auto inside = [&](int i, int j, int k) {
    return i >= 0 && j >= 0 && k >= 0 && i < n[0] && j < n[1] && k < n[2] && gm.filled(i, j, k);
  };
  std::vector<Quad> quads;
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) {
        if (!inside(i, j, k)) continue;
        const int c[3] = {i, j, k};
        for (int a = 0; a < 3; ++a)
          for (int dir : {-1, 1}) {
            int nc[3] = {i, j, k};
            nc[a] += dir;
            if (inside(nc[0], nc[1], nc[2])) continue;
            const int u = (a + 1) % 3, v = (a + 2) % 3;
            Quad q;
            q.axis = a, q.dir = dir, q.plane = c[a] + (dir > 0 ? 1 : 0);
            q.cu = c[u], q.cv = c[v];
            auto corner = [&](int du, int dv) {
              I3 p;
              p[a] = q.plane;
              p[u] = c[u] + du;
              p[v] = c[v] + dv;
              return p;
            };
            if (dir > 0)
              q.corners = {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
            else
              q.corners = {corner(0, 0), corner(0, 1), corner(1, 1), corner(1, 0)};
            quads.push_back(q);
          }
      }

  // Maximal planar faces: coplanar, equally oriented quads sharing an edge.
  std::vector<uint32_t> comp(quads.size());
  std::iota(comp.begin(), comp.end(), 0u);
  std::function<uint32_t(uint32_t)> find = [&](uint32_t x) {
    return comp[x] == x ? x : comp[x] = find(comp[x]);
  };
  std::map<std::array<int, 5>, uint32_t> at;
  for (uint32_t q = 0; q < quads.size(); ++q)
    at[{quads[q].axis, quads[q].dir, quads[q].plane, quads[q].cu, quads[q].cv}] = q;
  for (uint32_t q = 0; q < quads.size(); ++q) {
    const Quad& Q = quads[q];
    for (auto [du, dv] : {std::pair{1, 0}, std::pair{0, 1}}) {
      auto it = at.find({Q.axis, Q.dir, Q.plane, Q.cu + du, Q.cv + dv});
      if (it != at.end() && !coplanar_after_move(gm, Q, quads[it->second])) continue;
      if (it != at.end()) {
        uint32_t a = find(q), b = find(it->second);
        if (a != b) comp[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  // Names: "<axis><sign><coordinate>", suffixed when several faces share a plane.
  std::map<uint32_t, std::string> base_of_root;
  std::map<std::string, std::vector<uint32_t>> roots_of_base;
  for (uint32_t q = 0; q < quads.size(); ++q) {
    uint32_t r = find(q);
    if (base_of_root.count(r)) continue;
    const Quad& Q = quads[r];
    std::string base = std::string(1, "xyz"[Q.axis]) + (Q.dir > 0 ? "+" : "-") +
                       std::to_string(gm.g[Q.axis][Q.plane]);
    base_of_root[r] = base;
    roots_of_base[base].push_back(r);
  }
  std::map<uint32_t, std::string> name_of_root;
  for (const auto& [base, roots] : roots_of_base)
    for (size_t i = 0; i < roots.size(); ++i) {
      std::string nm = roots.size() == 1 ? base : base + "_" + std::to_string(i);
      auto it = gm.rename.find(nm);
      name_of_root[roots[i]] = it == gm.rename.end() ? nm : it->second;
    }

  RawMesh raw;
  raw.source = gm.name;
  std::map<I3, uint32_t> vid;
  std::vector<I3> pts;  // scaled, unrotated
  auto vertex = [&](const I3& gi) {
    auto it = vid.find(gi);
    if (it != vid.end()) return it->second;
    I3 p{gm.g[0][gi[0]], gm.g[1][gi[1]], gm.g[2][gi[2]]};
    if (gm.move) gm.move(p);
    for (auto& c : p) c *= kScale;
    uint32_t id = static_cast<uint32_t>(pts.size());
    pts.push_back(p);
    vid.emplace(gi, id);
    return id;
  };
  for (uint32_t q = 0; q < quads.size(); ++q) {
    std::array<uint32_t, 4> v;
    for (int i = 0; i < 4; ++i) v[i] = vertex(quads[q].corners[i]);
    auto& group = raw.groups[name_of_root[find(q)]];
    auto emit = [&](std::vector<uint32_t> f) {
      group.push_back(static_cast<uint32_t>(raw.faces.size()));
      raw.faces.push_back(std::move(f));
    };
    if (o.split) {
      I3 c{0, 0, 0};
      for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k) c[k] += pts[v[i]][k];
      for (auto& x : c) x /= 4;  // exact: coordinates are multiples of 12
      uint32_t ci = static_cast<uint32_t>(pts.size());
      pts.push_back(c);
      for (int i = 0; i < 4; ++i) emit({v[i], v[(i + 1) % 4], ci});
    } else if (o.quads) {
      emit({v[0], v[1], v[2], v[3]});
    } else {
      emit({v[0], v[1], v[2]});
      emit({v[0], v[2], v[3]});
    }
  }
  for (const I3& p : pts) {
    I3 r = rotate(p, o.rotation);
    raw.points.push_back({static_cast<double>(r[0]), static_cast<double>(r[1]),
                          static_cast<double>(r[2])});
  }
  return raw;
}

std::map<std::string, std::string> pocket_walls(int x0, int x1, int y0, int y1) {
  auto s = [](int v) { return std::to_string(v); };
  return {{"x+" + s(x0), "wall_x0"}, {"x-" + s(x1), "wall_x1"},
          {"y+" + s(y0), "wall_y0"}, {"y-" + s(y1), "wall_y1"}};
}

GridModel pocket_model() {
  GridModel m;
  m.name = "pocket";
  m.g[0] = {0, 4, 8, 12};
  m.g[1] = {0, 4, 8, 12};
  m.g[2] = {0, 4, 8};
  m.filled = [](int i, int j, int k) { return !(i == 1 && j == 1 && k == 1); };
  m.rename = pocket_walls(4, 8, 4, 8);
  m.rename["z+4"] = "floor";
  m.rename["z+8"] = "top";
  return m;
}

GridModel tslot_model(bool closed) {
  GridModel m;
  m.name = closed ? "tslot_closed" : "tslot_open";
  m.g[0] = {0, 3, 5, 7, 9, 12};
  m.g[1] = closed ? std::vector<int64_t>{0, 2, 8, 10} : std::vector<int64_t>{0, 10};
  m.g[2] = {0, 2, 5, 8};
  m.filled = [closed](int i, int j, int k) {
    if (closed && j != 1) return true;
    bool wide = k == 1 && i >= 1 && i <= 3;
    bool neck = k == 2 && i == 2;
    return !(wide || neck);
  };
  m.rename = {{"z+2", "floor"},         {"z-5_0", "lip_underside_0"},
              {"z-5_1", "lip_underside_1"}, {"x+3", "wall_x0"},
              {"x-9", "wall_x1"},       {"x+5", "neck_x0"},
              {"x-7", "neck_x1"},       {"y+2", "end_y0"},
              {"y-8", "end_y1"}};
  return m;
}

}  // namespace

RawMesh box_part(const TestPartOptions& o) {
  GridModel m;
  m.name = "box";
  m.g[0] = {0, 10};
  m.g[1] = {0, 6};
  m.g[2] = {0, 4};
  m.filled = [](int, int, int) { return true; };
  m.rename = {{"z+4", "top"}, {"z-0", "bottom"}};
  return build(m, o);
}

RawMesh slot_part(const TestPartOptions& o) {
  GridModel m;
  m.name = "slot";
  m.g[0] = {0, 4, 8, 12};
  m.g[1] = {0, 10};
  m.g[2] = {0, 4, 8};
  m.filled = [](int i, int, int k) { return !(i == 1 && k == 1); };
  m.rename = {{"z+4", "floor"}, {"x+4", "wall_x0"}, {"x-8", "wall_x1"}};
  return build(m, o);
}

// A slot whose walls have a groove at mid-height (x 3..9, z 6..8): the upper walls are
// exactly in the planes of the lower ones.
RawMesh grooved_slot_part(const TestPartOptions& o) {
  GridModel m;
  m.name = "grooved_slot";
  m.g[0] = {0, 3, 4, 8, 9, 12};
  m.g[1] = {0, 10};
  m.g[2] = {0, 4, 6, 8, 10};
  m.filled = [](int i, int, int k) {
    const bool slot = i == 2 && k >= 1;
    const bool groove = k == 2 && i >= 1 && i <= 3;
    return !(slot || groove);
  };
  m.rename = {{"z+4", "floor"}, {"x+4_0", "lower_x0"}, {"x-8_0", "lower_x1"},
              {"x+4_1", "upper_x0"}, {"x-8_1", "upper_x1"}};
  return build(m, o);
}

RawMesh through_hole_part(const TestPartOptions& o) {
  GridModel m;
  m.name = "through_hole";
  m.g[0] = {0, 4, 8, 12};
  m.g[1] = {0, 4, 8, 12};
  m.g[2] = {0, 6};
  m.filled = [](int i, int j, int) { return !(i == 1 && j == 1); };
  m.rename = pocket_walls(4, 8, 4, 8);
  return build(m, o);
}

RawMesh pocket_part(const TestPartOptions& o) { return build(pocket_model(), o); }

RawMesh drafted_pocket_part(const TestPartOptions& o) {
  GridModel m = pocket_model();
  m.name = "drafted_pocket";
  // Depth 4, walls lean out by 1: the pocket's top rim corners move out by 1 in x and y.
  m.move = [](I3& p) {
    if (p[2] != 8) return;
    if ((p[0] == 4 || p[0] == 8) && (p[1] == 4 || p[1] == 8)) {
      p[0] += p[0] == 4 ? -1 : 1;
      p[1] += p[1] == 4 ? -1 : 1;
    }
  };
  return build(m, o);
}

GridModel grooved_pocket_model() {
  GridModel m;
  m.name = "grooved_pocket";
  m.g[0] = {0, 3, 4, 8, 9, 12};
  m.g[1] = {0, 3, 4, 8, 9, 12};
  m.g[2] = {0, 4, 6, 8, 10};
  m.filled = [](int i, int j, int k) {
    const bool bore = i == 2 && j == 2 && k >= 1;
    const bool groove = k == 2 && i >= 1 && i <= 3 && j >= 1 && j <= 3;
    return !(bore || groove);
  };
  m.rename = {{"z+4", "floor"},          {"z+6", "groove_floor"}, {"z-8", "groove_ceiling"},
              {"z+10", "top"},           {"x+4_0", "lower_x0"},   {"x-8_0", "lower_x1"},
              {"y+4_0", "lower_y0"},     {"y-8_0", "lower_y1"},   {"x+4_1", "upper_x0"},
              {"x-8_1", "upper_x1"},     {"y+4_1", "upper_y0"},   {"y-8_1", "upper_y1"}};
  // The bottom's grid lines under the pocket walls move inwards, so that rays running
  // down along the walls leave through the inside of a bottom triangle, not along an edge.
  m.move = [](I3& p) {
    if (p[2] != 0) return;
    for (int k = 0; k < 2; ++k) {
      if (p[k] == 4) p[k] = 5;
      else if (p[k] == 8) p[k] = 7;
    }
  };
  return m;
}

RawMesh grooved_pocket_part(const TestPartOptions& o) { return build(grooved_pocket_model(), o); }

RawMesh grooved_pocket_rim_vertex_part(const TestPartOptions& o) {
  GridModel m = grooved_pocket_model();
  m.name = "grooved_pocket_rim_vertex";
  m.g[1] = {0, 3, 4, 6, 8, 9, 12};  // a grid line at y = 6: index j shifts by one above it
  m.filled = [](int i, int j, int k) {
    const bool bore = i == 2 && j >= 2 && j <= 3 && k >= 1;
    const bool groove = k == 2 && i >= 1 && i <= 3 && j >= 1 && j <= 4;
    return !(bore || groove);
  };
  m.move = [bottom = m.move](I3& p) {
    bottom(p);
    if (p[0] == 4 && p[1] == 6 && (p[2] == 4 || p[2] == 6)) p[1] = 5;
  };
  return build(m, o);
}

// Zero clearance: the walls lean out by 1 from the floor up to z = 6 and back in to the
// opening at z = 8, which has exactly the floor's outline (x and y in [4, 8]).
GridModel flared_pocket_model() {
  GridModel m = pocket_model();
  m.name = "flared_pocket";
  m.g[2] = {0, 4, 6, 8};
  m.filled = [](int i, int j, int k) { return !(i == 1 && j == 1 && k >= 1); };
  m.rename = {{"z+4", "floor"},     {"z+8", "top"},       {"x+4_0", "lower_x0"}, {"x-8_0", "lower_x1"},
              {"y+4_0", "lower_y0"}, {"y-8_0", "lower_y1"}, {"x+4_1", "upper_x0"}, {"x-8_1", "upper_x1"},
              {"y+4_1", "upper_y0"}, {"y-8_1", "upper_y1"}};
  m.move = [](I3& p) {
    if (p[2] != 6) return;
    if ((p[0] == 4 || p[0] == 8) && (p[1] == 4 || p[1] == 8)) {
      p[0] += p[0] == 4 ? -1 : 1;
      p[1] += p[1] == 4 ? -1 : 1;
    }
  };
  return m;
}

// A slot along y, through the part, whose walls lean out by 2 from the floor up to z = 6
// and back in to a mouth exactly as wide as its floor (x in [4, 8]). With `boss`, a block
// stands on the top beside the mouth, its face flush with the mouth's edge at x = 4.
GridModel flared_slot_model(bool boss) {
  GridModel m;
  m.name = boss ? "flared_slot_boss" : "flared_slot";
  m.g[0] = {0, 4, 8, 12};
  m.g[1] = {0, 10};
  m.g[2] = boss ? std::vector<int64_t>{0, 4, 6, 8, 10} : std::vector<int64_t>{0, 4, 6, 8};
  m.filled = [](int i, int, int k) { return !(i == 1 && k >= 1) && !(k == 3 && i != 0); };
  m.rename = {{"z+4", "floor"}, {"x+4_0", "lower_x0"}, {"x-8_0", "lower_x1"},
              {"x+4_1", "upper_x0"}, {"x-8_1", "upper_x1"}, {"x+4_2", "boss_side"}};
  m.move = [](I3& p) {
    if (p[2] == 6 && (p[0] == 4 || p[0] == 8)) p[0] += p[0] == 4 ? -2 : 2;
  };
  return m;
}

RawMesh step_part(const TestPartOptions& o) {
  GridModel m;
  m.name = "step";
  m.g[0] = {0, 6, 12};
  m.g[1] = {0, 10};
  m.g[2] = {0, 4, 8};
  m.filled = [](int i, int, int k) { return !(i == 1 && k == 1); };
  m.rename = {{"z+4", "step_floor"}, {"x+6", "riser"}, {"z+8", "top"}};
  return build(m, o);
}

RawMesh flared_pocket_part(const TestPartOptions& o) { return build(flared_pocket_model(), o); }
RawMesh flared_slot_part(const TestPartOptions& o) { return build(flared_slot_model(false), o); }
RawMesh flared_slot_boss_part(const TestPartOptions& o) { return build(flared_slot_model(true), o); }

RawMesh tslot_closed_part(const TestPartOptions& o) { return build(tslot_model(true), o); }
RawMesh tslot_open_part(const TestPartOptions& o) { return build(tslot_model(false), o); }

RawMesh two_pockets_part(const TestPartOptions& o) {
  GridModel m;
  m.name = "two_pockets";
  m.g[0] = {0, 3, 6, 9, 12, 15};
  m.g[1] = {0, 3, 6, 9};
  m.g[2] = {0, 3, 6};
  m.filled = [](int i, int j, int k) { return !(k == 1 && j == 1 && (i == 1 || i == 3)); };
  m.rename = {{"z+3_0", "floor_0"},    {"z+3_1", "floor_1"},    {"x+3", "p0_wall_x0"},
              {"x-6", "p0_wall_x1"},   {"x+9", "p1_wall_x0"},   {"x-12", "p1_wall_x1"},
              {"y+3_0", "p0_wall_y0"}, {"y+3_1", "p1_wall_y0"}, {"y-6_0", "p0_wall_y1"},
              {"y-6_1", "p1_wall_y1"}, {"z+6", "top"}};
  return build(m, o);
}

RawMesh pocket_with_void_part(const TestPartOptions& o) {
  GridModel m;
  m.name = "pocket_with_void";
  m.g[0] = {0, 3, 6, 9, 12, 15};
  m.g[1] = {0, 3, 6, 9};
  m.g[2] = {0, 3, 6, 9};
  m.filled = [](int i, int j, int k) {
    return !(j == 1 && ((i == 1 && k == 2) || (i == 3 && k == 1)));
  };
  m.rename = {{"z+6", "floor"},         {"x+3", "wall_x0"},     {"x-6", "wall_x1"},
              {"y+3_0", "wall_y0"},     {"y-6_0", "wall_y1"},   {"z+9", "top"},
              {"x+9", "void_x0"},       {"x-12", "void_x1"},    {"y+3_1", "void_y0"},
              {"y-6_1", "void_y1"},     {"z+3", "void_z0"},     {"z-6", "void_z1"}};
  return build(m, o);
}

RawMesh machined_block_part(const TestPartOptions& o) {
  GridModel m;
  m.name = "machined_block";
  m.g[0] = {0, 2, 6, 10, 14, 16};
  m.g[1] = {0, 4, 5, 7, 8, 12};
  m.g[2] = {0, 2, 4, 6, 7, 10};
  m.filled = [](int i, int j, int k) {
    const bool hole = j >= 1 && j <= 3 && k == 1;        // y 4..8, z 2..4, all along x
    const bool pocket = i == 1 && j == 2 && k >= 3;      // x 2..6, y 5..7, z 6..10
    const bool slot = i == 3 && k == 4;                  // x 10..14, z 7..10, all along y
    return !(hole || pocket || slot);
  };
  m.rename = {{"y+4", "hole_y0"},     {"y-8", "hole_y1"},       {"z+2", "hole_floor"},
              {"z-4", "hole_ceiling"}, {"z+6", "pocket_floor"},  {"x+2", "pocket_x0"},
              {"x-6", "pocket_x1"},   {"y+5", "pocket_y0"},     {"y-7", "pocket_y1"},
              {"z+7", "slot_floor"},  {"x+10", "slot_x0"},      {"x-14", "slot_x1"},
              {"z-0", "bottom"}};
  return build(m, o);
}

Point3 rotated(const TestPartOptions& o, const Point3& p) {
  const I3 q = rotate({static_cast<int64_t>(p.x), static_cast<int64_t>(p.y), static_cast<int64_t>(p.z)},
                      o.rotation);
  return {double(q[0]), double(q[1]), double(q[2])};
}

std::vector<NamedTestPart> all_test_parts() {
  return {{"box", box_part},
          {"slot", slot_part},
          {"through_hole", through_hole_part},
          {"pocket", pocket_part},
          {"drafted_pocket", drafted_pocket_part},
          {"grooved_slot", grooved_slot_part},
          {"grooved_pocket", grooved_pocket_part},
          {"grooved_pocket_rim_vertex", grooved_pocket_rim_vertex_part},
          {"flared_pocket", flared_pocket_part},
          {"flared_slot", flared_slot_part},
          {"flared_slot_boss", flared_slot_boss_part},
          {"step", step_part},
          {"tslot_closed", tslot_closed_part},
          {"tslot_open", tslot_open_part},
          {"two_pockets", two_pockets_part},
          {"pocket_with_void", pocket_with_void_part},
          {"machined_block", machined_block_part}};
}

std::vector<uint32_t> faces_of(const RawMesh& raw, std::initializer_list<std::string> names) {
  std::vector<uint32_t> out;
  for (const std::string& n : names) {
    auto it = raw.groups.find(n);
    if (it != raw.groups.end()) out.insert(out.end(), it->second.begin(), it->second.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<uint32_t> triangles_of_faces(const SolidMesh& mesh, const std::vector<uint32_t>& faces) {
  std::vector<uint32_t> out;
  for (uint32_t t = 0; t < mesh.triangles.size(); ++t)
    if (std::binary_search(faces.begin(), faces.end(), mesh.triangle_face[t])) out.push_back(t);
  return out;
}

std::vector<uint32_t> triangles_of(const SolidMesh& mesh, const RawMesh& raw,
                                   std::initializer_list<std::string> names) {
  return triangles_of_faces(mesh, faces_of(raw, names));
}

}  // namespace gvm::test
