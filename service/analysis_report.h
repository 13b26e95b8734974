// The readable report of `gvm analyze`.
#pragma once

#include <ostream>

#include "gvm/v1/gvm.pb.h"

namespace gvm {

void print_report(const v1::Analysis& analysis, std::ostream& out);

}  // namespace gvm
