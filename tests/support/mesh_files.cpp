#include "support/mesh_files.h"

#include <cstdio>
#include <fstream>
#include <vector>

namespace gvm::test {

std::string write_obj(const RawMesh& raw, const std::filesystem::path& path) {
  std::vector<std::string> group_of(raw.faces.size(), "default");
  for (const auto& [name, faces] : raw.groups) {
    for (uint32_t f : faces) group_of[f] = name;
  }
  std::ofstream out(path);
  char buf[128];
  for (const Point3& p : raw.points) {
    std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
    out << buf;
  }
  for (size_t f = 0; f < raw.faces.size(); ++f) {
    out << "g " << group_of[f] << "\nf";
    for (uint32_t v : raw.faces[f]) out << " " << v + 1;
    out << "\n";
  }
  return path.string();
}

std::string write_off(const RawMesh& raw, const std::filesystem::path& path) {
  std::ofstream out(path);
  out << "OFF\n" << raw.points.size() << " " << raw.faces.size() << " 0\n";
  char buf[128];
  for (const Point3& p : raw.points) {
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
    out << buf;
  }
  for (const auto& face : raw.faces) {
    out << face.size();
    for (uint32_t v : face) out << " " << v;
    out << "\n";
  }
  return path.string();
}

}  // namespace gvm::test
