// The STEP worker's request and reply (proto/gvm/v1/step_worker.proto) to and from the
// engine's types: what crosses the pipe between a program and its worker, exactly (doubles
// travel as their bits).
#pragma once

#include <string>
#include <string_view>

#include "gvm/step.h"
#include "gvm/v1/step_worker.pb.h"

namespace gvm::step_internal {

v1::StepWorkerRequest worker_request(std::string_view bytes, const StepOptions& options, const std::string& source);
// The options of a request (no stop token: the worker is stopped by being killed).
StepOptions options_of(const v1::StepWorkerRequest& request);

v1::StepWorkerReply worker_reply(const StatusOr<StepPart>& result);
// The part or the error a reply carries; kInternal when it is not a well-formed reply
// (point indices out of range, an unknown surface type, an error without a code).
StatusOr<StepPart> result_of(const v1::StepWorkerReply& reply);

}  // namespace gvm::step_internal
