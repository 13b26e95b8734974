#include "cbc_cover.h"

#include <CbcHeuristic.hpp>
#include <CbcHeuristicGreedy.hpp>
#include <CbcHeuristicLocal.hpp>
#include <CbcModel.hpp>
#include <CglZeroHalf.hpp>
#include <ClpSolve.hpp>
#include <CoinError.hpp>
#include <CoinPackedMatrix.hpp>
#include <OsiClpSolverInterface.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <string>

#include <spdlog/spdlog.h>

#include "cbc_poll.h"
#include "cover_bounds.h"

namespace gvm::planner {
namespace {

// Thread safety. Cbc 2.10.8, Clp 1.17.6, Cgl 0.60.3 and CoinUtils 2.11.4 as Debian builds
// them keep process-wide mutable state on the branch-and-cut path, so two searches must not
// overlap in one process:
//  - CoinFactorization::factorSparseSmall/Large (CoinFactorization2.cpp) increment a
//    file-static counter on every factorization, i.e. in every LP solve: a data race;
//  - ClpSimplex::initialSolve(ClpSolve&) stores the model in a file-static `currentModel`
//    and swaps the process's SIGINT handler ("Allow for interrupts / But is this threadsafe
//    ? (so switched off by option)", ClpSolve.cpp) unless ClpSolve special option 2 is set,
//    as make_lp does;
//  - CglZeroHalf's separator keeps its state in file statics (Cgl012cut.cpp), and
//    CoinDrand48 (CoinHelperFunctions.hpp; called by CglOddHole, CglDuplicateRow,
//    CbcHeuristicRandRound, CbcModel::analyzeObjective) a process-wide seed.
// (Found with `nm` and `objdump` on the installed static libraries, then in the sources.)
// The maintainers agree: "CBC itself is still not 100% stable with multiple threads"
// (coin-or/Cbc#223); CbcMain needs a -DCBC_THREAD_SAFE build (coin-or/Cbc#332). So every
// use of Cbc/Clp here takes the one SolverTurn. The generators used here re-initialise their state
// on each call and none draws on CoinDrand48, so a result does not depend on earlier solves.
//
// A turn is a flag under a mutex rather than a std::timed_mutex held throughout: waiting
// for it still honours a cancel or the deadline, and every lock is a plain mutex that
// ThreadSanitizer sees (libstdc++'s timed_mutex::try_lock_for calls
// pthread_mutex_clocklock, which GCC 12's TSan does not intercept).
class SolverTurn {
 public:
  // Waits for the solver; owns() is false when `stop` asked to stop first.
  explicit SolverTurn(CoverStop& stop) {
    Shared& s = shared();
    std::unique_lock lock(s.mutex);
    while (s.busy) {
      if (stop.should_stop()) return;
      s.freed.wait_for(lock, std::chrono::milliseconds(20));
    }
    s.busy = owns_ = true;
  }
  ~SolverTurn() {
    if (!owns_) return;
    Shared& s = shared();
    {
      std::lock_guard lock(s.mutex);
      s.busy = false;
    }
    s.freed.notify_one();
  }
  SolverTurn(const SolverTurn&) = delete;
  SolverTurn& operator=(const SolverTurn&) = delete;
  bool owns() const { return owns_; }

