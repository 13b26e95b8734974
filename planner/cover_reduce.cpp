#include "cover_reduce.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace gvm::planner {
namespace {

// The problem as it shrinks: alive flags, with the lists filtered between passes.
class Reducer {
 public:
  explicit Reducer(const CoverProblem& problem)
      : items_of_(problem.candidates),
        item_alive_(problem.items, 1),
        candidate_alive_(problem.candidates.size(), 1),
        stamp_of_(std::max<size_t>(problem.items, problem.candidates.size()), 0) {
    candidates_of_ = make_cover_instance(problem.items, items_of_).candidates_of;
    for (uint32_t i = 0; i < problem.items; ++i) {
      if (candidates_of_[i].empty()) {
        item_alive_[i] = 0;
        result_.uncoverable.push_back(i);
      }
    }
  }

  ReducedCover run() && {
    bool changed = true;
    while (changed) {
      refresh();
      changed = drop_dominated_candidates();
      refresh();
      changed |= drop_implied_items();
      refresh();
      changed |= take_forced_candidates();
    }
    refresh();
    split_components();
    return std::move(result_);
  }

 private:
  // Filters every alive list down to alive members.
  void refresh() {
    for (uint32_t c = 0; c < items_of_.size(); ++c) {
      if (candidate_alive_[c]) std::erase_if(items_of_[c], [&](uint32_t i) { return !item_alive_[i]; });
    }
    for (uint32_t i = 0; i < candidates_of_.size(); ++i) {
      if (item_alive_[i]) {
        std::erase_if(candidates_of_[i], [&](uint32_t c) { return !candidate_alive_[c]; });
      }
    }
  }

  // Marks `ids` with a fresh stamp, so that membership tests need no clearing.
  void mark(const std::vector<uint32_t>& ids) {
    ++stamp_;
    for (uint32_t x : ids) stamp_of_[x] = stamp_;
  }
  size_t count_marked(const std::vector<uint32_t>& ids) const {
    size_t n = 0;
    for (uint32_t x : ids) n += stamp_of_[x] == stamp_;
    return n;
  }

  // A superset of candidate c's items must contain its rarest item: only that item's
  // candidates are compared with c.
  bool drop_dominated_candidates() {
    bool changed = false;
    for (uint32_t c = 0; c < items_of_.size(); ++c) {
      if (!candidate_alive_[c]) continue;
      const std::vector<uint32_t>& mine = items_of_[c];
      if (mine.empty()) {
        candidate_alive_[c] = 0;
        changed = true;
        continue;
      }
      const uint32_t rarest = *std::min_element(mine.begin(), mine.end(), [&](uint32_t a, uint32_t b) {
        return candidates_of_[a].size() < candidates_of_[b].size();
      });
      mark(mine);
      for (uint32_t d : candidates_of_[rarest]) {
        if (d == c || !candidate_alive_[d]) continue;
        const std::vector<uint32_t>& theirs = items_of_[d];
        if (theirs.size() < mine.size() || (theirs.size() == mine.size() && d > c)) continue;
        if (count_marked(theirs) == mine.size()) {
          candidate_alive_[c] = 0;
          changed = true;
          break;
        }
      }
    }
    return changed;
  }

  // Item i is implied by item j when every candidate of j covers i; such i lie in all of
  // j's candidates, so only the smallest one is scanned.
  bool drop_implied_items() {
    bool changed = false;
    for (uint32_t j = 0; j < candidates_of_.size(); ++j) {
      if (!item_alive_[j]) continue;
      const std::vector<uint32_t>& mine = candidates_of_[j];
      if (mine.empty()) continue;  // cannot happen: an alive item keeps a candidate
      const uint32_t smallest = *std::min_element(mine.begin(), mine.end(), [&](uint32_t a, uint32_t b) {
        return items_of_[a].size() < items_of_[b].size();
      });
      mark(mine);
      for (uint32_t i : items_of_[smallest]) {
        if (i == j || !item_alive_[i]) continue;
        const std::vector<uint32_t>& theirs = candidates_of_[i];
        if (theirs.size() < mine.size() || (theirs.size() == mine.size() && i < j)) continue;
        if (count_marked(theirs) == mine.size()) {
          item_alive_[i] = 0;
          changed = true;
        }
      }
    }
    return changed;
  }

  bool take_forced_candidates() {
    bool changed = false;
    for (uint32_t i = 0; i < candidates_of_.size(); ++i) {
      if (!item_alive_[i] || candidates_of_[i].size() != 1) continue;
      const uint32_t c = candidates_of_[i].front();
      result_.forced.push_back(c);
      result_.forced_items.push_back(i);
      candidate_alive_[c] = 0;
      for (uint32_t x : items_of_[c]) item_alive_[x] = 0;
      changed = true;
    }
    return changed;
  }

  static uint32_t find(std::vector<uint32_t>& parent, uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }

  void split_components() {
    const uint32_t n = static_cast<uint32_t>(candidates_of_.size());
    std::vector<uint32_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    for (uint32_t c = 0; c < items_of_.size(); ++c) {
      if (!candidate_alive_[c]) continue;
      for (uint32_t i : items_of_[c]) parent[find(parent, i)] = find(parent, items_of_[c].front());
    }
    // Components numbered by their first item; local ids ascend with the problem's ids.
    std::vector<int64_t> component_of_root(n, -1);
    std::vector<uint32_t> local_item(n, 0);
    for (uint32_t i = 0; i < n; ++i) {
      if (!item_alive_[i]) continue;
      int64_t& k = component_of_root[find(parent, i)];
      if (k < 0) {
        k = static_cast<int64_t>(result_.components.size());
        result_.components.emplace_back();
      }
      CoverComponent& component = result_.components[static_cast<size_t>(k)];
      local_item[i] = static_cast<uint32_t>(component.item_ids.size());
      component.item_ids.push_back(i);
    }
    std::vector<std::vector<std::vector<uint32_t>>> lists(result_.components.size());
    for (uint32_t c = 0; c < items_of_.size(); ++c) {
      if (!candidate_alive_[c]) continue;
      const auto k = static_cast<size_t>(component_of_root[find(parent, items_of_[c].front())]);
      result_.components[k].candidate_ids.push_back(c);
      std::vector<uint32_t>& local = lists[k].emplace_back();
      for (uint32_t i : items_of_[c]) local.push_back(local_item[i]);
    }
    for (size_t k = 0; k < lists.size(); ++k) {
      CoverComponent& component = result_.components[k];
      component.instance = make_cover_instance(static_cast<uint32_t>(component.item_ids.size()),
                                               std::move(lists[k]));
    }
  }

  std::vector<std::vector<uint32_t>> items_of_;
  std::vector<std::vector<uint32_t>> candidates_of_;
  std::vector<char> item_alive_;
  std::vector<char> candidate_alive_;
  std::vector<uint64_t> stamp_of_;
  uint64_t stamp_ = 0;
  ReducedCover result_;
};

}  // namespace

ReducedCover reduce_cover(const CoverProblem& problem) { return Reducer(problem).run(); }

}  // namespace gvm::planner
