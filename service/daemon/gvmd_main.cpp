// gvmd: the accessibility engine and planner as a daemon (gRPC, gvm.v1.Accessibility),
// normally on a Unix socket only its owner can reach.
#include <grpcpp/ext/proto_server_reflection_plugin.h>
#include <grpcpp/grpcpp.h>
#include <grpcpp/health_check_service_interface.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <sys/stat.h>
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <thread>

#include "accessibility_service.h"
#include "malformed_request.h"
#include "unix_socket.h"

namespace {

namespace fs = std::filesystem;
using gvm::daemon::Limits;

struct Options {
  std::string listen;
  unsigned threads = 0;
  double max_request_mb = 256;
  double grace_seconds = 10;
  std::string socket_mode = "0600";
  std::string socket_group;
  std::vector<std::string> allow_paths;
  bool verbose = false, quiet = false;
  Limits limits;
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("--listen", o.listen,
                 "unix:PATH (default: unix:" + gvm::daemon::default_socket_path().string() +
                     ") or tcp:127.0.0.1:PORT (only when asked: anyone on the host can connect)");
  app.add_option("--threads", o.threads, "worker threads shared by all requests (default: all cores)")
      ->check(CLI::Range(0u, 1024u));
  app.add_option("--max-jobs", o.limits.max_jobs, "requests computing at once")->capture_default_str()->check(CLI::Range(1u, 1024u));
  app.add_option("--max-queue", o.limits.max_queue, "requests waiting behind them; more are refused (RESOURCE_EXHAUSTED)")
      ->capture_default_str();
  app.add_option("--max-request-mb", o.max_request_mb, "largest part accepted, MiB")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 2047.0));  // gRPC's limit is an int of bytes
  app.add_option("--max-faces", o.limits.max_faces, "most input faces accepted (0: no limit)")->capture_default_str();
  app.add_option("--cache-entries", o.limits.cache_entries, "analyses kept for later requests on the same part (0: none)")
      ->capture_default_str();
  app.add_option("--allow-path", o.allow_paths, "a directory whose parts may be named by path in requests (repeatable)")
      ->check(CLI::ExistingDirectory);
  app.add_option("--socket-mode", o.socket_mode, "the Unix socket's mode, octal")->capture_default_str();
  app.add_option("--socket-group", o.socket_group, "share the socket (and its directory) with this group");
  app.add_option("--grace", o.grace_seconds, "on SIGTERM/SIGINT, seconds running requests may take to finish")
      ->capture_default_str()->check(CLI::Range(0.0, 86400.0));
  app.add_flag("-v,--verbose", o.verbose, "log details (debug level)");
  app.add_flag("-q,--quiet", o.quiet, "log only errors");
}

void set_up_logging(const Options& o) {
  auto logger = spdlog::stderr_color_mt("gvmd");
  spdlog::set_default_logger(logger);
  spdlog::set_pattern("%Y-%m-%d %H:%M:%S.%e %n %l: %v");
  spdlog::set_level(o.verbose ? spdlog::level::debug : o.quiet ? spdlog::level::err : spdlog::level::info);
}

// The canonical served directories.
std::vector<fs::path> served(const std::vector<std::string>& dirs) {
  std::vector<fs::path> out;
  for (const std::string& d : dirs) out.push_back(fs::canonical(d));
  return out;
}

int fail(const std::string& message) {
  spdlog::error("{}", message);
  return 1;
}

// Blocks until SIGTERM or SIGINT (blocked in every thread, so only this wait sees them).
int wait_for_signal(const sigset_t& signals) {
  int signal = 0;
  sigwait(&signals, &signal);
  return signal;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"gvmd - the exact accessibility engine and setup planner as a gRPC daemon (gvm.v1.Accessibility)"};
  Options o;
  add_options(app, o);
  app.set_version_flag("--version", std::string("gvmd ") + GVM_VERSION);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "gvmd: " << e.what() << "\nRun 'gvmd --help' for usage.\n";
    return 2;
  }
  set_up_logging(o);

  unsigned mode = 0;
  try {
    mode = static_cast<unsigned>(std::stoul(o.socket_mode, nullptr, 8));
  } catch (...) {
    return fail("--socket-mode needs an octal mode such as 0600, not '" + o.socket_mode + "'");
  }
  o.limits.max_request_bytes = static_cast<size_t>(o.max_request_mb * (1 << 20));
  o.limits.allowed_paths = served(o.allow_paths);
  const unsigned threads = o.threads ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, threads);

  std::string address = o.listen.empty() ? "unix:" + gvm::daemon::default_socket_path().string() : o.listen;
  std::optional<fs::path> socket;
  gvm::daemon::SocketAccess access{mode, o.socket_group.empty() ? std::nullopt : std::optional(o.socket_group)};
  if (address.rfind("unix:", 0) == 0) {
    socket = fs::absolute(address.substr(5));
    address = "unix:" + socket->string();
    if (gvm::Status s = gvm::daemon::prepare_socket_path(*socket, access); !s.ok()) return fail(s.message());
  } else if (address.rfind("tcp:", 0) == 0) {
    address = address.substr(4);
  } else {
    return fail("--listen needs unix:PATH or tcp:HOST:PORT, not '" + address + "'");
  }

  // SIGTERM and SIGINT are taken by the main thread's wait, never by a worker.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGINT);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  gvm::daemon::AccessibilityService service(o.limits, threads);
  grpc::EnableDefaultHealthCheckService(true);
  grpc::reflection::InitProtoReflectionServerBuilderPlugin();
  grpc::ServerBuilder builder;
  builder.AddListeningPort(address, grpc::InsecureServerCredentials());
  builder.RegisterService(&service);
  builder.SetMaxReceiveMessageSize(static_cast<int>(std::min<size_t>(o.limits.max_request_bytes + (1 << 20), INT32_MAX)));
  builder.SetMaxSendMessageSize(INT32_MAX);
  builder.experimental().SetInterceptorCreators(gvm::daemon::malformed_request_interceptors());
  const mode_t old_umask = ::umask(0177);  // the socket is never open wider than 0600, even briefly
  std::unique_ptr<grpc::Server> server = builder.BuildAndStart();
  ::umask(old_umask);
  if (!server) return fail("cannot listen on " + address);
  if (socket) {
    if (gvm::Status s = gvm::daemon::apply_socket_access(*socket, access); !s.ok()) return fail(s.message());
  }
  server->GetHealthCheckService()->SetServingStatus("gvm.v1.Accessibility", true);
  spdlog::info("listening on {} ({} threads, {} jobs at once, queue {}, cache {} analyses)", address, threads,
               o.limits.max_jobs, o.limits.max_queue, o.limits.cache_entries);

  const int signal = wait_for_signal(signals);
  spdlog::info("{}: draining (running requests have {} s)", signal == SIGTERM ? "SIGTERM" : "SIGINT", o.grace_seconds);
  server->GetHealthCheckService()->SetServingStatus(false);  // every service, "" included
  service.drain();
  server->Shutdown(std::chrono::system_clock::now() +
                   std::chrono::milliseconds(static_cast<int64_t>(o.grace_seconds * 1000)));
  server->Wait();
  if (socket) fs::remove(*socket);
  spdlog::info("stopped");
  return 0;
}
