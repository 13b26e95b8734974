#include "remote_client.h"

#include <grpcpp/grpcpp.h>

#include <filesystem>
#include <fstream>
#include <future>
#include <iostream>
#include <sstream>

#include "gvm/mesh.h"
#include "gvm/v1/service.grpc.pb.h"

namespace gvm::cli {
namespace {

v1::PartFormat format_of(const std::string& path) {
  switch (parse_mesh_format(std::filesystem::path(path).extension().string()).value_or(MeshFormat{-1})) {
    case MeshFormat::kStl: return v1::PART_FORMAT_STL;
    case MeshFormat::kOff: return v1::PART_FORMAT_OFF;
    case MeshFormat::kObj: return v1::PART_FORMAT_OBJ;
    case MeshFormat::kPly: return v1::PART_FORMAT_PLY;
    case MeshFormat::kStep: return v1::PART_FORMAT_STEP;
  }
  return v1::PART_FORMAT_UNSPECIFIED;  // the daemon names the problem
}

bool read_file(const std::string& path, std::string* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  *out = std::move(s).str();
  return static_cast<bool>(in) || in.eof();
}

// The part as sent: its bytes, format from the extension, and the path as the name (so
// that the analysis's source reads as it does locally).
grpc::Status make_part(const std::string& path, const std::string& groups_json, v1::Part* part) {
  if (!read_file(path, part->mutable_data())) {
    return grpc::Status(grpc::NOT_FOUND, "cannot read '" + path + "'");
  }
  part->set_format(format_of(path));
  part->set_name(path);
  part->set_groups_json(groups_json);
  return grpc::Status::OK;
}

std::shared_ptr<grpc::Channel> channel_to(const std::string& server) {
  grpc::ChannelArguments arguments;
  arguments.SetMaxReceiveMessageSize(-1);
  arguments.SetMaxSendMessageSize(-1);
  return grpc::CreateCustomChannel(server, grpc::InsecureChannelCredentials(), arguments);
}

std::string describe(const grpc::Status& s, const std::string& server) {
  if (s.error_code() == grpc::UNAVAILABLE && s.error_message().find("shutting down") == std::string::npos) {
    return "cannot reach the daemon at " + server + " (is gvmd running?): " + s.error_message();
  }
  return s.error_message();
}

// Runs `call` for every part at once and hands each result to `done` in PART order.
template <class Response, class Call, class Sink>
int for_each_part(const AnalysisArgs& args, Call call, const Sink& sink) {
  std::string groups_json;
  if (!args.groups.empty() && !read_file(args.groups, &groups_json)) {
    return failure("cannot read the groups file '" + args.groups + "'");
  }
  auto stub = v1::Accessibility::NewStub(channel_to(args.server));
  std::vector<std::future<std::pair<grpc::Status, Response>>> results;
  for (const std::string& path : args.parts) {
    results.push_back(std::async(std::launch::async, [&, path] {
      Response response;
      v1::Part part;
      grpc::Status s = make_part(path, groups_json, &part);
      if (s.ok()) {
        grpc::ClientContext context;
        if (args.timeout_seconds > 0) {
          context.set_deadline(std::chrono::system_clock::now() +
                               std::chrono::milliseconds(static_cast<int64_t>(args.timeout_seconds * 1000)));
        }
        s = call(*stub, context, std::move(part), &response);
      }
      return std::make_pair(s, std::move(response));
    }));
  }
  int exit = 0;
  for (size_t k = 0; k < results.size(); ++k) {
    auto [status, response] = results[k].get();
    if (args.parts.size() > 1 && !args.quiet) std::cout << (k ? "\n" : "") << "== " << args.parts[k] << " ==\n";
    // The engine's messages name the part already, as they do locally.
    const std::string message = describe(status, args.server);
    const int part_exit = status.ok()                            ? sink(args.parts[k], response)
                          : message.rfind(args.parts[k], 0) == 0 ? failure(message)
                                                                 : failure(args.parts[k] + ": " + message);
    exit = std::max(exit, part_exit);
  }
  return exit;
}

}  // namespace

int remote_analyze(const AnalysisArgs& args, const AnalysisSink& sink) {
  const v1::AnalyzeOptions options = analyze_request(args).options;
  return for_each_part<v1::AnalyzeResponse>(
      args,
      [&](v1::Accessibility::Stub& stub, grpc::ClientContext& context, v1::Part part, v1::AnalyzeResponse* out) {
        v1::AnalyzeRequest request;
        *request.mutable_part() = std::move(part);
        *request.mutable_options() = options;
        return stub.Analyze(&context, request, out);
      },
      sink);
}

int remote_plan(const AnalysisArgs& args, const v1::PlanOptions& options, bool include_analysis,
                const PlanSink& sink) {
  const v1::AnalyzeOptions analyze_options = analyze_request(args).options;
  return for_each_part<v1::PlanResponse>(
      args,
      [&](v1::Accessibility::Stub& stub, grpc::ClientContext& context, v1::Part part, v1::PlanResponse* out) {
        v1::PlanRequest request;
        *request.mutable_part() = std::move(part);
        *request.mutable_analyze_options() = analyze_options;
        *request.mutable_plan_options() = options;
        request.set_include_analysis(include_analysis);
        return stub.Plan(&context, request, out);
      },
      sink);
}

}  // namespace gvm::cli
