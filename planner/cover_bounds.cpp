#include "cover_bounds.h"

#include <algorithm>
#include <numeric>
#include <queue>
#include <utility>

namespace gvm::planner {
namespace {

// Picks in greedy order: a lazy max-heap on (gain, lowest index). Gains only fall, so an
// entry whose recomputed gain still equals its key is a true maximum.
std::vector<uint32_t> greedy_order(const CoverInstance& instance) {
  using Entry = std::pair<uint32_t, uint32_t>;  // gain, candidate
  auto lower = [](const Entry& a, const Entry& b) {
    return a.first != b.first ? a.first < b.first : a.second > b.second;
  };
  std::priority_queue<Entry, std::vector<Entry>, decltype(lower)> heap(lower);
  for (uint32_t c = 0; c < instance.candidate_count(); ++c) {
    heap.emplace(static_cast<uint32_t>(instance.items_of[c].size()), c);
  }
  std::vector<char> covered(instance.item_count(), 0);
  uint32_t uncovered = instance.item_count();
  std::vector<uint32_t> order;
  while (uncovered > 0 && !heap.empty()) {
    const auto [key, c] = heap.top();
    heap.pop();
    uint32_t gain = 0;
    for (uint32_t i : instance.items_of[c]) gain += !covered[i];
    if (gain != key) {
      if (gain > 0) heap.emplace(gain, c);
      continue;
    }
    order.push_back(c);
    for (uint32_t i : instance.items_of[c]) covered[i] = 1;
    uncovered -= gain;
  }
  return order;
}

}  // namespace

std::vector<uint32_t> drop_redundant(const CoverInstance& instance, const std::vector<uint32_t>& order) {
  std::vector<uint32_t> times_covered(instance.item_count(), 0);
  for (uint32_t c : order) {
    for (uint32_t i : instance.items_of[c]) ++times_covered[i];
  }
  std::vector<uint32_t> kept;
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const std::vector<uint32_t>& items = instance.items_of[*it];
    const bool redundant =
        std::all_of(items.begin(), items.end(), [&](uint32_t i) { return times_covered[i] >= 2; });
    if (!redundant) {
      kept.push_back(*it);
      continue;
    }
    for (uint32_t i : items) --times_covered[i];
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

std::vector<uint32_t> greedy_cover(const CoverInstance& instance) {
  return drop_redundant(instance, greedy_order(instance));
}

namespace {

bool share_candidate(const CoverInstance& instance, uint32_t a, uint32_t b) {
  const std::vector<uint32_t>& x = instance.candidates_of[a];
  const std::vector<uint32_t>& y = instance.candidates_of[b];
  size_t i = 0, j = 0;
  while (i < x.size() && j < y.size()) {
    if (x[i] == y[j]) return true;
    x[i] < y[j] ? ++i : ++j;
  }
  return false;
}

constexpr int64_t kFree = -1;

// A packing with owner[c] = the packed item in candidate c (at most one, by definition).
class Packing {
 public:
  explicit Packing(const CoverInstance& instance)
      : instance_(instance),
        owner_(instance.candidate_count(), kFree),
        packed_(instance.item_count(), 0) {
    order_.resize(instance.item_count());
    std::iota(order_.begin(), order_.end(), 0u);
    std::stable_sort(order_.begin(), order_.end(), [&](uint32_t a, uint32_t b) {
      return instance.candidates_of[a].size() < instance.candidates_of[b].size();
    });
  }

  void fill() {
    for (uint32_t i : order_) {
      if (!packed_[i] && is_free(i)) add(i);
    }
  }

  // One (1,2)-swap: a packed item p and two unpacked items a, b, sharing no candidate with
  // each other nor with any packed item but p, replace p. Returns false when none exists.
  bool swap_once() {
    std::vector<std::vector<uint32_t>> blocked_only_by(instance_.item_count());
    for (uint32_t x : order_) {
      if (packed_[x]) continue;
      const int64_t p = sole_owner(x);
      if (p >= 0) blocked_only_by[static_cast<size_t>(p)].push_back(x);
    }
    constexpr size_t kMaxTried = 64;  // bounds the pair search; the result stays deterministic
    for (uint32_t p : order_) {
      if (!packed_[p]) continue;
      const std::vector<uint32_t>& tight = blocked_only_by[p];
      const size_t n = std::min(tight.size(), kMaxTried);
      for (size_t s = 0; s < n; ++s) {
        for (size_t t = s + 1; t < n; ++t) {
          if (share_candidate(instance_, tight[s], tight[t])) continue;
          remove(p);
          add(tight[s]);
          add(tight[t]);
          fill();
          return true;
        }
      }
    }
    return false;
  }

  std::vector<uint32_t> items() const {
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < packed_.size(); ++i) {
      if (packed_[i]) out.push_back(i);
    }
    return out;
  }

 private:
  bool is_free(uint32_t i) const {
    const std::vector<uint32_t>& cs = instance_.candidates_of[i];
    return std::all_of(cs.begin(), cs.end(), [&](uint32_t c) { return owner_[c] == kFree; });
  }
  // The one packed item sharing a candidate with x, or -1 when none or several do.
  int64_t sole_owner(uint32_t x) const {
    int64_t found = kFree;
    for (uint32_t c : instance_.candidates_of[x]) {
      if (owner_[c] == kFree || owner_[c] == found) continue;
      if (found != kFree) return kFree;
      found = owner_[c];
    }
    return found;
  }
  void add(uint32_t i) {
    packed_[i] = 1;
    for (uint32_t c : instance_.candidates_of[i]) owner_[c] = i;
  }
  void remove(uint32_t i) {
    packed_[i] = 0;
    for (uint32_t c : instance_.candidates_of[i]) owner_[c] = kFree;
  }

  const CoverInstance& instance_;
  std::vector<uint32_t> order_;
  std::vector<int64_t> owner_;
  std::vector<char> packed_;
};

}  // namespace

std::vector<uint32_t> greedy_packing(const CoverInstance& instance) {
  Packing packing(instance);
  packing.fill();
  // Each swap grows the packing by at least one, and no packing outgrows a cover.
  while (packing.swap_once()) {
  }
  return packing.items();
}

bool is_packing(const CoverInstance& instance, const std::vector<uint32_t>& items) {
  std::vector<char> used(instance.candidate_count(), 0);
  for (uint32_t i : items) {
    for (uint32_t c : instance.candidates_of[i]) {
      if (used[c]) return false;
      used[c] = 1;
    }
  }
  return true;
}

}  // namespace gvm::planner
