#include "analysis_cache.h"

namespace gvm::daemon {

std::string AnalysisCache::key(const std::string& part_hash, const v1::AnalyzeOptions& options) {
  v1::AnalyzeOptions o = options;
  o.clear_threads();
  std::string bytes;
  o.SerializeToString(&bytes);  // no maps in AnalyzeOptions: the bytes are deterministic
  return part_hash + ":" + bytes;
}

std::optional<Analysis> AnalysisCache::find(const std::string& key) {
  std::lock_guard lock(mutex_);
  auto it = index_.find(key);
  if (it == index_.end()) return std::nullopt;
  entries_.splice(entries_.begin(), entries_, it->second);
  return it->second->second;
}

void AnalysisCache::insert(const std::string& key, const Analysis& analysis) {
  if (capacity_ == 0) return;
  std::lock_guard lock(mutex_);
  if (auto it = index_.find(key); it != index_.end()) {
    entries_.splice(entries_.begin(), entries_, it->second);
    return;
  }
  entries_.emplace_front(key, analysis);
  index_[key] = entries_.begin();
  while (entries_.size() > capacity_) {
    index_.erase(entries_.back().first);
    entries_.pop_back();
  }
}

size_t AnalysisCache::size() const {
  std::lock_guard lock(mutex_);
  return entries_.size();
}

}  // namespace gvm::daemon
