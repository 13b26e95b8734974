#include "accessibility_service.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <optional>

#include "gvm/analysis_proto.h"
#include "gvm/planner/plan.h"
#include "part_source.h"
#include "request_watch.h"

namespace gvm::daemon {
namespace {

using Clock = std::chrono::steady_clock;

const char* code_name(grpc::StatusCode code) {
  switch (code) {
    case grpc::OK: return "OK";
    case grpc::CANCELLED: return "CANCELLED";
    case grpc::INVALID_ARGUMENT: return "INVALID_ARGUMENT";
    case grpc::DEADLINE_EXCEEDED: return "DEADLINE_EXCEEDED";
    case grpc::NOT_FOUND: return "NOT_FOUND";
    case grpc::PERMISSION_DENIED: return "PERMISSION_DENIED";
    case grpc::RESOURCE_EXHAUSTED: return "RESOURCE_EXHAUSTED";
    case grpc::FAILED_PRECONDITION: return "FAILED_PRECONDITION";
    case grpc::UNAVAILABLE: return "UNAVAILABLE";
    default: return "INTERNAL";
  }
}

// The latest progress of a request, written by the computing threads and read by its watch.
class ProgressBoard {
 public:
  explicit ProgressBoard(Clock::time_point start) : start_(start) {}

  void set(std::string_view phase, size_t done, size_t total) {
    std::lock_guard lock(mutex_);
    if (current_.phase() != phase) current_.set_phase(std::string(phase));
    current_.set_done(done);
    current_.set_total(total);
    changed_ = true;
  }
  std::optional<v1::Progress> take_if_changed() {
    std::lock_guard lock(mutex_);
    if (!changed_) return std::nullopt;
    changed_ = false;
    v1::Progress p = current_;
    p.set_seconds(std::chrono::duration<double>(Clock::now() - start_).count());
    return p;
  }

 private:
  const Clock::time_point start_;
  std::mutex mutex_;
  v1::Progress current_;
  bool changed_ = false;
};

std::shared_ptr<spdlog::logger> request_logger(uint64_t id) {
  auto base = spdlog::default_logger();
  auto log = std::make_shared<spdlog::logger>("req " + std::to_string(id), base->sinks().begin(), base->sinks().end());
  log->set_level(base->level());
  return log;
}

// The planner names proto fields of PlanOptions; a client sent them as plan_options.
Status in_field(const std::string& prefix, const Status& s) {
  return s.ok() ? s : Status(s.code(), prefix + s.message());
}

// A streaming method: progress events while `run` works, then the result as the last event.
template <class Event, class Run>
grpc::Status stream(grpc::ServerWriter<Event>* writer, Run run) {
  Event last;
  const grpc::Status s = run(last.mutable_result(), [writer](const v1::Progress& p) {
    Event e;
    *e.mutable_progress() = p;
    writer->Write(e);
  });
  if (s.ok()) writer->Write(last);
  return s;
}

}  // namespace

// One request from arrival to its log line.
struct AccessibilityService::Job {
  Job(const char* method, const char* options_field, grpc::ServerContext* context, uint64_t id)
      : method(method), options_field(options_field), context(context), log(request_logger(id)), board(start) {}

  const char* method;
  const char* options_field;  // where the request holds its AnalyzeOptions, for messages
  grpc::ServerContext* context;
  const Clock::time_point start = Clock::now();
  std::shared_ptr<spdlog::logger> log;
  std::stop_source stop;
  ProgressBoard board;
  std::string name = "?", hash;
  uint32_t faces = 0;
  bool cached = false;