 private:
  struct Shared {
    std::mutex mutex;
    std::condition_variable freed;
    bool busy = false;
  };
  static Shared& shared() {
    static Shared s;
    return s;
  }
  bool owns_ = false;
};

OsiClpSolverInterface make_lp(const CoverInstance& instance) {
  const int rows = static_cast<int>(instance.item_count());
  const int columns = static_cast<int>(instance.candidate_count());
  CoinPackedMatrix matrix(true, 0, 0);
  matrix.setDimensions(rows, 0);
  for (const std::vector<uint32_t>& items : instance.items_of) {
    const std::vector<int> index(items.begin(), items.end());
    const std::vector<double> ones(items.size(), 1.0);
    matrix.appendCol(static_cast<int>(index.size()), index.data(), ones.data());
  }
  const std::vector<double> column_lower(columns, 0.0), column_upper(columns, 1.0), cost(columns, 1.0);
  const std::vector<double> row_lower(rows, 1.0), row_upper(rows, COIN_DBL_MAX);
  OsiClpSolverInterface lp;
  lp.loadProblem(matrix, column_lower.data(), column_upper.data(), cost.data(), row_lower.data(),
                 row_upper.data());
  for (int c = 0; c < columns; ++c) lp.setInteger(c);
  ClpSolve options;
  options.setSpecialOption(2, 1);  // no SIGINT handler (see the note on thread safety)
  lp.setSolveOptions(options);
  lp.messageHandler()->setLogLevel(0);
  lp.getModelPtr()->messageHandler()->setLogLevel(0);
  return lp;
}

// Cuts and heuristics that suit covering rows. Zero-half cuts are the strong family for set
// covering (odd-cycle and other {0, 1/2}-Chvatal-Gomory inequalities of the covering rows).
// Gomory and probing cuts were measured and left out: on random covers of 100-300 items
// Gomory cuts made the search 2-3 times slower (denser LPs), probing about 30% slower, and
// on sphere-cap covers neither changed much. Rounding, the greedy-cover heuristic and the
// swap-based local search all target covering problems and cost little.
void configure(CbcModel& model) {
  model.setLogLevel(0);
  model.messageHandler()->setLogLevel(0);
  model.solver()->messageHandler()->setLogLevel(0);
  model.setNumberThreads(0);

  CglZeroHalf zero_half;
  model.addCutGenerator(&zero_half, -1, "ZeroHalf");

  CbcRounding rounding(model);
  model.addHeuristic(&rounding);
  CbcHeuristicGreedyCover greedy(model);
  model.addHeuristic(&greedy);
  CbcHeuristicLocal local(model);
  model.addHeuristic(&local);
}

std::vector<uint32_t> columns_at_one(const double* x, uint32_t columns) {
  std::vector<uint32_t> chosen;
  for (uint32_t c = 0; c < columns; ++c) {
    if (x[c] > 0.5) chosen.push_back(c);
  }
  return chosen;
}

// The objective is integral, so a proven fractional bound rounds up (with a tolerance for
// the LP's own).
uint32_t round_up_bound(double bound) {
  if (!std::isfinite(bound) || bound <= 0) return 0;
  return static_cast<uint32_t>(std::ceil(bound - 1e-6));
}

struct SearchOutcome {
  std::vector<uint32_t> best;  // empty when no cover better than the start was found
  uint32_t bound = 0;          // proven (0: nothing proven beyond the caller's bound)
  double lp = 0;               // root LP value (0 when not solved)
  uint64_t nodes = 0;
  bool seconds_limit = false;
};

// A proven bound from the finished or stopped search. After an interrupt only the root LP
// (solved before the search) is trusted; otherwise Cbc's best possible value, unless it
// reaches the incumbent without a proof: Cbc reports the incumbent itself when it stopped
// before bounding anything.
uint32_t proven_bound(const CbcModel& model, uint32_t root_bound, uint32_t incumbent, bool interrupted) {
  if (interrupted) return root_bound;
  if (model.isProvenOptimal()) return std::max(root_bound, round_up_bound(model.getObjValue()));
  const uint32_t searched = round_up_bound(model.getBestPossibleObjValue());
  return searched < incumbent ? std::max(root_bound, searched) : root_bound;
}

SearchOutcome run_search(const CoverInstance& instance, const std::vector<uint32_t>& start,
                         CoverStop& stop) {
  const uint32_t columns = instance.candidate_count();
  SearchOutcome out;
  // The root LP first, on its own: its bound stays valid however the search ends.
  OsiClpSolverInterface lp = make_lp(instance);
  const auto state = std::make_shared<LpPoll::State>();
  {
    const LpPoll poll(&stop, nullptr, state);
    lp.getModelPtr()->passInEventHandler(&poll);
  }
  lp.initialSolve();
  if (state->interrupted) return out;
  if (!lp.isProvenOptimal()) throw CoinError("the LP relaxation was not solved", "initialSolve", "Clp");
  out.lp = lp.getObjValue();
  const uint32_t root_bound = round_up_bound(out.lp);

  CbcModel model(lp);  // a copy of the solver, with the optimal root basis
  configure(model);
  if (stop.has_limit()) {
    model.setUseElapsedTime(true);
    model.setMaximumSeconds(stop.seconds_left());
  }
  std::vector<double> incumbent(columns, 0.0);
  for (uint32_t c : start) incumbent[c] = 1.0;
  model.setBestSolution(incumbent.data(), static_cast<int>(columns), static_cast<double>(start.size()),
                        true);
  const CbcPoll poll(&stop);
  model.passInEventHandler(&poll);
  if (auto* clp = dynamic_cast<OsiClpSolverInterface*>(model.solver())) {
    const LpPoll lp_poll(&stop, &model, state);
    clp->getModelPtr()->passInEventHandler(&lp_poll);
  }

  model.branchAndBound();

  if (model.bestSolution() != nullptr) {
    out.best = drop_redundant(instance, columns_at_one(model.bestSolution(), columns));
    if (out.best.size() >= start.size()) out.best.clear();
  }
  const auto incumbent_size = static_cast<uint32_t>(out.best.empty() ? start.size() : out.best.size());
  out.bound = proven_bound(model, root_bound, incumbent_size, state->interrupted);
  out.nodes = static_cast<uint64_t>(std::max(0, model.getNodeCount()));
  out.seconds_limit = model.isSecondsLimitReached();
  return out;
}

}  // namespace

StatusOr<CbcCoverResult> solve_cover_with_cbc(const CoverInstance& instance,
                                              const std::vector<uint32_t>& start,
                                              uint32_t lower_bound, CoverStop& stop) {
  CbcCoverResult result;
  result.chosen = start;
  result.lower_bound = lower_bound;
  result.lp_bound = lower_bound;
  const SolverTurn turn(stop);
  if (!turn.owns() || stop.should_stop()) return result;

  SearchOutcome outcome;
  try {
    outcome = run_search(instance, start, stop);
  } catch (const CoinError& e) {
    return Internal("Cbc failed in " + e.className() + "::" + e.methodName() + ": " + e.message());
  } catch (const std::exception& e) {
    return Internal(std::string("Cbc failed: ") + e.what());
  }
  if (outcome.seconds_limit && !stop.cancelled()) stop.note_time_limit();
  result.ran = true;
  result.nodes = outcome.nodes;
  if (!outcome.best.empty()) {
    if (!covers_all(instance, outcome.best)) {
      return Internal("Cbc returned a selection that is not a cover");
    }
    result.chosen = std::move(outcome.best);
  }
  const auto size = static_cast<uint32_t>(result.chosen.size());
  result.lower_bound = std::min(size, std::max(lower_bound, outcome.bound));
  // The LP lies between the packing (a dual solution) and any cover; 0 when it was stopped.
  if (std::isfinite(outcome.lp) && outcome.lp >= lower_bound && outcome.lp <= size + 1e-6) {
    result.lp_bound = outcome.lp;
  }
  spdlog::debug("set cover: Cbc on {} items x {} candidates: {} -> {}, bound {}, LP {:.3f}, {} nodes",
                instance.item_count(), instance.candidate_count(), start.size(), size,
                result.lower_bound, result.lp_bound, result.nodes);
  return result;
}

}  // namespace gvm::planner
