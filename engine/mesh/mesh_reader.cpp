// Reading OFF, OBJ, STL (ASCII and binary) and PLY into a RawMesh with the exact doubles
// of the file.
//
// Why not OpenMesh's readers: measured with OpenMesh 9.0 through a recording importer
// (tests/support/openmesh_recording_importer.h, see MeshReader.OpenMeshReadersDeliverFloatsOnly in
// tests/mesh_reader_test.cpp), every reader -- ASCII OFF, OBJ, PLY (even with `property
// double`) and ASCII STL -- hands the importer Vec3f, so 0.1 arrives as 0.100000001490116,
// 1e-300 as 0 and 1e12 as 999999995904. The OBJ reader also silently drops faces with a
// repeated vertex index, the STL reader drops degenerate (collapsed) facets, and no reader
// passes OBJ groups to the importer. A validator must see the file as it is, so the four
// formats are parsed here (numbers with std::from_chars: exact, locale independent).
// Binary STL is float32 by format; those floats are exact as doubles. A binary STL whose
// header starts with "solid" is recognised by its size (84 + 50 * facet count).
#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "gvm/mesh.h"

namespace gvm {
namespace {

constexpr uint64_t kMaxFaces = 50'000'000;
constexpr uint64_t kMaxVertices = 150'000'000;

Status Bad(const std::string& path, const std::string& what) {
  return InvalidArgument(path + ": " + what);
}

// Line/token cursor over the whole file.
class Cursor {
 public:
  explicit Cursor(std::string_view s) : s_(s) {}
  bool eof() const { return p_ >= s_.size(); }
  // Next line (without the line break); false at end.
  bool line(std::string_view& out) {
    if (p_ >= s_.size()) return false;
    size_t e = s_.find('\n', p_);
    if (e == std::string_view::npos) e = s_.size();
    out = s_.substr(p_, e - p_);
    if (!out.empty() && out.back() == '\r') out.remove_suffix(1);
    p_ = e + 1;
    ++line_no_;
    return true;
  }
  size_t line_no() const { return line_no_; }

