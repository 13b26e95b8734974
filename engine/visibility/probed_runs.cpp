#include "visibility/probed_runs.h"

#include <optional>

namespace gvm {
namespace {

using exact::ExactVec;
using sphere::Arrangement;

// An edge walked one way: from `from` to `to`, counter-clockwise around `normal`.
struct Step {
  uint32_t edge;
  bool forward;  // v0 -> v1
  uint32_t from(const Arrangement& arr) const { return forward ? arr.edges()[edge].v0 : arr.edges()[edge].v1; }
  uint32_t to(const Arrangement& arr) const { return forward ? arr.edges()[edge].v1 : arr.edges()[edge].v0; }
  ExactVec normal(const Arrangement& arr) const { return forward ? arr.edges()[edge].normal : -arr.edges()[edge].normal; }
};

class Walker {
 public:
  Walker(const Arrangement& arr, std::span<const uint8_t> selected) : arr_(arr), incident_(arr.vertices().size()) {
    for (uint32_t e = 0; e < arr.edges().size(); ++e) {
      if (!selected[e]) continue;
      incident_[arr.edges()[e].v0].push_back(e);
      incident_[arr.edges()[e].v1].push_back(e);
    }
  }

  // The step that continues `s` through its end vertex (ending at it when backwards), if
  // exactly two selected edges meet there, on one circle, both walked the same way round.
  std::optional<Step> next(const Step& s, bool backwards) const {
    const uint32_t v = backwards ? s.from(arr_) : s.to(arr_);
    const std::vector<uint32_t>& at = incident_[v];
    if (at.size() != 2) return std::nullopt;
    const uint32_t other = at[0] == s.edge ? at[1] : at[0];
    if (other == s.edge) return std::nullopt;
    const Step t{other, backwards ? arr_.edges()[other].v1 == v : arr_.edges()[other].v0 == v};
    const ExactVec m = s.normal(arr_), n = t.normal(arr_);
    if (!exact::parallel(m, n) || exact::sign_dot(m, n) != Sign::kPositive) return std::nullopt;
    return t;
  }

  // The maximal sequence of steps through `e` (walked forwards), in order; a closed
  // sequence starts at e.
  std::vector<Step> sequence_through(uint32_t e) const {
    Step first{e, true};
    for (std::optional<Step> b = next(first, true); b && b->edge != e; b = next(*b, true)) first = *b;
    std::vector<Step> out{first};
    for (std::optional<Step> f = next(first, false); f && f->edge != first.edge; f = next(*f, false)) out.push_back(*f);
    return out;
  }

 private:
  const Arrangement& arr_;
  std::vector<std::vector<uint32_t>> incident_;  // selected edges at each vertex
};

// The sequence cut into runs shorter than 180 degrees: a run grows while its start and
// its new end stay counter-clockwise around the circle's normal (each step turns by less
// than 180 degrees, so the run's turn stays below it).
void cut_into_runs(const Arrangement& arr, const std::vector<Step>& steps, std::vector<ProbedRun>& out) {
  const ExactVec normal = steps[0].normal(arr);
  for (size_t i = 0; i < steps.size();) {
    const uint32_t start = steps[i].from(arr);
    ProbedRun run;
    run.edges.push_back(steps[i].edge);
    size_t j = i + 1;
    for (; j < steps.size(); ++j) {
      const uint32_t end = steps[j].to(arr);
      if (end == start ||
          exact::sign_det(arr.vertices()[start].p, arr.vertices()[end].p, normal) != Sign::kPositive) {
        break;
      }
      run.inner.push_back(steps[j].from(arr));
      run.edges.push_back(steps[j].edge);
    }
    run.arc = {arr.vertices()[start].p, arr.vertices()[steps[j - 1].to(arr)].p, normal};
    out.push_back(std::move(run));
    i = j;
  }
}

}  // namespace

std::vector<ProbedRun> probed_runs(const Arrangement& arr, std::span<const uint8_t> selected) {
  const Walker walker(arr, selected);
  std::vector<uint8_t> done(arr.edges().size(), 0);
  std::vector<ProbedRun> out;
  for (uint32_t e = 0; e < arr.edges().size(); ++e) {
    if (!selected[e] || done[e]) continue;
    const std::vector<Step> steps = walker.sequence_through(e);
    for (const Step& s : steps) done[s.edge] = 1;
    cut_into_runs(arr, steps, out);
  }
  return out;
}

}  // namespace gvm
