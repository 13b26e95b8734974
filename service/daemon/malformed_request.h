// gRPC answers a request whose bytes do not parse as the method's message with INTERNAL
// and no message, before any service code runs. This interceptor turns that answer into
// INVALID_ARGUMENT with a message a person can act on; the service itself never answers
// INTERNAL without a message.
#pragma once

#include <grpcpp/support/server_interceptor.h>

#include <memory>
#include <vector>

namespace gvm::daemon {

std::vector<std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>> malformed_request_interceptors();

}  // namespace gvm::daemon