 private:
  std::string_view s_;
  size_t p_ = 0;
  size_t line_no_ = 0;
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

// The tokens of a line into `t`, whose capacity is kept: the OFF reader splits a line per
// vertex and face (286 k lines in occt_brep_Bottom.off), one allocation each before.
void split_into(std::string_view l, std::vector<std::string_view>& t) {
  t.clear();
  size_t i = 0;
  while (i < l.size()) {
    while (i < l.size() && is_space(l[i])) ++i;
    size_t b = i;
    while (i < l.size() && !is_space(l[i])) ++i;
    if (i > b) t.push_back(l.substr(b, i - b));
  }
}

std::vector<std::string_view> split(std::string_view l) {
  std::vector<std::string_view> t;
  split_into(l, t);
  return t;
}

bool parse_double(std::string_view t, double& v) {
  if (!t.empty() && t[0] == '+') t.remove_prefix(1);
  auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  return r.ec == std::errc() && r.ptr == t.data() + t.size();
}

template <class I>
bool parse_int(std::string_view t, I& v) {
  if (!t.empty() && t[0] == '+') t.remove_prefix(1);
  auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  return r.ec == std::errc() && r.ptr == t.data() + t.size();
}

std::string lower(std::string s) {
  for (auto& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string shortest(double d) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, d);
  return std::string(buf, r.ptr);
}

// Every coordinate finite, before any geometry; the message names the vertex (input
// numbering), the coordinate and the first face using it. The magnitude of finite
// coordinates is analyze()'s business (it scales the part exactly, see mesh/exact_scale.h).
Status check_coordinates(const RawMesh& m) {
  for (size_t i = 0; i < m.points.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      const double c = m.points[i][a];
      if (std::isfinite(c)) continue;
      std::string value = std::string(1, "xyz"[a]) + " = " + shortest(c);
      for (size_t f = 0; f < m.faces.size(); ++f) {
        if (std::find(m.faces[f].begin(), m.faces[f].end(), uint32_t(i)) != m.faces[f].end()) {
          value += ", in face " + std::to_string(f);
          break;
        }
      }
      return Bad(m.source, "vertex " + std::to_string(i) + " has a non-finite coordinate (" + value + ")");
    }
  }
  return Status::Ok();
}

// Collapses vertices with exactly equal coordinates onto the first one, renumbering the
// survivors in input order.
Status weld(RawMesh& m) {
  struct H {
    size_t operator()(const Point3& p) const {
      auto b = [](double d) { return std::bit_cast<uint64_t>(d == 0 ? 0.0 : d); };
      uint64_t h = b(p.x) * 0x9E3779B97F4A7C15ull;
      h ^= b(p.y) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
      h ^= b(p.z) + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
      return size_t(h);
    }
  };
  std::unordered_map<Point3, uint32_t, H> first;
  first.reserve(m.points.size());
  std::vector<uint32_t> remap(m.points.size());
  std::vector<Point3> kept;
  kept.reserve(m.points.size());
  for (size_t i = 0; i < m.points.size(); ++i) {
    auto [it, inserted] = first.emplace(m.points[i], uint32_t(kept.size()));
    if (inserted) kept.push_back(m.points[i]);
    remap[i] = it->second;
  }
  if (kept.size() == m.points.size()) return Status::Ok();
  m.points = std::move(kept);
  for (auto& f : m.faces)
    for (auto& v : f) v = remap[v];
  return Status::Ok();
}

Status check_indices(const RawMesh& m) {
  for (size_t f = 0; f < m.faces.size(); ++f)
    for (uint32_t v : m.faces[f])
      if (v >= m.points.size())
        return Bad(m.source, "face " + std::to_string(f) + " refers to vertex " +
                                 std::to_string(v) + ", but the file has only " +
                                 std::to_string(m.points.size()) + " vertices");
  return Status::Ok();
}

// ---------------------------------------------------------------- OFF
Status read_off(std::string_view s, RawMesh& m) {
  Cursor c(s);
  std::vector<std::string_view> tok;  // pending header tokens
  std::string_view l;
  auto next_tokens = [&](std::vector<std::string_view>& out) {
    while (c.line(l)) {
      size_t h = l.find('#');
      if (h != std::string_view::npos) l = l.substr(0, h);
      split_into(l, out);
      if (!out.empty()) return true;
    }
    return false;
  };
  if (!next_tokens(tok)) return Bad(m.source, "empty OFF file");
  std::string_view head = tok[0];
  if (head.size() < 3 || head.substr(head.size() - 3) != "OFF")
    return Bad(m.source, "not an OFF file (no OFF header)");
  // ST/C/N prefixes add values after x y z on each vertex line; those are ignored.
  if (head.find('4') != std::string_view::npos || head.find('n') == 0)
    return Bad(m.source, "unsupported OFF variant '" + std::string(head) + "'");
  tok.erase(tok.begin());
  if (!tok.empty() && tok[0] == "BINARY") return Bad(m.source, "binary OFF is not supported");
  if (tok.empty() && !next_tokens(tok)) return Bad(m.source, "OFF header without counts");
  uint64_t nv = 0, nf = 0;
  if (tok.size() < 2 || !parse_int(tok[0], nv) || !parse_int(tok[1], nf))
    return Bad(m.source, "bad OFF counts line");
  // A vertex line holds at least "x y z" and a line break, a face line at least its count
  // and a line break: counts the bytes cannot hold are refused before anything is reserved.
  if (nv > s.size() / 6 + 1 || nf > s.size() / 2 + 1)
    return Bad(m.source, "the OFF header declares " + std::to_string(nv) + " vertices and " +
                             std::to_string(nf) + " faces, more than the " +
                             std::to_string(s.size()) + " bytes of the file can hold");
  if (nf > kMaxFaces || nv > kMaxVertices)
    return ResourceExhausted(m.source + ": " + std::to_string(nf) + " faces / " +
                             std::to_string(nv) + " vertices exceeds the limit");
  m.points.reserve(nv);
  for (uint64_t i = 0; i < nv; ++i) {
    if (!next_tokens(tok)) return Bad(m.source, "OFF file ends inside the vertex list");
    Point3 p;
    if (tok.size() < 3 || !parse_double(tok[0], p.x) || !parse_double(tok[1], p.y) ||
        !parse_double(tok[2], p.z))
      return Bad(m.source, "bad coordinates for vertex " + std::to_string(i) + " (line " +
                               std::to_string(c.line_no()) + ")");
    m.points.push_back(p);
  }
  m.faces.reserve(nf);
  for (uint64_t i = 0; i < nf; ++i) {
    if (!next_tokens(tok)) return Bad(m.source, "OFF file ends inside the face list");
    uint32_t n = 0;
    if (!parse_int(tok[0], n) || tok.size() < size_t(n) + 1)
      return Bad(m.source, "bad face " + std::to_string(i) + " (line " +
                               std::to_string(c.line_no()) + ")");
    std::vector<uint32_t> f(n);
    for (uint32_t k = 0; k < n; ++k)
      if (!parse_int(tok[k + 1], f[k]))
        return Bad(m.source, "bad vertex index in face " + std::to_string(i));
    m.faces.push_back(std::move(f));
  }
  return Status::Ok();
}

// ---------------------------------------------------------------- OBJ
Status read_obj(std::string_view s, RawMesh& m) {
  Cursor c(s);
  std::string_view l;
  std::vector<std::string> current;  // active group names
  while (c.line(l)) {
    size_t h = l.find('#');
    if (h != std::string_view::npos) l = l.substr(0, h);
    auto tok = split(l);
    if (tok.empty()) continue;
    if (tok[0] == "v") {
      Point3 p;
      if (tok.size() < 4 || !parse_double(tok[1], p.x) || !parse_double(tok[2], p.y) ||
          !parse_double(tok[3], p.z))
        return Bad(m.source, "bad vertex on line " + std::to_string(c.line_no()));
      if (m.points.size() >= kMaxVertices) return ResourceExhausted(m.source + ": too many vertices");
      m.points.push_back(p);
    } else if (tok[0] == "f") {
      std::vector<uint32_t> f;
      for (size_t k = 1; k < tok.size(); ++k) {
        std::string_view t = tok[k].substr(0, tok[k].find('/'));
        int64_t i = 0;
        if (!parse_int(t, i) || i == 0)
          return Bad(m.source, "bad face index on line " + std::to_string(c.line_no()));
        int64_t n = int64_t(m.points.size());
        int64_t idx = i > 0 ? i - 1 : n + i;
        if (idx < 0 || idx >= n)
          return Bad(m.source, "face on line " + std::to_string(c.line_no()) +
                                   " refers to an undefined vertex " + std::string(t));
        f.push_back(uint32_t(idx));
      }
      if (m.faces.size() >= kMaxFaces) return ResourceExhausted(m.source + ": more than 50 million faces");
      for (const auto& g : current) m.groups[g].push_back(uint32_t(m.faces.size()));
      m.faces.push_back(std::move(f));
    } else if (tok[0] == "g") {
      current.clear();
      for (size_t k = 1; k < tok.size(); ++k)
        if (tok[k] != "default") current.emplace_back(tok[k]);
    }
  }
  return Status::Ok();
}

// ---------------------------------------------------------------- STL
Status read_stl(std::string_view s, RawMesh& m) {
  size_t first = 0;
  while (first < s.size() && is_space(s[first])) ++first;
  const bool starts_solid = s.substr(first, 5) == "solid";
  uint32_t n = 0;
  bool binary = false;
  if (s.size() >= 84) {
    std::memcpy(&n, s.data() + 80, 4);  // little endian by format (host is little endian)
    binary = 84 + 50 * uint64_t(n) == s.size();
  }
  if (binary) {
    if (n > kMaxFaces) return ResourceExhausted(m.source + ": more than 50 million facets");
    m.points.reserve(3 * size_t(n));  // n matches the size of the file
    m.faces.reserve(n);
    for (uint32_t i = 0; i < n; ++i) {
      const char* r = s.data() + 84 + 50 * size_t(i) + 12;
      std::vector<uint32_t> f(3);
      for (int k = 0; k < 3; ++k) {
        float c[3];
        std::memcpy(c, r + 12 * k, 12);
        f[k] = uint32_t(m.points.size());
        m.points.push_back({double(c[0]), double(c[1]), double(c[2])});
      }
      m.faces.push_back(std::move(f));
    }
    return Status::Ok();
  }
  if (!starts_solid) {
    if (s.size() < 84)
      return Bad(m.source, "neither ASCII STL (no 'solid') nor binary STL (" +
                               std::to_string(s.size()) + " bytes, shorter than the 84-byte header)");
    return Bad(m.source, "neither ASCII STL (no 'solid') nor binary STL (the header declares " +
                             std::to_string(n) + " facets, " + std::to_string(84 + 50 * uint64_t(n)) +
                             " bytes, but the file has " + std::to_string(s.size()) + " bytes)");
  }
  Cursor c(s);
  std::string_view l;
  std::vector<uint32_t> f;
  bool in_facet = false;
  while (c.line(l)) {
    auto tok = split(l);
    if (tok.empty()) continue;
    if (tok[0] == "facet") {
      in_facet = true;
      f.clear();
    } else if (tok[0] == "vertex") {
      Point3 p;
      if (!in_facet || tok.size() < 4 || !parse_double(tok[1], p.x) ||
          !parse_double(tok[2], p.y) || !parse_double(tok[3], p.z))
        return Bad(m.source, "bad vertex on line " + std::to_string(c.line_no()));
      if (m.points.size() >= kMaxVertices) return ResourceExhausted(m.source + ": too many vertices");
      f.push_back(uint32_t(m.points.size()));
      m.points.push_back(p);
    } else if (tok[0] == "endfacet") {
      if (!in_facet) return Bad(m.source, "'endfacet' without 'facet' on line " + std::to_string(c.line_no()));
      if (m.faces.size() >= kMaxFaces) return ResourceExhausted(m.source + ": more than 50 million facets");
      m.faces.push_back(f);
      in_facet = false;
    }
  }
  if (in_facet) return Bad(m.source, "ASCII STL ends inside facet " + std::to_string(m.faces.size()));
  return Status::Ok();
}

// ---------------------------------------------------------------- PLY
enum class PType { kI8, kU8, kI16, kU16, kI32, kU32, kF32, kF64, kBad };

PType ptype(std::string_view t) {
  if (t == "char" || t == "int8") return PType::kI8;
  if (t == "uchar" || t == "uint8") return PType::kU8;
  if (t == "short" || t == "int16") return PType::kI16;
  if (t == "ushort" || t == "uint16") return PType::kU16;
  if (t == "int" || t == "int32") return PType::kI32;
  if (t == "uint" || t == "uint32") return PType::kU32;
  if (t == "float" || t == "float32") return PType::kF32;
  if (t == "double" || t == "float64") return PType::kF64;
  return PType::kBad;
}
size_t psize(PType t) {
  switch (t) {
    case PType::kI8: case PType::kU8: return 1;
    case PType::kI16: case PType::kU16: return 2;
    case PType::kI32: case PType::kU32: case PType::kF32: return 4;
    case PType::kF64: return 8;
    default: return 0;
  }
}

struct PlyProp {
  std::string name;
  bool list = false;
  PType count_type = PType::kBad, type = PType::kBad;
};
struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProp> props;
};

class PlyValues {
 public:
  PlyValues(std::string_view body, int format) : b_(body), fmt_(format) {}
  // Reads one value of type t as a double (integers up to 32 bits are exact in a double).
  bool read(PType t, double& v) {
    if (fmt_ == 0) {
      while (p_ < b_.size() && is_space(b_[p_])) ++p_;
      size_t e = p_;
      while (e < b_.size() && !is_space(b_[e])) ++e;
      if (e == p_) return false;
      bool ok = parse_double(b_.substr(p_, e - p_), v);
      p_ = e;
      return ok;
    }
    size_t n = psize(t);
    if (p_ + n > b_.size()) return false;
    unsigned char raw[8];
    std::memcpy(raw, b_.data() + p_, n);
    p_ += n;
    if (fmt_ == 2) std::reverse(raw, raw + n);  // big endian file on a little-endian host
    switch (t) {
      case PType::kI8: { int8_t x; std::memcpy(&x, raw, 1); v = x; break; }
      case PType::kU8: { uint8_t x; std::memcpy(&x, raw, 1); v = x; break; }
      case PType::kI16: { int16_t x; std::memcpy(&x, raw, 2); v = x; break; }
      case PType::kU16: { uint16_t x; std::memcpy(&x, raw, 2); v = x; break; }
      case PType::kI32: { int32_t x; std::memcpy(&x, raw, 4); v = x; break; }
      case PType::kU32: { uint32_t x; std::memcpy(&x, raw, 4); v = x; break; }
      case PType::kF32: { float x; std::memcpy(&x, raw, 4); v = x; break; }
      case PType::kF64: { double x; std::memcpy(&x, raw, 8); v = x; break; }
      default: return false;
    }
    return true;
  }

