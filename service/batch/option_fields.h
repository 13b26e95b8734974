// A CSV manifest's columns: part, groups, name, or a field of the part's PlanOptions or
// AnalyzeOptions named as in the proto ("mode", "min_clearance_degrees", "step.solid").
#pragma once

#include <string>

#include "gvm/status.h"
#include "gvm/v1/batch.pb.h"

namespace gvm::batch {

// Sets `column` of `part` from the text of its cell: numbers as gvm reads them, booleans
// true/false/1/0, enums by their proto name or its last words ("probe" for
// PLAN_MODE_PROBE). kInvalidArgument names the column and says what it needs.
Status set_column(v1::BatchPart& part, const std::string& column, const std::string& value);

}  // namespace gvm::batch