  // The status the client sees, and the request's one log line.
  grpc::Status finish(const Status& s) {
    grpc::Status out(static_cast<grpc::StatusCode>(s.code()), s.message());
    if (s.code() == StatusCode::kCancelled && context->IsCancelled()) {
      out = deadline_passed(*context) ? grpc::Status(grpc::DEADLINE_EXCEEDED, "the request's deadline passed")
                                      : grpc::Status(grpc::CANCELLED, "the client cancelled the request");
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    log->info("{} from {}: '{}' sha256 {}{}: {} in {:.3f} s{}{}", method, context->peer(), name, hash.substr(0, 12),
              faces ? fmt::format(" {} faces", faces) : std::string(), code_name(out.error_code()), seconds,
              cached ? " (cached)" : "", out.ok() ? std::string() : fmt::format(" - {}", out.error_message()));
    return out;
  }
};

AccessibilityService::AccessibilityService(Limits limits, unsigned threads)
    : limits_(std::move(limits)),
      threads_(threads),
      slots_(limits_.max_jobs, limits_.max_queue),
      cache_(limits_.cache_entries) {}

Status AccessibilityService::with_analysis(Job& job, const v1::Part& part, v1::AnalyzeOptions options,
                                          const ProgressSink& progress,
                                          const std::function<Status(const Analysis&)>& then) {
  if (Status s = gvm::validate(options); !s.ok()) return in_field(job.options_field, s);
  StatusOr<PartBytes> bytes = load_part(part, limits_);
  if (!bytes.ok()) return bytes.status();
  job.name = bytes->name;
  job.hash = bytes->hash;
  grpc::ServerContext* context = job.context;
  StatusOr<JobSlots::Slot> slot = slots_.acquire([context] { return context->IsCancelled(); });
  if (!slot.ok()) return slot.status();

  RequestWatch watch(context, job.stop, progress ? std::function<void()>([&] {
    if (auto p = job.board.take_if_changed()) progress(*p);
  }) : std::function<void()>());
  if (options.threads() == 0 || options.threads() > threads_) options.set_threads(threads_);
  const std::string key = AnalysisCache::key(bytes->hash, options);
  std::optional<Analysis> analysis = cache_.find(key);
  job.cached = analysis.has_value();
  if (!analysis) {
    AnalyzeRequest request;
    request.part_bytes = bytes->bytes;
    request.part_format = bytes->format;
    request.part_name = bytes->name;
    request.groups_json = bytes->groups_json;
    request.options = options;
    request.max_faces = limits_.max_faces;
    request.stop = job.stop.get_token();
    request.logger = job.log;
    request.progress = [&job](size_t done, size_t total) {
      job.board.set("analysis", done, total);
      return !job.stop.stop_requested();
    };
    StatusOr<Analysis> computed = gvm::analyze(request);
    if (!computed.ok()) return computed.status();
    cache_.insert(key, *computed);
    analysis = std::move(*computed);
  }
  job.faces = analysis->part().input_faces;
  return then(*analysis);
}

grpc::Status AccessibilityService::analyze(grpc::ServerContext* context, const v1::AnalyzeRequest& request,
                                           v1::AnalyzeResponse* response, const ProgressSink& progress) {
  Job job("Analyze", "options.", context, next_id_++);
  const Status s = with_analysis(job, request.part(), request.options(), progress, [&](const Analysis& analysis) {
    *response->mutable_analysis() = to_proto(analysis);
    response->set_cached(job.cached);
    return Status::Ok();
  });
  return job.finish(s);
}

grpc::Status AccessibilityService::plan(grpc::ServerContext* context, const v1::PlanRequest& request,
                                        v1::PlanResponse* response, const ProgressSink& progress) {
  Job job("Plan", "analyze_options.", context, next_id_++);
  v1::PlanOptions options = request.plan_options();
  if (Status s = planner::validate(options); !s.ok()) return job.finish(in_field("plan_options.", s));
  const Status s = with_analysis(job, request.part(), request.analyze_options(), progress, [&](const Analysis& analysis) {
    if (options.threads() == 0 || options.threads() > threads_) options.set_threads(threads_);
    planner::PlanControl control;
    control.stop = job.stop.get_token();
    control.progress = [&job](std::string_view phase, size_t done, size_t total) {
      job.board.set(phase, done, total);
      return !job.stop.stop_requested();
    };
    StatusOr<planner::SetupPlan> plan = planner::plan(analysis, options, control);
    if (!plan.ok()) return plan.status();
    *response->mutable_plan() = std::move(plan->message);
    if (request.include_analysis()) *response->mutable_analysis() = to_proto(analysis);
    response->set_cached(job.cached);
    return Status::Ok();
  });
  return job.finish(s);
}

grpc::Status AccessibilityService::Analyze(grpc::ServerContext* context, const v1::AnalyzeRequest* request,
                                           v1::AnalyzeResponse* response) {
  return analyze(context, *request, response, {});
}

grpc::Status AccessibilityService::Plan(grpc::ServerContext* context, const v1::PlanRequest* request,
                                        v1::PlanResponse* response) {
  return plan(context, *request, response, {});
}

grpc::Status AccessibilityService::AnalyzeStream(grpc::ServerContext* context, const v1::AnalyzeRequest* request,
                                                 grpc::ServerWriter<v1::AnalyzeEvent>* writer) {
  return stream(writer, [&](v1::AnalyzeResponse* result, const ProgressSink& progress) {
    return analyze(context, *request, result, progress);
  });
}

grpc::Status AccessibilityService::PlanStream(grpc::ServerContext* context, const v1::PlanRequest* request,
                                              grpc::ServerWriter<v1::PlanEvent>* writer) {
  return stream(writer, [&](v1::PlanResponse* result, const ProgressSink& progress) {
    return plan(context, *request, result, progress);
  });
}

}  // namespace gvm::daemon