 private:
  std::string_view b_;
  int fmt_;  // 0 ascii, 1 binary little endian, 2 binary big endian
  size_t p_ = 0;
};

Status read_ply(std::string_view s, RawMesh& m) {
  Cursor c(s);
  std::string_view l;
  if (!c.line(l) || split(l).empty() || split(l)[0] != "ply") return Bad(m.source, "not a PLY file");
  int format = -1;
  std::vector<PlyElement> elements;
  size_t body = std::string_view::npos;
  while (c.line(l)) {
    auto tok = split(l);
    if (tok.empty()) continue;
    if (tok[0] == "format" && tok.size() >= 2) {
      if (tok[1] == "ascii") format = 0;
      else if (tok[1] == "binary_little_endian") format = 1;
      else if (tok[1] == "binary_big_endian") format = 2;
      else return Bad(m.source, "unknown PLY format " + std::string(tok[1]));
    } else if (tok[0] == "element" && tok.size() >= 3) {
      PlyElement e;
      e.name = tok[1];
      if (!parse_int(tok[2], e.count)) return Bad(m.source, "bad PLY element count");
      if (elements.size() >= 1000) return Bad(m.source, "more than 1000 PLY elements");
      elements.push_back(e);
    } else if (tok[0] == "property" && !elements.empty()) {
      PlyProp p;
      if (tok.size() >= 5 && tok[1] == "list") {
        p.list = true;
        p.count_type = ptype(tok[2]);
        p.type = ptype(tok[3]);
        p.name = tok[4];
        if (p.count_type == PType::kBad || p.type == PType::kBad)
          return Bad(m.source, "unknown PLY property type");
      } else if (tok.size() >= 3) {
        p.type = ptype(tok[1]);
        p.name = tok[2];
        if (p.type == PType::kBad) return Bad(m.source, "unknown PLY property type " + std::string(tok[1]));
      } else {
        return Bad(m.source, "bad PLY property line");
      }
      elements.back().props.push_back(p);
    } else if (tok[0] == "end_header") {
      body = size_t(l.data() - s.data()) + l.size();
      // skip the rest of this line (the \r\n or \n after end_header)
      while (body < s.size() && s[body] != '\n') ++body;
      if (body < s.size()) ++body;
      break;
    }
  }
  if (format < 0 || body == std::string_view::npos) return Bad(m.source, "incomplete PLY header");
  PlyValues in(s.substr(body), format);
  const uint64_t body_bytes = s.size() - body;
  for (const auto& e : elements) {
    bool is_v = e.name == "vertex", is_f = e.name == "face";
    if (e.props.empty()) continue;  // holds no data, whatever its count
    // Each element takes at least one byte per value (binary: the size of each scalar and
    // list count; ASCII: a character and a separator): counts the bytes cannot hold are
    // refused before the loop.
    uint64_t min_bytes = 0;
    for (const auto& p : e.props) min_bytes += format == 0 ? 2 : psize(p.list ? p.count_type : p.type);
    if (e.count > (body_bytes + 1) / min_bytes)
      return Bad(m.source, "the PLY header declares " + std::to_string(e.count) + " elements '" + e.name +
                               "', more than the " + std::to_string(body_bytes) +
                               " bytes after the header can hold");
    if (is_f && e.count > kMaxFaces) return ResourceExhausted(m.source + ": more than 50 million faces");
    if (is_v && e.count > kMaxVertices) return ResourceExhausted(m.source + ": too many vertices");
    int ix = -1, iy = -1, iz = -1, iface = -1;
    for (size_t k = 0; k < e.props.size(); ++k) {
      const auto& p = e.props[k];
      if (is_v && !p.list && p.name == "x") ix = int(k);
      if (is_v && !p.list && p.name == "y") iy = int(k);
      if (is_v && !p.list && p.name == "z") iz = int(k);
      if (is_f && p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) iface = int(k);
    }
    if (is_v && (ix < 0 || iy < 0 || iz < 0)) return Bad(m.source, "PLY vertex without x, y, z");
    if (is_f && iface < 0) return Bad(m.source, "PLY face without vertex_indices");
    for (uint64_t i = 0; i < e.count; ++i) {
      Point3 pt;
      std::vector<uint32_t> f;
      for (size_t k = 0; k < e.props.size(); ++k) {
        const auto& p = e.props[k];
        double v = 0;
        if (!p.list) {
          if (!in.read(p.type, v)) return Bad(m.source, "PLY data ends early in element " + e.name);
          if (int(k) == ix) pt.x = v;
          if (int(k) == iy) pt.y = v;
          if (int(k) == iz) pt.z = v;
          continue;
        }
        double cnt = 0;
        if (!in.read(p.count_type, cnt) || !(cnt >= 0) || cnt != std::floor(cnt) || cnt > 4294967295.0)
          return Bad(m.source, "bad PLY list length in element " + e.name);
        for (uint64_t j = 0; j < uint64_t(cnt); ++j) {
          if (!in.read(p.type, v)) return Bad(m.source, "PLY data ends early in element " + e.name);
          if (int(k) == iface) {
            if (v < 0 || v != std::floor(v) || v > 4294967295.0)
              return Bad(m.source, "bad vertex index in PLY face " + std::to_string(i));
            f.push_back(uint32_t(v));
          }
        }
      }
      if (is_v) m.points.push_back(pt);
      if (is_f) m.faces.push_back(std::move(f));
    }
  }
  return Status::Ok();
}

}  // namespace

