// How a cancel or the deadline reaches a running Cbc search. Cbc polls nothing of ours by
// itself: these handlers check the CoverStop at each of Cbc's events and at each simplex
// iteration, and make Cbc wind down.
#pragma once

#include <CbcEventHandler.hpp>
#include <ClpEventHandler.hpp>

#include <memory>

#include "cover_stop.h"

class CbcModel;

namespace gvm::planner {

// Makes Cbc stop at its next check: the flag its own time limit raises, and a time limit
// that has already passed. Cbc checks between root cut passes, heuristics and nodes.
void stop_cbc(CbcModel& model);

// Polls at each of Cbc's events (nodes, solutions, heuristic passes).
class CbcPoll : public CbcEventHandler {
 public:
  explicit CbcPoll(CoverStop* stop) : stop_(stop) {}
  CbcAction event(CbcEvent which) override;
  CbcEventHandler* clone() const override { return new CbcPoll(*this); }

 private:
  CoverStop* stop_;
};

// Polls at each simplex iteration, since Cbc's events are rare during root processing.
// Once stopped it tells Cbc (when given one). Cbc does not check its clock inside a round
// of strong branching, which can take seconds, so on a cancel, or well past the deadline,
// it also cuts every LP short by Clp's own interrupt (an iteration limit of 0, what Clp's
// SIGINT handler does): then the LP answers Cbc sees are not final, and its bounds are not
// to be trusted. Clp clones this handler into every solver copied from the one it is given
// (all on the solving thread); the clones share one state.
class LpPoll : public ClpEventHandler {
 public:
  struct State {
    bool cbc_told = false;
    bool interrupted = false;  // some LP was cut short
  };

  LpPoll(CoverStop* stop, CbcModel* cbc, std::shared_ptr<State> state)
      : stop_(stop), cbc_(cbc), state_(std::move(state)) {}
  int event(Event which) override;
  ClpEventHandler* clone() const override { return new LpPoll(*this); }

 private:
  CoverStop* stop_;
  CbcModel* cbc_;  // may be null (an LP solved before the search)
  std::shared_ptr<State> state_;
};

}  // namespace gvm::planner
