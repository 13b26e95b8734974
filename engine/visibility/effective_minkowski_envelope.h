// The effective Minkowski envelope EME(O + (-S)) of paper Sec. 4 and the border curves
// of its pure back-facing patches, whose projection bounds Phi(O + (-S)).
//
// Tentative faces are V_O + (-F_S) (VF), F_O + (-V_S) (FV) and E_O + (-E_S) (EE). A face
// whose critical set has both signs lies inside the sum (Lemma 1) and is dropped; the
// others are oriented by Lemma 2 ({0,0}: towards the origin's back side) and kept when
// back-facing to the origin. A kept face never contains the origin and its plane never
// passes through it, so every edge projects to a proper minor arc; faces whose plane
// passes through the origin project to arcs, which cannot change Int(Phi), and are
// dropped. The border of the kept faces is their boundary chain with shared edges
// cancelled; the number of kept faces covering a direction u (the coverage) changes by
// the chain's multiplicity across each border arc, so Int(Phi(O + (-S))) is the set of
// directions around which the coverage is positive. This holds for touching surfaces
// too (the origin in O + (-S)): only faces through the origin are tangent.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "gvm/mesh.h"

namespace gvm {

// A border edge of the envelope: the segment from (q0 - p0) to (q1 - p1) of the sum, with
// q's vertices of O and p's vertices of S (mesh vertex ids). It projects to the minor arc
// from dir(q0 - p0) to dir(q1 - p1), counter-clockwise around (q0 - p0) x (q1 - p1); the
// coverage on its left exceeds the coverage on its right by `multiplicity` (> 0).
struct EnvelopeBorderEdge {
  uint32_t q0, p0, q1, p1;
  int32_t multiplicity;
};

struct EnvelopeStatistics {
  uint64_t tentative_faces = 0;   // VF + FV + EE pairs examined
  uint64_t outside_window = 0;    // of those, left out: their directions miss the window
  uint64_t kept_faces = 0;        // critical set not {+,-}
  uint64_t envelope_faces = 0;    // kept and back-facing to the origin
  uint64_t patches = 0;           // maximal edge-connected sets of envelope faces
  uint64_t border_edges = 0;      // #GOM in the paper's tables
};

// A face of the envelope: its vertices as (q, p) pairs, counter-clockwise around its
// outward normal. Kept only on request (tests, coverage counts).
struct EnvelopeFace {
  std::vector<std::pair<uint32_t, uint32_t>> vertices;
};

struct EffectiveMinkowskiEnvelope {
  std::vector<EnvelopeBorderEdge> border;  // sorted, deterministic
  EnvelopeStatistics statistics;
  std::vector<EnvelopeFace> faces;         // only with keep_faces
};

class DirectionWindow;

// The border chain of any set of envelope faces: their edges with shared ones cancelled.
std::vector<EnvelopeBorderEdge> border_chain(std::span<const EnvelopeFace> faces);

// S and O: disjoint sets of triangles of `mesh` (they may touch). With a window, the
// faces whose directions certainly miss it are left out (see direction_window.h): the
// result then describes the coverage near the window's directions only.
EffectiveMinkowskiEnvelope compute_effective_minkowski_envelope(
    const SolidMesh& mesh, std::span<const uint32_t> s, std::span<const uint32_t> o,
    bool keep_faces = false, const DirectionWindow* window = nullptr);

}  // namespace gvm