std::optional<MeshFormat> parse_mesh_format(std::string_view name) {
  if (!name.empty() && name.front() == '.') name.remove_prefix(1);
  std::string ext = lower(std::string(name));
  if (ext == "stp" || ext == "step") return MeshFormat::kStep;
  if (ext == "off") return MeshFormat::kOff;
  if (ext == "obj") return MeshFormat::kObj;
  if (ext == "stl") return MeshFormat::kStl;
  if (ext == "ply") return MeshFormat::kPly;
  return std::nullopt;
}

StatusOr<RawMesh> read_raw_mesh(std::string_view bytes, MeshFormat format, const std::string& source) {
  RawMesh m;
  m.source = source;
  if (bytes.empty()) return InvalidArgument(source + ": empty file");
  Status st;
  switch (format) {
    case MeshFormat::kOff: st = read_off(bytes, m); break;
    case MeshFormat::kObj: st = read_obj(bytes, m); break;
    case MeshFormat::kStl: st = read_stl(bytes, m); break;
    case MeshFormat::kPly: st = read_ply(bytes, m); break;
    case MeshFormat::kStep: return InvalidArgument(source + ": a STEP part is a B-rep, not a mesh (read_step tessellates it)");
    default: return InvalidArgument(source + ": unknown mesh format");
  }
  if (!st.ok()) return st;
  if (m.faces.empty()) return InvalidArgument(source + ": the file holds no faces");
  if (m.faces.size() > kMaxFaces) return ResourceExhausted(source + ": more than 50 million faces");
  if (st = check_indices(m); !st.ok()) return st;
  if (st = check_coordinates(m); !st.ok()) return st;
  if (st = weld(m); !st.ok()) return st;
  return m;
}

