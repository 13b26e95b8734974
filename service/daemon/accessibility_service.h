// gvm.v1.Accessibility: a thin layer over the engine and the planner. Each request's part
// is loaded and checked against the limits before any work, waits for a job slot, then
// runs on the daemon's shared worker pool with its own stop source (the client's
// cancellation and deadline reach inside the engine's loops); analyses are cached by part
// hash and options, so that planning a part again does not recompute its maps.
#pragma once

#include <atomic>
#include <functional>
#include <memory>

#include "analysis_cache.h"
#include "gvm/v1/service.grpc.pb.h"
#include "job_slots.h"
#include "daemon_limits.h"

namespace gvm::daemon {

class AccessibilityService final : public v1::Accessibility::Service {
 public:
  AccessibilityService(Limits limits, unsigned threads);

  grpc::Status Analyze(grpc::ServerContext* context, const v1::AnalyzeRequest* request,
                       v1::AnalyzeResponse* response) override;
  grpc::Status Plan(grpc::ServerContext* context, const v1::PlanRequest* request,
                    v1::PlanResponse* response) override;
  grpc::Status AnalyzeStream(grpc::ServerContext* context, const v1::AnalyzeRequest* request,
                             grpc::ServerWriter<v1::AnalyzeEvent>* writer) override;
  grpc::Status PlanStream(grpc::ServerContext* context, const v1::PlanRequest* request,
                          grpc::ServerWriter<v1::PlanEvent>* writer) override;

  // Refuse new requests (UNAVAILABLE); running ones go on until the server cancels them.
  void drain() { slots_.drain(); }

 private:
  struct Job;
  using ProgressSink = std::function<void(const v1::Progress&)>;
  grpc::Status analyze(grpc::ServerContext* context, const v1::AnalyzeRequest& request, v1::AnalyzeResponse* response,
                       const ProgressSink& progress);
  grpc::Status plan(grpc::ServerContext* context, const v1::PlanRequest& request, v1::PlanResponse* response,
                    const ProgressSink& progress);
  // Loads the part, waits for a slot, and runs `then` on its analysis (from the cache, or
  // computed now) while the request is watched.
  Status with_analysis(Job& job, const v1::Part& part, v1::AnalyzeOptions options, const ProgressSink& progress,
                       const std::function<Status(const Analysis&)>& then);

  const Limits limits_;
  const unsigned threads_;
  JobSlots slots_;
  AnalysisCache cache_;
  std::atomic<uint64_t> next_id_{1};
};

}  // namespace gvm::daemon
