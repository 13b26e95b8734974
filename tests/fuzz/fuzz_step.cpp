// libFuzzer target: what gvm-step-worker does with a file -- Open CASCADE reads, checks and
// tessellates it (the STEP module, called in this process), and the part makes the round
// trip of the worker's reply -- on any bytes. A refusal must be clean; a part must come back
// from its reply whole and build a solid, or be refused cleanly by validation.
//
// Open CASCADE's own crashes are findings too, but not ours to fix: the worker contains
// them (read_step answers "the STEP reader crashed on this file"). Run it in fork mode so
// that fuzzing goes on past them (-fork=2 -ignore_crashes=1); tests/data/step-crashers/
// keeps one input of each place found.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_support.h"
#include "gvm/mesh.h"
#include "gvm/step.h"
#include "step_loader/step_module_loader.h"
#include "step_loader/step_worker_messages.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  gvm::StepOptions options;
  options.max_triangles = 20000;  // larger tessellations would slow the run without reaching more
  auto part = gvm::step_internal::read_step_in_process(bytes, options, "fuzz.stp");
  std::string wire;
  if (!gvm::step_internal::worker_reply(part).SerializeToString(&wire)) gvm::fuzz::broken("a reply not written");
  gvm::v1::StepWorkerReply reply;
  if (!reply.ParseFromString(wire)) gvm::fuzz::broken("a reply not read back");
  auto back = gvm::step_internal::result_of(reply);
  if (!part.ok()) {
    gvm::fuzz::expect_clean_error(part.status());
    if (back.ok() || back.status().code() != part.status().code() || back.status().message() != part.status().message())
      gvm::fuzz::broken("a refusal changed on its way back");
    return 0;
  }
  if (!back.ok()) gvm::fuzz::broken("a part lost on its way back");
  if (back->mesh.faces != part->mesh.faces || back->face_cad != part->face_cad)
    gvm::fuzz::broken("a part changed on its way back");
  back->mesh.source = "fuzz.stp";
  auto solid = gvm::build_solid(back->mesh);
  if (!solid.ok()) gvm::fuzz::expect_clean_error(solid.status());
  return 0;
}
