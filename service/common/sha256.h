// Content hashes, shared by the daemon's cache and the batches' --resume.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

namespace gvm {

// The lowercase hex SHA-256 of the pieces (each preceded by its length, so that
// different splits of the same bytes never hash alike).
std::string sha256_hex(std::initializer_list<std::string_view> pieces);

}  // namespace gvm
