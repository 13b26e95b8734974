// plan_part: the library's front door, through its public headers only. Reads a part,
// computes the exact visibility maps of its features (gvm/analysis.h) and plans the fewest
// setups that reach them (gvm/planner/plan.h), then prints the setups and the proof.
//
//   plan_part PART [setup|rotary|probe]
//
// PART is a closed mesh (OFF, OBJ, STL, PLY) or a STEP file. The plan is the one
// `gvm plan PART` prints (same defaults: every feature, tolerance 1e-6 rad, automatic split).
#include <cstdio>
#include <string>

#include "gvm/analysis.h"
#include "gvm/planner/plan.h"

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: plan_part PART [setup|rotary|probe]\n");
    return 2;
  }

  // 1. Analyse: every concave region and feature with its exact maps (LVM, GVM).
  gvm::AnalyzeRequest request;
  request.part_path = argv[1];
  gvm::StatusOr<gvm::Analysis> analysis = gvm::analyze(request);
  if (!analysis.ok()) {  // the message names the offending face, edge or vertex
    std::fprintf(stderr, "plan_part: %s\n", analysis.status().message().c_str());
    return 1;
  }

  // 2. Plan on the exact maps. PlanOptions is the protobuf message gvm.v1.PlanOptions
  //    (proto/gvm/v1/plan.proto), the same one `gvm plan`, gvmd and batches fill in.
  gvm::v1::PlanOptions options;
  const std::string mode = argc == 3 ? argv[2] : "setup";
  if (mode == "rotary") {
    options.set_mode(gvm::v1::PLAN_MODE_ROTARY);
  } else if (mode == "probe") {
    options.set_mode(gvm::v1::PLAN_MODE_PROBE);
  } else if (mode != "setup") {
    std::fprintf(stderr, "plan_part: unknown mode '%s'\n", mode.c_str());
    return 2;
  }
  gvm::StatusOr<gvm::planner::SetupPlan> plan = gvm::planner::plan(*analysis, options);
  if (!plan.ok()) {
    std::fprintf(stderr, "plan_part: %s\n", plan.status().message().c_str());
    return 1;
  }

  // 3. Read the result: plan->message is gvm.v1.Plan (what `gvm plan --json` writes);
  //    plan->directions holds each setup's exact direction, for further exact decisions.
  const gvm::v1::Plan& p = plan->message;
  std::printf("%s: %zu features, %u planned whole, %u unreachable\n", argv[1], analysis->features().size(),
              p.reached(), p.unreachable_count());
  std::printf("setups: %d\n", p.setups_size());
  for (int i = 0; i < p.setups_size(); ++i) {
    const gvm::v1::Setup& s = p.setups(i);
    // A whole feature reached exactly (not only within the tolerance) has the setup's exact
    // direction in its GVM: decided here again with the exact predicates. (In rotary mode
    // the direction is the table's axis, and the GVM meets the circle normal to it.)
    int checked = 0;
    for (const gvm::v1::SetupFeature& r : s.reach()) {
      if (mode == "rotary" || r.faces_size() > 0 || r.within_tolerance()) continue;
      const gvm::Surface& f = analysis->features().at(r.feature());
      if (!f.maps.gvm || !f.maps.gvm->contains(plan->directions[i])) {
        std::fprintf(stderr, "plan_part: setup %d does not reach %s exactly\n", i + 1, f.name.c_str());
        return 1;
      }
      ++checked;
    }
    std::printf("  %d  (%7.4f, %7.4f, %7.4f)  %d features", i + 1, s.direction().x(), s.direction().y(),
                s.direction().z(), s.features_size());
    if (mode == "rotary") {
      std::printf(" (the direction is the table's axis)\n");
    } else {
      std::printf(", %d checked exactly in their GVM\n", checked);
    }
  }
  std::printf("proof: %s - no plan has fewer than %u setups (%s)\n", p.optimal() ? "optimal" : "not proven",
              p.lower_bound(), p.solver().solver().c_str());
  return 0;
}
