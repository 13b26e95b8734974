// gvm-step-worker: one STEP file read and tessellated by Open CASCADE (the STEP module) in a
// process of its own, for read_step (step_loader/step_worker_client.cpp), which starts it
// as
//
//   gvm-step-worker MEMORY_BYTES CPU_SECONDS PARENT_PID
//
// with its standard input, output and error on sockets to the parent. It limits itself
// before reading anything (address space, CPU time, no core files, no new privileges,
// killed with its parent), reads one gvm.v1.StepWorkerRequest from standard input, and
// writes one gvm.v1.StepWorkerReply to standard output. Not meant to be run by hand.
#include <sys/prctl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>

#include "step_loader/step_module_loader.h"
#include "step_loader/step_worker_messages.h"

namespace {

bool limit(int resource, rlim_t soft, rlim_t hard) {
  const rlimit r{soft, hard};
  return setrlimit(resource, &r) == 0;
}

// A sanitizer's shadow memory is terabytes of address space, reserved before main: under
// a sanitizer build the address space is not limited (the CPU time still is).
#ifdef GVM_SANITIZED
constexpr bool kLimitAddressSpace = false;
#else
constexpr bool kLimitAddressSpace = true;
#endif

#ifdef GVM_SANITIZED
// Under a sanitizer a crash of Open CASCADE's must still end the worker by its signal (the
// parent reports "crashed on this file (signal 11)"), not by the sanitizer's report and
// exit status; Open CASCADE's never-freed tables are no finding of ours.
extern "C" const char* __asan_default_options() { return "handle_segv=0:handle_sigbus=0:handle_sigfpe=0:detect_leaks=0"; }
#endif

bool confine(const char* memory, const char* seconds, const char* parent) {
  const unsigned long long bytes = std::strtoull(memory, nullptr, 10), cpu = std::strtoull(seconds, nullptr, 10);
  if (bytes == 0 || cpu == 0) return false;
  if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != static_cast<pid_t>(std::atol(parent))) return false;
  return prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0 && limit(RLIMIT_CORE, 0, 0) &&
         (!kLimitAddressSpace || limit(RLIMIT_AS, bytes, bytes)) && limit(RLIMIT_CPU, cpu, cpu + 5);
}

std::string read_all(int fd) {
  std::string out;
  char buf[1 << 16];
  for (;;) {
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n > 0) out.append(buf, static_cast<size_t>(n));
    else if (n == 0 || errno != EINTR) return out;
  }
}

bool write_all(int fd, const std::string& data) {
  size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = write(fd, data.data() + done, data.size() - done);
    if (n > 0) done += static_cast<size_t>(n);
    else if (n < 0 && errno != EINTR) return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 || !confine(argv[1], argv[2], argv[3])) {
    std::fprintf(stderr, "gvm-step-worker: started by gvm to read one STEP file, not by hand\n");
    return 2;
  }
  gvm::v1::StepWorkerRequest request;
  if (!request.ParseFromString(read_all(0))) {
    std::fprintf(stderr, "gvm-step-worker: a malformed request\n");
    return 3;
  }
  gvm::StatusOr<gvm::StepPart> part = gvm::Internal("not read");
  try {
    part = gvm::step_internal::read_step_in_process(request.data(), gvm::step_internal::options_of(request),
                                                    request.source());
  } catch (const std::bad_alloc&) {
    part = gvm::ResourceExhausted(request.source() + ": out of memory while reading");
  }
  std::string reply;
  try {
    if (!gvm::step_internal::worker_reply(part).SerializeToString(&reply)) return 4;
  } catch (const std::bad_alloc&) {
    gvm::step_internal::worker_reply(gvm::ResourceExhausted(request.source() + ": out of memory while reading"))
        .SerializeToString(&reply);
  }
  // Out at once: Open CASCADE's static destructors have nothing to give back.
  _exit(write_all(1, reply) ? 0 : 5);
}
