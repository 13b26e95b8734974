// The readable report of `gvm plan`.
#pragma once

#include <ostream>

#include "gvm/v1/plan.pb.h"

namespace gvm {

void print_plan(const v1::Plan& plan, std::ostream& out);

}  // namespace gvm
