// A request to stop the work in progress, for hosts whose own interrupt cannot reach a long call
// (Python's KeyboardInterrupt while a fit runs with the GIL released). Long loops check it where
// stopping is cheap and leaves nothing half-done: every SMO shrinking round (at most 1000
// iterations), every task of the thread pool, every iteration of the optimizers
// (docs/reliability.md, "Python interrupts").
#pragma once

#include <stdexcept>

namespace fogdrift {

/// What check_interrupt() throws once an interrupt was requested.
class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted") {}
};

/// Asks the work in progress in this process to stop at its next check.
void request_interrupt() noexcept;
/// Forgets a request (before the next call starts).
void clear_interrupt() noexcept;
/// Whether a request is pending.
bool interrupt_requested() noexcept;
/// Throws Interrupted when a request is pending.
void check_interrupt();

}  // namespace fogdrift
