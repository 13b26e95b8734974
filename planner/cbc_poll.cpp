#include "cbc_poll.h"

#include <CbcModel.hpp>
#include <ClpSimplex.hpp>

namespace gvm::planner {
namespace {

// How long past the deadline Cbc may run before its LPs are cut short. Within it Cbc's
// own time check stops the search with its bounds intact.
constexpr double kDeadlineGrace = 0.5;

}  // namespace

void stop_cbc(CbcModel& model) {
  model.sayEventHappened();
  model.setMaximumSeconds(model.getCurrentSeconds());
}

CbcEventHandler::CbcAction CbcPoll::event(CbcEvent which) {
  if (model_ == nullptr || !stop_->should_stop()) return noAction;
  stop_cbc(*model_);
  return (which == node || which == treeStatus) ? stop : noAction;
}

int LpPoll::event(Event) {
  if (!stop_->should_stop()) return -1;
  if (cbc_ != nullptr && !state_->cbc_told) {
    state_->cbc_told = true;
    stop_cbc(*cbc_);
  }
  if (model_ != nullptr && (stop_->cancelled() || stop_->seconds_past_deadline() > kDeadlineGrace)) {
    state_->interrupted = true;
    model_->setMaximumIterations(0);  // again at every event: hot starts reset the limit
  }
  return -1;  // carry on (to the iteration limit)
}

}  // namespace gvm::planner
