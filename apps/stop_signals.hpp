// The first SIGINT or SIGTERM as a flag that long commands (`tribo run`, `tribo orbit
// --continue`) poll: they stop where they stand and write what they have; a second signal
// ends the process at once (the default action, restored by the first).
// Not here: what each command keeps, or its exit status (5, interrupted, for both).
#pragma once

#include <atomic>

namespace tribo::app {

// Installs the handlers and returns the flag they set (one per process).
const std::atomic<bool>& catchStopSignals();

}  // namespace tribo::app
