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
// What a STEP part's tessellation kept of the B-rep, in one line.
std::string tessellation_text(const v1::StepTessellation& tessellation);

}  // namespace gvm
