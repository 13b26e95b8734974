// Why a surface cannot be reached, from the maps the engine already has.
#include <algorithm>
#include <cstdio>
#include <map>

#include "placement.h"
#include "plan_state.h"

namespace gvm::planner {
namespace {

std::string vector_text(const Direction& d) {
  const std::array<double, 3> u = d.unit();
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.4f, %.4f, %.4f)", u[0], u[1], u[2]);
  return buf;
}

// The feature of every input face.
std::map<uint32_t, uint32_t> feature_of_faces(const Analysis& analysis) {
  std::map<uint32_t, uint32_t> out;
  for (const Surface& f : analysis.features()) {
    for (uint32_t face : f.faces) out[face] = f.id;
  }
  return out;
}

std::string feature_list(const Analysis& analysis, const std::vector<uint32_t>& ids) {
  std::string out;
  const size_t shown = std::min<size_t>(ids.size(), 8);
  for (size_t i = 0; i < shown; ++i) out += (i ? ", " : "") + analysis.features()[ids[i]].name;
  if (shown < ids.size()) out += " and " + std::to_string(ids.size() - shown) + " more";
  return out;
}

// LVM(S + N_S) is empty. Whether S alone has no common direction (an undercut of its own
// shape) or its neighbours across concave edges take the rest: then the fewest neighbouring
// features found (each left out in turn while the rest still leave nothing) are named.
void explain_empty_lvm(const Analysis& analysis, const Surface& s, UnreachableSurface& out) {
  const StatusOr<DirectionSet> own = analysis.own_lvm(s.faces);
  if (!own.ok() || own->is_empty()) {
    out.detail = "LVM(S) is empty: no direction faces all of its own faces, an undercut of its own shape";
    return;
  }
  const std::map<uint32_t, uint32_t> feature = feature_of_faces(analysis);
  std::map<uint32_t, std::vector<uint32_t>> by_feature;  // N_S faces of each neighbouring feature
  for (uint32_t face : analysis.neighbor_faces(s.faces))
    if (auto it = feature.find(face); it != feature.end()) by_feature[it->second].push_back(face);
  auto leaves_nothing = [&](const std::map<uint32_t, std::vector<uint32_t>>& kept) {
    std::vector<uint32_t> faces = s.faces;
    for (const auto& [f, fs] : kept) faces.insert(faces.end(), fs.begin(), fs.end());
    const StatusOr<DirectionSet> lvm = analysis.own_lvm(faces);
    return lvm.ok() && lvm->is_empty();
  };
  for (auto it = by_feature.begin(); it != by_feature.end();) {
    auto without = by_feature;
    without.erase(it->first);
    it = leaves_nothing(without) ? by_feature.erase(it) : std::next(it);
  }
  out.reason = v1::UNREACHABLE_REASON_NEIGHBOR_OCCLUDED;
  for (const auto& [f, fs] : by_feature) out.blocking_features.push_back(f);
  out.detail = "LVM(S) is " + own->description() +
               ", but the faces beside it across its concave edges leave no direction of it (LVM(S + N_S) is "
               "empty): blocked by " + feature_list(analysis, out.blocking_features);
}

std::string reason_words(v1::UnreachableReason r) {
  switch (r) {
    case v1::UNREACHABLE_REASON_NEIGHBOR_OCCLUDED: return "blocked by the faces beside it (LVM(S + N_S) is empty)";
    case v1::UNREACHABLE_REASON_OCCLUDED: return "occluded by the rest of the part (its GVM is empty)";
    case v1::UNREACHABLE_REASON_NOT_ALONG_NORMAL: return "not reachable along its normal";
    default: return "unreachable";
  }
}

}  // namespace

v1::UnreachableReason reason_of_empty_reach(const Surface& s, bool planar_normal_only) {
  if (s.maps.status == GvmStatus::kEmptyVoid) return v1::UNREACHABLE_REASON_VOID;
  if (!s.maps.gvm) return v1::UNREACHABLE_REASON_GVM_NOT_COMPUTED;
  if (s.maps.lvm.is_empty()) return v1::UNREACHABLE_REASON_SELF_OCCLUDED;
  if (s.maps.gvm->is_empty()) return v1::UNREACHABLE_REASON_OCCLUDED;
  if (planar_normal_only && s.planar_normal) return v1::UNREACHABLE_REASON_NOT_ALONG_NORMAL;
  return v1::UNREACHABLE_REASON_UNSPECIFIED;  // not empty: not for this function
}

void explain(const Analysis& analysis, const Surface& s, UnreachableSurface& out) {
  if (out.split_by_direction && !out.pieces_unreachable.empty()) {
    // What is said is why the pieces left are unreachable: the feature's own shape was
    // answered by the split.
    out.reason = out.pieces_unreachable.front().second;
    out.detail = "no one direction sees all of its faces (LVM(S) is empty), so it was planned in " +
                 std::to_string(out.pieces) + " pieces that each have one; a piece left is " + reason_words(out.reason);
    return;
  }
  switch (out.reason) {
    case v1::UNREACHABLE_REASON_VOID:
      out.detail = "faces of an internal void: never visible from outside";
      return;
    case v1::UNREACHABLE_REASON_GVM_NOT_COMPUTED:
      out.detail = "the analysis skipped the global occlusion (--lvm-only): its GVM is unknown";
      return;
    case v1::UNREACHABLE_REASON_SELF_OCCLUDED:
      explain_empty_lvm(analysis, s, out);
      if (out.split_limit > 0) {
        out.detail += "; not split into pieces: " + std::to_string(s.faces.size()) + " faces, more than " +
                      std::to_string(out.split_limit) + " (--split-max-faces)";
      }
      return;
    case v1::UNREACHABLE_REASON_NOT_ALONG_NORMAL:
      out.detail = "its GVM (" + s.maps.gvm->description() + ") does not contain its own normal " +
                   vector_text(*s.planar_normal);
      return;
    case v1::UNREACHABLE_REASON_OCCLUDED:
      break;
    default:
      out.detail = out.nearest.detail;
      return;
  }
  // Occluded by the rest of the part: which faces block the most open direction of the
  // LVM, named by their features.
  const DirectionSet* lvm[] = {&s.maps.lvm};
  const Direction probe = place_in(lvm, s.maps.lvm.witness()).direction;
  out.probed_direction = probe;
  const std::map<uint32_t, uint32_t> feature = feature_of_faces(analysis);
  for (uint32_t face : analysis.blocking_faces(s.faces, probe)) {
    auto it = feature.find(face);
    if (it != feature.end()) out.blocking_features.push_back(it->second);
  }
  std::sort(out.blocking_features.begin(), out.blocking_features.end());
  out.blocking_features.erase(std::unique(out.blocking_features.begin(), out.blocking_features.end()),
                              out.blocking_features.end());
  out.detail = "occluded by the rest of the part: LVM(S + N_S) is " + s.maps.lvm.description() +
               " but the GVM is empty; along its most open direction " + vector_text(probe) +
               " the rays are blocked by ";
  if (out.blocking_features.empty()) {
    out.detail += "faces met only where they graze (no face crossed)";
    return;
  }
  out.detail += feature_list(analysis, out.blocking_features);
}

}  // namespace gvm::planner
