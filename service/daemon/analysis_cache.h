// Analyses kept by (part hash, options that change the maps), least recently used first
// out: planning a part again with other planner options does not recompute its maps.
// The key holds the SHA-256 of the part's bytes, format and groups and the serialized
// options, so a hit is never for other bytes or options.
#pragma once

#include <list>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>

#include "gvm/analysis.h"
#include "gvm/v1/gvm.pb.h"

namespace gvm::daemon {

class AnalysisCache {
 public:
  explicit AnalysisCache(size_t capacity) : capacity_(capacity) {}

  // The key of a part (its hash) analysed with these options (threads do not count).
  static std::string key(const std::string& part_hash, const v1::AnalyzeOptions& options);

  std::optional<Analysis> find(const std::string& key);
  void insert(const std::string& key, const Analysis& analysis);
  size_t size() const;

 private:
  using Entry = std::pair<std::string, Analysis>;
  size_t capacity_;
  mutable std::mutex mutex_;
  std::list<Entry> entries_;  // most recently used first
  std::unordered_map<std::string, std::list<Entry>::iterator> index_;
};

}  // namespace gvm::daemon