StatusOr<RawMesh> read_raw_mesh(const std::string& path) {
  size_t dot = path.find_last_of('.');
  size_t slash = path.find_last_of('/');
  std::string ext = (dot == std::string::npos || (slash != std::string::npos && dot < slash))
                        ? std::string()
                        : path.substr(dot + 1);
  const std::optional<MeshFormat> format = parse_mesh_format(ext);
  if (!format)
    return InvalidArgument(path + ": unknown mesh file extension '" + lower(ext) +
                           "' (expected .off, .obj, .stl, .ply, or .stp/.step for STEP)");
  std::ifstream in(path, std::ios::binary);
  if (!in) return NotFound(path + ": cannot open file");
  std::string data;
  in.seekg(0, std::ios::end);
  std::streamoff size = in.tellg();
  if (size < 0) return InvalidArgument(path + ": cannot read file");
  in.seekg(0, std::ios::beg);
  data.resize(size_t(size));
  if (size > 0 && !in.read(data.data(), size)) return InvalidArgument(path + ": cannot read file");
  return read_raw_mesh(data, *format, path);
}

StatusOr<SolidMesh> load_solid(const std::string& path) {
  auto raw = read_raw_mesh(path);
  if (!raw.ok()) return raw.status();
  return build_solid(*raw);
}

}  // namespace gvm
