// The readable report of `gvm analyze`.
#pragma once

#include <ostream>
#include <string>

#include "gvm/v1/gvm.pb.h"

namespace gvm {

void print_report(const v1::Analysis& analysis, std::ostream& out);

// "  STEP: 18 B-rep faces, file unit millimetre (coordinates in mm), tessellated at ...\n"
// for a STEP part, nothing for a mesh.
std::string step_line(const v1::PartSummary& part);

}  // namespace gvm
