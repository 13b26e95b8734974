// The wire format at the edge: the exact analysis and its direction sets as the protobuf
// messages of proto/gvm/v1 (doubles, rounded once here), and protobuf's JSON mapping.
#pragma once

#include <google/protobuf/message.h>

#include <string>

#include "gvm/analysis.h"
#include "gvm/direction_set.h"
#include "gvm/v1/gvm.pb.h"

namespace gvm {

v1::Analysis to_proto(const Analysis& analysis);
// Every arc of a loop or polyline is written at most 90 degrees long (vertices added
// exactly on its circle, then rounded), so the doubles decide each arc unambiguously.
void to_proto(const DirectionSet& set, v1::SphericalImage* out);
void to_proto(const Direction& d, v1::Vec3* out);
void to_proto(const PartSummary& part, v1::PartSummary* out);
void to_proto(const StepTessellation& tessellation, v1::StepTessellation* out);
v1::GvmStatus to_proto(GvmStatus status);

// Protobuf's JSON mapping (lowerCamelCase names, every field printed).
std::string to_json(const google::protobuf::Message& message);

}  // namespace gvm
