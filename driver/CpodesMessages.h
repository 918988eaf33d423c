#pragma once
// Where CPodes' (SUNDIALS) own messages go. CPodes prints its warnings and
// errors ("[CPODES ERROR] ...") to the FILE* that `stderr` was when the
// integrator was made, and Simbody gives no way to set that file
// afterwards. So each CPodes integrator is made while `stderr` points, for
// that moment, at one message sink:
//
// - text written to the sink by a thread that makes and runs CPodes
//   integrators (makeCpodesIntegrator marks the thread) is CPodes' own:
//   kept for that thread, and a failed integration folds the last error
//   into its one-line message (takeCpodesError);
// - text any other thread writes to `stderr` in that moment reaches the
//   process's standard error unchanged (written to file descriptor 2), so
//   another thread's diagnostics are not swallowed. Left: a thread that
//   integrates with CPodes and itself writes to C `stderr` (not std::cerr,
//   which keeps the original FILE) in the microseconds another thread makes
//   one; milldyn's integrating threads write nothing there.
//
// The lock: `stderr` is swapped only under cpodesStderrLock(). Code that
// must not see the sink at all (a writer that takes `stderr`'s value and
// keeps it) takes the same lock. An integrator lives and ends on the thread
// that made it (Simulation makes and ends it in one call).

#include <simmath/CPodesIntegrator.h>

#include <cstdio>
#include <memory>
#include <mutex>
#include <string>

namespace milldyn {

/// A CPodes integrator whose messages go to this thread's kept text; marks
/// the calling thread as one that integrates with CPodes.
std::unique_ptr<SimTK::Integrator> makeCpodesIntegrator(const SimTK::System& system,
                                                        SimTK::CPodes::LinearMultistepMethod method,
                                                        SimTK::CPodes::NonlinearSystemIterationType iteration);

/// The last error CPodes reported on this thread, on one line ("" if none);
/// clears what was kept.
std::string takeCpodesError();

/// The sink CPodes integrators write to (exposed for tests).
FILE* cpodesMessageSink();

/// Held while `stderr` is swapped.
std::mutex& cpodesStderrLock();

}  // namespace milldyn
