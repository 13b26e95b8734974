#include "set_cover.h"

#include <algorithm>
#include <string>
#include <utility>

#include <spdlog/spdlog.h>

#include "cbc_cover.h"
#include "cover_bounds.h"
#include "cover_reduce.h"
#include "cover_stop.h"

namespace gvm::planner {
namespace {

// Candidate lists ascending without repeats (sorted here when they are not), ids < items.
StatusOr<CoverProblem> normalized(const CoverProblem& problem) {
  CoverProblem out = problem;
  for (size_t c = 0; c < out.candidates.size(); ++c) {
    std::vector<uint32_t>& items = out.candidates[c];
    if (!std::is_sorted(items.begin(), items.end())) std::sort(items.begin(), items.end());
    items.erase(std::unique(items.begin(), items.end()), items.end());
    if (!items.empty() && items.back() >= out.items) {
      return InvalidArgument("set cover: candidate " + std::to_string(c) + " names item " +
                             std::to_string(items.back()) + " of only " + std::to_string(out.items));
    }
  }
  return out;
}

// One component's answer, on the component's local ids.
struct ComponentAnswer {
  std::vector<uint32_t> chosen;
  std::vector<uint32_t> packing;
  uint32_t lower_bound = 0;
  uint32_t greedy = 0;
  double lp_bound = 0;
  uint64_t nodes = 0;
  bool solver_ran = false;
};

StatusOr<ComponentAnswer> solve_component(const CoverInstance& instance, CoverStop& stop) {
  ComponentAnswer answer;
  answer.chosen = greedy_cover(instance);
  answer.packing = greedy_packing(instance);
  answer.greedy = static_cast<uint32_t>(answer.chosen.size());
  answer.lower_bound = static_cast<uint32_t>(answer.packing.size());
  // The packing is a dual solution: a lower bound on the LP, equal to it when greedy meets it.
  answer.lp_bound = answer.lower_bound;
  if (answer.lower_bound == answer.greedy || stop.should_stop()) return answer;

  StatusOr<CbcCoverResult> searched =
      solve_cover_with_cbc(instance, answer.chosen, answer.lower_bound, stop);
  if (!searched.ok()) return searched.status();
  answer.chosen = std::move(searched->chosen);
  answer.lower_bound = searched->lower_bound;
  answer.lp_bound = searched->lp_bound;
  answer.nodes = searched->nodes;
  answer.solver_ran = searched->ran;
  return answer;
}

void append_mapped(std::vector<uint32_t>& out, const std::vector<uint32_t>& local,
                   const std::vector<uint32_t>& ids) {
  for (uint32_t x : local) out.push_back(ids[x]);
}

void add_component(CoverSolution& solution, const CoverComponent& component, ComponentAnswer&& answer) {
  append_mapped(solution.chosen, answer.chosen, component.candidate_ids);
  append_mapped(solution.packing, answer.packing, component.item_ids);
  solution.lower_bound += answer.lower_bound;
  solution.greedy += answer.greedy;
  solution.lp_bound += answer.lp_bound;
  solution.nodes += answer.nodes;
  solution.solver_ran = solution.solver_ran || answer.solver_ran;
  solution.reduced_items += component.instance.item_count();
  solution.reduced_candidates += component.instance.candidate_count();
}

// Checks the answer against the problem itself, independently of the reductions.
Status check(const CoverProblem& problem, const CoverSolution& solution) {
  std::vector<char> covered(problem.items, 0);
  for (uint32_t c : solution.chosen) {
    for (uint32_t i : problem.candidates[c]) covered[i] = 1;
  }
  for (uint32_t i : solution.uncoverable) covered[i] = 1;
  if (std::find(covered.begin(), covered.end(), 0) != covered.end()) {
    return Internal("set cover: the chosen candidates miss a coverable item");
  }
  return Status::Ok();
}

}  // namespace

StatusOr<CoverSolution> solve_set_cover(const CoverProblem& input, const CoverOptions& options) {
  CoverStop stop(options.cancelled, options.time_limit_seconds);
  StatusOr<CoverProblem> problem = normalized(input);
  if (!problem.ok()) return problem.status();

  ReducedCover reduced = reduce_cover(*problem);
  CoverSolution solution;
  solution.uncoverable = std::move(reduced.uncoverable);
  solution.chosen = reduced.forced;
  solution.packing = reduced.forced_items;
  solution.forced = static_cast<uint32_t>(reduced.forced.size());
  solution.components = static_cast<uint32_t>(reduced.components.size());
  solution.lower_bound = solution.greedy = solution.forced;
  solution.lp_bound = solution.forced;
  for (const CoverComponent& component : reduced.components) {
    StatusOr<ComponentAnswer> answer = solve_component(component.instance, stop);
    if (!answer.ok()) return answer.status();
    add_component(solution, component, std::move(*answer));
  }
  std::sort(solution.chosen.begin(), solution.chosen.end());
  std::sort(solution.packing.begin(), solution.packing.end());
  solution.optimal = solution.chosen.size() == solution.lower_bound;
  solution.cancelled = stop.cancelled();
  solution.time_limit_reached = stop.time_limit_reached();
  solution.seconds = stop.elapsed_seconds();
  if (Status s = check(*problem, solution); !s.ok()) return s;

  spdlog::debug("set cover: {} items ({} uncoverable) x {} candidates -> {} forced, {} components "
                "of {} items x {} candidates; greedy {}, chosen {}, bound {}{}, {:.3f} s",
                problem->items, solution.uncoverable.size(), problem->candidates.size(),
                solution.forced, solution.components, solution.reduced_items,
                solution.reduced_candidates, solution.greedy, solution.chosen.size(),
                solution.lower_bound, solution.optimal ? " (optimal)" : "", solution.seconds);
  return solution;
}

}  // namespace gvm::planner
