// Assertion helpers shared by the test files.
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace gvm::test {

// `msg` contains `sub`; on failure both are printed.
inline ::testing::AssertionResult Has(const std::string& msg, const std::string& sub) {
  if (msg.find(sub) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << msg << "' does not contain '" << sub << "'";
}

}  // namespace gvm::test
