#include "plan_report.h"

#include "analysis_report.h"

#include <cstdio>
#include <map>
#include <string>

namespace gvm {
namespace {

std::string format(const char* f, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

// Strings are appended piece by piece: GCC 12 warns falsely on "literal" + std::string.
std::string vec(const v1::Vec3& v) {
  std::string s = "(";
  s += format("%7.4f", v.x()) + ", ";
  s += format("%7.4f", v.y()) + ", ";
  s += format("%7.4f", v.z()) + ")";
  return s;
}

const char* mode_text(v1::PlanMode m) {
  switch (m) {
    case v1::PLAN_MODE_ROTARY:
      return "rotary (4-axis indexer: one rotary axis per setup, tool perpendicular to it)";
    case v1::PLAN_MODE_PROBE:
      return "probe (CMM indexing head: one head orientation per setup)";
    default:
      return "setup (3-axis: one tool direction per setup)";
  }
}

const char* reason_text(v1::UnreachableReason r) {
  switch (r) {
    case v1::UNREACHABLE_REASON_SELF_OCCLUDED: return "self-occluded";
    case v1::UNREACHABLE_REASON_OCCLUDED: return "occluded";
    case v1::UNREACHABLE_REASON_VOID: return "internal void";
    case v1::UNREACHABLE_REASON_NOT_ALONG_NORMAL: return "not along its normal";
    case v1::UNREACHABLE_REASON_NO_HEAD_ORIENTATION: return "no head orientation";
    case v1::UNREACHABLE_REASON_GVM_NOT_COMPUTED: return "GVM not computed";
    case v1::UNREACHABLE_REASON_NO_CLEARANCE: return "not enough clearance";
    case v1::UNREACHABLE_REASON_NEIGHBOR_OCCLUDED: return "blocked by its neighbours";
    default: return "unreachable";
  }
}

class Names {
 public:
  explicit Names(const v1::Plan& p) {
    for (const auto& s : p.surfaces()) name_[s.id()] = s.name();
  }
  std::string operator()(uint32_t id) const {
    auto it = name_.find(id);
    if (it != name_.end()) return it->second;
    std::string s = "#";
    return s += std::to_string(id);
  }

 private:
  std::map<uint32_t, std::string> name_;
};

// "F1 F2 F5" with pieces as "F7[piece 2]" and flags for exact alignment and reach within
// the tolerance, wrapped after `width` characters onto lines indented by `indent`.
std::string reach_list(const v1::Setup& s, const Names& name, size_t width, size_t indent) {
  std::string out;
  size_t line = 0;
  for (const v1::SetupFeature& r : s.reach()) {
    if (out.size() - line > width) {
      out += '\n';
      out.append(indent, ' ');
      line = out.size();
    } else if (!out.empty()) {
      out += " ";
    }
    out += name(r.feature());
    if (r.has_piece()) {
      out += "[piece " + std::to_string(r.piece()) + "]";
    } else if (r.faces_size() > 0) {
      out += "[faces";
      for (int i = 0; i < r.faces_size(); ++i) {
        out += i ? "," : " ";
        out += std::to_string(r.faces(i));
      }
      out += "]";
    }
    out += r.within_tolerance() ? "~" : r.exact_alignment() ? "*" : "";
  }
  return out;
}

bool any_within(const v1::Plan& p) {
  for (const v1::Setup& s : p.setups()) {
    for (const v1::SetupFeature& r : s.reach()) {
      if (r.within_tolerance()) return true;
    }
  }
  return false;
}

std::string setup_list(const std::vector<int>& setups) {
  std::string out = setups.size() == 1 ? "setup " : "setups ";
  for (size_t i = 0; i < setups.size(); ++i) {
    out += i == 0 ? "" : i + 1 == setups.size() ? " and " : ", ";
    out += std::to_string(setups[i] + 1);
  }
  return out;
}

void print_setups(const v1::Plan& p, const Names& name, std::ostream& out) {
  const bool rotary = p.mode() == v1::PLAN_MODE_ROTARY, probe = p.mode() == v1::PLAN_MODE_PROBE;
  out << "  #  " << (rotary ? "rotary axis" : "direction u") << "                  clearance  "
      << (probe ? "head A, B       " : "") << "surfaces (* = needs exact alignment"
      << (any_within(p) ? ", ~ = reached within the tolerance" : "") << ")\n";
  for (int k = 0; k < p.setups_size(); ++k) {
    const v1::Setup& s = p.setups(k);
    out << format("%3.0f", k + 1.0) << "  " << vec(s.direction()) << "  " << format("%7.2f", s.clearance_degrees())
        << " deg  ";
    if (probe) out << format("%6.1f", s.head_a_degrees()) << ", " << format("%6.1f", s.head_b_degrees()) << "  ";
    out << reach_list(s, name, 60, probe ? 63 : 47) << "\n";
    if (rotary) {
      out << "       table angle 0 = tool along " << vec(s.rotary_zero()) << "; angles:";
      for (const v1::SetupFeature& r : s.reach()) {
        out << " " << name(r.feature()) << "@" << format("%.1f", r.rotary_angle_degrees());
      }
      out << "\n";
    }
  }
}

// What the tolerance did: the surfaces reached only within it, and how far off.
void print_within(const v1::Plan& p, const Names& name, std::ostream& out) {
  if (!any_within(p)) return;
  out << "\nReached within the tolerance (" << format("%g", p.tolerance().radians()) << " rad), off their GVM by:";
  size_t line = 0;
  std::string text;
  for (int k = 0; k < p.setups_size(); ++k) {
    for (const v1::SetupFeature& r : p.setups(k).reach()) {
      if (!r.within_tolerance()) continue;
      std::string item = " " + name(r.feature()) + (r.has_piece() ? "[piece " + std::to_string(r.piece()) + "]" : "") +
                         " " + format("%.2g", r.distance_radians()) + " (setup " + std::to_string(k + 1) + ")";
      if (text.size() - line + item.size() > 88) text += "\n ", line = text.size();
      text += item;
    }
  }
  out << "\n " << text << "\n";
}

// Surfaces planned piece by piece, and in which setups.
void print_pieces(const v1::Plan& p, const Names& name, std::ostream& out) {
  std::map<uint32_t, int> unreached;  // pieces left unreachable, by surface
  for (const v1::Unreachable& u : p.unreachable()) unreached[u.feature()] = u.pieces_unreachable_size();
  std::string text;
  for (const v1::PlannedSurface& s : p.surfaces()) {
    if (!s.has_pieces() || s.pieces().setups_size() == 0) continue;
    const uint32_t count = s.pieces().count(), left = static_cast<uint32_t>(unreached[s.id()]);
    text += "  " + name(s.id()) + " (" + std::to_string(s.face_count()) + " faces, " + std::to_string(count) +
            " pieces): " + (left > 0 ? std::to_string(count - left) + " machinable in " : "machinable in ") +
            setup_list({s.pieces().setups().begin(), s.pieces().setups().end()}) +
            (left > 0 ? ", " + std::to_string(left) + " unreachable" : "") + "\n";
  }
  if (!text.empty()) out << "\nPlanned piece by piece:\n" << text;
}

void print_unreachable(const v1::Plan& p, const Names& name, std::ostream& out) {
  out << "\nUnreachable " << (p.surfaces_kind() == v1::PLAN_SURFACES_REGIONS ? "regions" : "features") << ": "
      << p.unreachable_size() << "\n";
  for (const v1::Unreachable& u : p.unreachable()) {
    out << "  " << name(u.feature()) << ": " << reason_text(u.reason()) << " - " << u.detail() << "\n";
    if (u.pieces_reached() + u.pieces_unreachable_size() > 0) {
      out << "      split: " << u.pieces_reached() << " piece(s) planned in the setups above, "
          << u.pieces_unreachable_size() << " piece(s) unreachable\n";
    }
  }
}

void print_proof(const v1::Plan& p, const Names& name, std::ostream& out) {
  const v1::SolverStatistics& s = p.solver();
  out << "\nOptimality: ";
  const std::string within = p.has_tolerance() ? " within the tolerance" : "";
  if (p.optimal()) {
    out << "proven - no plan has fewer than " << p.lower_bound() << " setup(s)" << within;
  } else {
    out << "not proven - lower bound " << p.lower_bound() << within << ", gap " << (p.setups_size() - int(p.lower_bound()));
    if (s.time_limit_reached()) out << " (time limit reached)";
  }
  out << "\n  over " << s.candidate_set() << "\n  " << s.solver() << "; greedy " << s.greedy_setups()
      << ", packing bound " << s.packing_bound();
  if (p.lower_bound_witness_size() > 0 && s.packing_bound() == p.lower_bound()) {
    out << (p.has_tolerance() ? " (reach sets pairwise more than twice the tolerance apart:"
                              : " (pairwise without a common direction:");
    for (uint32_t id : p.lower_bound_witness()) out << " " << name(id);
    out << ")";
  }
  out << "\n";
  if (p.has_tolerance() && p.tolerance().exact_setups() != static_cast<uint32_t>(p.setups_size())) {
    const v1::PlanTolerance& t = p.tolerance();
    out << "  exactly (tolerance 0): " << t.exact_setups() << " setup(s), "
        << (t.exact_setups() == t.exact_lower_bound() ? std::string("proven")
                                                      : "lower bound " + std::to_string(t.exact_lower_bound()))
        << "\n";
  }
  if (s.continuous_lower_bound() > 0) {
    out << "  without the clearance requirement " << s.continuous_lower_bound()
        << " setup(s) suffice: a lower bound over every direction\n";
  }
}

}  // namespace

void print_plan(const v1::Plan& p, std::ostream& out) {
  const Names name(p);
  const v1::PartSummary& part = p.part();
  const bool regions = p.surfaces_kind() == v1::PLAN_SURFACES_REGIONS;
  out << "Part " << part.source() << ": " << part.input_faces() << " faces (" << part.triangles()
      << " triangles)\n"
      << step_line(part) << "Mode: " << mode_text(p.mode()) << "\n"
      << "Planned: " << p.surfaces_size() << (regions ? " concave regions" : p.options().concave_only() ? " concave features" : " features (hull features too)")
      << (p.options().planar_normal() ? ", planar ones along their normal only" : "") << "; "
      << p.reached() << " reached, " << p.unreachable_count() << " unreachable\n"
      << "Directions u are those along which rays leave the surface; the tool approaches along -u.\n\n"
      << "Setups: " << p.setups_size();
  if (p.has_tolerance() && p.tolerance().exact_setups() != static_cast<uint32_t>(p.setups_size())) {
    out << " within " << format("%g", p.tolerance().radians()) << " rad; " << p.tolerance().exact_setups()
        << " exactly";
  }
  out << "\n";
  print_setups(p, name, out);
  print_within(p, name, out);
  print_pieces(p, name, out);
  print_unreachable(p, name, out);
  print_proof(p, name, out);
  const v1::PlanTiming& t = p.timing();
  out << "\nTiming: analysis " << format("%.3f", t.analysis_seconds()) << " s; planning "
      << format("%.3f", t.total_seconds()) << " s (candidates " << format("%.3f", t.candidates_seconds())
      << ", set cover " << format("%.3f", t.cover_seconds()) << ", placement "
      << format("%.3f", t.placement_seconds()) << ", reasons " << format("%.3f", t.unreachable_seconds())
      << ") on " << t.threads() << " thread(s)\n";
}

}  // namespace gvm
