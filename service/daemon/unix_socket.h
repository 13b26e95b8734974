// The daemon's Unix socket: where it lives by default, a directory only its owner (and,
// when asked, a group) can enter, never over a live daemon's socket, and its mode.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "gvm/status.h"

namespace gvm::daemon {

// $XDG_RUNTIME_DIR/gvmd.sock, else /tmp/gvmd-$UID/gvmd.sock.
std::filesystem::path default_socket_path();

struct SocketAccess {
  unsigned mode = 0600;          // of the socket
  std::optional<std::string> group;
};

// Creates the socket's directory (mode 0700, 0750 when shared with a group) or checks that
// an existing one is ours and closed to others; removes a stale socket left by a daemon
// that died, and refuses (FAILED_PRECONDITION) when a daemon is listening there.
Status prepare_socket_path(const std::filesystem::path& socket, const SocketAccess& access);

// Gives the created socket its mode and group.
Status apply_socket_access(const std::filesystem::path& socket, const SocketAccess& access);

}  // namespace gvm::daemon
