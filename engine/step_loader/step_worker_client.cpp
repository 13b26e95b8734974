// read_step (gvm/step.h): the file's bytes handed to a worker process (gvm-step-worker),
// which reads and tessellates them with Open CASCADE and sends the part back. Whatever
// the reader does with a hostile file -- crash, loop, allocate without bound -- costs the
// worker, never this process: it is started with its limits (it sets them on itself
// before reading), all descriptors but its three sockets closed, and killed when the
// caller stops, when it runs over its time, or when this process dies.
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "step_loader/step_module_loader.h"
#include "step_loader/step_worker_messages.h"

extern char** environ;

namespace gvm {
namespace {

using Clock = std::chrono::steady_clock;
using step_internal::beside_program;

constexpr double kDefaultSeconds = 600;
constexpr uint64_t kGiB = uint64_t(1) << 30;

struct Limits {
  uint64_t memory = 0;
  double seconds = 0;
};

Limits limits_of(size_t bytes, const StepOptions& o) {
  Limits l;
  l.memory = o.max_memory_bytes > 0 ? o.max_memory_bytes : std::max<uint64_t>(2 * kGiB, kGiB + 256 * uint64_t(bytes));
  l.seconds = o.max_seconds > 0 ? o.max_seconds : kDefaultSeconds;
  return l;
}

std::string size_text(uint64_t bytes) {
  std::ostringstream s;
  s.precision(3);
  if (bytes < kGiB) s << double(bytes) / double(1 << 20) << " MiB";
  else s << double(bytes) / double(kGiB) << " GiB";
  return s.str();
}

const char* signal_name(int sig) {
  switch (sig) {
    case SIGSEGV: return "SIGSEGV";
    case SIGABRT: return "SIGABRT";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGKILL: return "SIGKILL";
    case SIGXCPU: return "SIGXCPU";
    default: return "";
  }
}

// A socket pair whose ends close on exec (the worker gets its own end as 0, 1 or 2).
struct Channel {
  int ours = -1, theirs = -1;
  bool open() {
    int fds[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) return false;
    ours = fds[0], theirs = fds[1];
    return true;
  }
  void close_theirs() {
    if (theirs >= 0) ::close(theirs), theirs = -1;
  }
  void close_ours() {
    if (ours >= 0) ::close(ours), ours = -1;
  }
  ~Channel() {
    close_theirs();
    close_ours();
  }
};

// The running worker: its pid, and the request and reply moving through its sockets.
class Worker {
 public:
  Worker(const std::string& source, const Limits& limits) : source_(source), limits_(limits) {}
  ~Worker() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      reap();
    }
  }

  Status start(const std::string& path) {
    if (!in_.open() || !out_.open() || !err_.open()) return Internal(source_ + ": cannot make the STEP worker's sockets");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in_.theirs, 0);
    posix_spawn_file_actions_adddup2(&actions, out_.theirs, 1);
    posix_spawn_file_actions_adddup2(&actions, err_.theirs, 2);
    posix_spawn_file_actions_addclosefrom_np(&actions, 3);
    const std::string memory = std::to_string(limits_.memory);
    const std::string seconds = std::to_string(static_cast<uint64_t>(std::ceil(limits_.seconds)));
    const std::string parent = std::to_string(::getpid());
    std::vector<char*> argv = {const_cast<char*>(path.c_str()), const_cast<char*>(memory.c_str()),
                               const_cast<char*>(seconds.c_str()), const_cast<char*>(parent.c_str()), nullptr};
    // Few malloc arenas: their reserved address space would count against the limit.
    std::vector<std::string> env = {"MALLOC_ARENA_MAX=2"};
    for (char** e = environ; *e; ++e) {
      if (std::strncmp(*e, "MALLOC_ARENA_MAX=", 17) != 0) env.emplace_back(*e);
    }
    std::vector<char*> envp;
    for (std::string& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);
    const int rc = posix_spawn(&pid_, path.c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    in_.close_theirs(), out_.close_theirs(), err_.close_theirs();
    if (rc != 0) {
      pid_ = -1;
      return Internal(source_ + ": STEP input needs the worker " + path + ", which could not be started (" +
                      std::strerror(rc) + ")");
    }
    return Status::Ok();
  }

  // Sends the request, collects the reply, and waits for the worker to end: stopped by
  // `stop` (kCancelled) or the time limit.
  Status run(const std::string& request, const std::stop_token& stop) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(limits_.seconds + 5);
    size_t sent = 0;
    if (request.empty()) in_.close_ours();
    while (out_.ours >= 0 || err_.ours >= 0) {
      if (stop.stop_requested()) return Status(StatusCode::kCancelled, source_ + ": reading cancelled");
      if (Clock::now() > deadline) {
        return ResourceExhausted(source_ + ": the STEP reader ran over its time limit of " +
                                 std::to_string(static_cast<uint64_t>(limits_.seconds)) + " s");
      }
      pollfd fds[3] = {{in_.ours, POLLOUT, 0}, {out_.ours, POLLIN, 0}, {err_.ours, POLLIN, 0}};
      if (::poll(fds, 3, 50) < 0 && errno != EINTR) return Internal(source_ + ": poll failed");
      if (in_.ours >= 0 && (fds[0].revents & (POLLOUT | POLLERR | POLLHUP))) {
        const ssize_t n = ::send(in_.ours, request.data() + sent, request.size() - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
        if (n > 0) sent += static_cast<size_t>(n);
        if (n < 0 && errno != EAGAIN && errno != EINTR) in_.close_ours();  // the worker is gone: its status says why
        if (sent == request.size()) in_.close_ours();
      }
      drain(out_, fds[1].revents, reply_);
      drain(err_, fds[2].revents, messages_);
    }
    reap();
    return Status::Ok();
  }

