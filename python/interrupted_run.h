#pragma once
// A run the user stopped. While a run holds engine/stop_request.h's handlers, a SIGINT (Ctrl-C),
// SIGTERM or SIGHUP stops it as it stops `shockmap study run`; once the interpreter's handlers
// are back, the stop reaches Python as the signal would have.

#include <string>

namespace shockmap::python {

// Nothing for 0. Otherwise raises `signal` again, now that the interpreter's handlers are back,
// and has the interpreter act on it at once: its default action ends the process (SIGTERM,
// SIGHUP); a Python handler runs now when called on the main thread (Python's own SIGINT
// handler raises KeyboardInterrupt), and an exception it raises is thrown as
// pybind11::error_already_set. Returns when the handler returns, or at once off the main
// thread, whose handler the main thread runs at its next check. Call with the GIL held.
void RaiseStop(int signal);

// Throws InterruptedError (as pybind11::error_already_set) with `message`: a run stopped by a
// signal whose handler returned, where the run has no result to return.
[[noreturn]] void ThrowInterrupted(const std::string& message);

}  // namespace shockmap::python
