#include "unix_socket.h"

#include <grp.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace gvm::daemon {
namespace {

namespace fs = std::filesystem;

std::string octal(unsigned mode) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%04o", mode);
  return buf;
}

StatusOr<gid_t> group_id(const std::string& name) {
  if (const group* g = getgrnam(name.c_str())) return g->gr_gid;
  return InvalidArgument("--socket-group: no group '" + name + "'");
}

// Someone accepts connections on the socket.
bool live(const fs::path& socket) {
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  std::strncpy(addr.sun_path, socket.c_str(), sizeof addr.sun_path - 1);
  const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return false;
  const bool connected = ::connect(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0;
  ::close(fd);
  return connected;
}

Status check_directory(const fs::path& dir, const SocketAccess& access) {
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0) return FailedPrecondition("socket directory " + dir.string() + ": " + std::strerror(errno));
  if (!S_ISDIR(st.st_mode)) return FailedPrecondition(dir.string() + " is not a directory");
  if (st.st_uid != ::geteuid()) {
    return FailedPrecondition("the socket directory " + dir.string() + " belongs to another user; use a directory of your own");
  }
  const unsigned open_to = access.group ? 0007u : 0077u;
  if (st.st_mode & open_to) {
    return FailedPrecondition("the socket directory " + dir.string() + " (mode " + octal(st.st_mode & 07777) +
                              ") can be entered by " + (access.group ? "other users" : "other users or its group") +
                              "; put the socket in a directory only you can enter (chmod 700), or leave --listen out");
  }
  return Status::Ok();
}

}  // namespace

fs::path default_socket_path() {
  if (const char* runtime = std::getenv("XDG_RUNTIME_DIR"); runtime && *runtime) return fs::path(runtime) / "gvmd.sock";
  return fs::path("/tmp") / ("gvmd-" + std::to_string(::geteuid())) / "gvmd.sock";
}

Status prepare_socket_path(const fs::path& socket, const SocketAccess& access) {
  if (socket.string().size() >= sizeof(sockaddr_un::sun_path)) {
    return InvalidArgument("the socket path " + socket.string() + " is longer than a Unix socket path may be (" +
                           std::to_string(sizeof(sockaddr_un::sun_path) - 1) + " characters)");
  }
  const fs::path dir = socket.parent_path().empty() ? fs::path(".") : socket.parent_path();
  std::error_code ec;
  if (!fs::exists(dir, ec)) {
    if (::mkdir(dir.c_str(), access.group ? 0750 : 0700) != 0) {
      return FailedPrecondition("cannot create the socket directory " + dir.string() + ": " + std::strerror(errno));
    }
    if (access.group) {
      StatusOr<gid_t> gid = group_id(*access.group);
      if (!gid.ok()) return gid.status();
      if (::chown(dir.c_str(), static_cast<uid_t>(-1), *gid) != 0) {
        return FailedPrecondition("cannot give " + dir.string() + " to group " + *access.group + ": " + std::strerror(errno));
      }
    }
  }
  if (Status s = check_directory(dir, access); !s.ok()) return s;
  struct stat st {};
  if (::lstat(socket.c_str(), &st) != 0) return Status::Ok();
  if (!S_ISSOCK(st.st_mode)) return FailedPrecondition(socket.string() + " exists and is not a socket; not replacing it");
  if (live(socket)) return FailedPrecondition("a daemon is already listening on " + socket.string());
  if (::unlink(socket.c_str()) != 0) {
    return FailedPrecondition("cannot remove the stale socket " + socket.string() + ": " + std::strerror(errno));
  }
  return Status::Ok();
}

Status apply_socket_access(const fs::path& socket, const SocketAccess& access) {
  if (access.group) {
    StatusOr<gid_t> gid = group_id(*access.group);
    if (!gid.ok()) return gid.status();
    if (::chown(socket.c_str(), static_cast<uid_t>(-1), *gid) != 0) {
      return FailedPrecondition("cannot give the socket to group " + *access.group + ": " + std::strerror(errno));
    }
  }
  if (::chmod(socket.c_str(), access.mode) != 0) {
    return FailedPrecondition("cannot set the socket's mode: " + std::string(std::strerror(errno)));
  }
  return Status::Ok();
}

}  // namespace gvm::daemon