  // What the worker's end says about the part.
  StatusOr<StepPart> result() const {
    if (WIFSIGNALED(status_)) {
      const int sig = WTERMSIG(status_);
      if (sig == SIGXCPU) {
        return ResourceExhausted(source_ + ": the STEP reader ran over its CPU time limit of " +
                                 std::to_string(static_cast<uint64_t>(limits_.seconds)) + " s");
      }
      return InvalidArgument(source_ + ": the STEP reader crashed on this file (signal " + std::to_string(sig) +
                             (*signal_name(sig) ? std::string(", ") + signal_name(sig) : "") + ")" + near_limit() +
                             last_words());
    }
    v1::StepWorkerReply reply;
    if (!WIFEXITED(status_) || WEXITSTATUS(status_) != 0 || !reply.ParseFromString(reply_)) {
      return Internal(source_ + ": the STEP reader ended without an answer (exit status " +
                      std::to_string(WIFEXITED(status_) ? WEXITSTATUS(status_) : -1) + ")" + last_words());
    }
    StatusOr<StepPart> part = step_internal::result_of(reply);
    if (!part.ok() && part.status().code() == StatusCode::kResourceExhausted &&
        part.status().message().ends_with("out of memory while reading")) {
      return ResourceExhausted(source_ + ": the STEP reader exceeded its memory limit of " + size_text(limits_.memory));
    }
    return part;
  }

 private:
  // Reads what is there; closes the channel at its end.
  static void drain(Channel& c, short revents, std::string& into) {
    if (c.ours < 0 || !(revents & (POLLIN | POLLHUP | POLLERR))) return;
    char buf[1 << 16];
    const ssize_t n = ::recv(c.ours, buf, sizeof buf, MSG_DONTWAIT);
    if (n > 0) {
      into.append(buf, static_cast<size_t>(n));
    } else if (n == 0 || (errno != EAGAIN && errno != EINTR)) {
      c.close_ours();
    }
  }

  void reap() {
    rusage usage{};
    while (pid_ > 0 && ::wait4(pid_, &status_, 0, &usage) < 0 && errno == EINTR) {
    }
    peak_bytes_ = uint64_t(usage.ru_maxrss) * 1024;
    pid_ = -1;
  }

  // Open CASCADE does not always check an allocation: a crash with the memory mostly used
  // up is likely the limit's doing, and the user can raise it.
  std::string near_limit() const {
    if (2 * peak_bytes_ < limits_.memory) return "";
    return " with " + size_text(peak_bytes_) + " of its memory limit of " + size_text(limits_.memory) +
           " in use: likely out of memory (--step-memory, step.reader_memory_mb, raises it)";
  }

  // The end of what the worker wrote to its standard error, for the message.
  std::string last_words() const {
    std::string text = messages_;
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    if (text.empty()) return "";
    const size_t line = text.rfind('\n');
    std::string last = line == std::string::npos ? text : text.substr(line + 1);
    if (last.size() > 300) last = last.substr(0, 300) + "...";
    return ": " + last;
  }

  std::string source_;
  Limits limits_;
  Channel in_, out_, err_;
  pid_t pid_ = -1;
  int status_ = 0;
  uint64_t peak_bytes_ = 0;  // the worker's largest resident size
  std::string reply_, messages_;
};

}  // namespace

StatusOr<StepPart> read_step(std::string_view bytes, const StepOptions& options, const std::string& source) {
  if (options.stop.stop_requested()) return Status(StatusCode::kCancelled, source + ": reading cancelled");
  const Limits limits = limits_of(bytes.size(), options);
  std::string request;
  if (!step_internal::worker_request(bytes, options, source).SerializeToString(&request)) {
    return Internal(source + ": the STEP request could not be written");
  }
  Worker worker(source, limits);
  if (Status s = worker.start(beside_program(GVM_STEP_WORKER)); !s.ok()) return s;
  if (Status s = worker.run(request, options.stop); !s.ok()) return s;
  StatusOr<StepPart> part = worker.result();
  if (part.ok()) part->mesh.source = source;
  return part;
}

StatusOr<StepPart> read_step(const std::string& path, const StepOptions& options) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return NotFound(path + ": no such file");
  if (std::filesystem::is_directory(path, ec))
    return InvalidArgument(path + ": is a directory, not a STEP file");
  std::ifstream in(path, std::ios::binary);
  if (!in) return NotFound(path + ": cannot be opened for reading");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) return InvalidArgument(path + ": read error");
  return read_step(std::string_view(bytes.view()), options, path);
}

}  // namespace gvm
