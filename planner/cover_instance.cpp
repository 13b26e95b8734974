#include "cover_instance.h"

#include <utility>

namespace gvm::planner {

CoverInstance make_cover_instance(uint32_t items, std::vector<std::vector<uint32_t>> items_of) {
  CoverInstance instance;
  instance.items_of = std::move(items_of);
  instance.candidates_of.resize(items);
  // Candidates are visited in increasing order, so each item's list comes out ascending.
  for (uint32_t c = 0; c < instance.candidate_count(); ++c) {
    for (uint32_t i : instance.items_of[c]) instance.candidates_of[i].push_back(c);
  }
  return instance;
}

bool covers_all(const CoverInstance& instance, const std::vector<uint32_t>& chosen) {
  std::vector<char> covered(instance.item_count(), 0);
  for (uint32_t c : chosen) {
    for (uint32_t i : instance.items_of[c]) covered[i] = 1;
  }
  for (char x : covered) {
    if (!x) return false;
  }
  return true;
}

}  // namespace gvm::planner
