// What every fuzz target asserts about a refusal: a clean error is kInvalidArgument (bad
// input, named) or kResourceExhausted (a limit), always with a message. Anything else --
// kInternal, an empty message -- is a finding, reported by abort() so that libFuzzer keeps
// the input.
#pragma once

#include <cstdio>
#include <cstdlib>

#include "gvm/status.h"

namespace gvm::fuzz {

inline void expect_clean_error(const Status& status) {
  if (status.ok()) return;
  const bool expected_code = status.code() == StatusCode::kInvalidArgument ||
                             status.code() == StatusCode::kResourceExhausted;
  if (!expected_code || status.message().empty()) {
    std::fprintf(stderr, "unexpected status %d: '%s'\n", static_cast<int>(status.code()),
                 status.message().c_str());
    std::abort();
  }
}

// An invariant of a successful result that does not hold.
[[noreturn]] inline void broken(const char* what) {
  std::fprintf(stderr, "broken invariant: %s\n", what);
  std::abort();
}

}  // namespace gvm::fuzz
