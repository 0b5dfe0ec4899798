#pragma once
// A run the user stopped. While a run holds engine/stop_request.h's handlers, a SIGINT (Ctrl-C),
// SIGTERM or SIGHUP stops it as it stops `shockmap study run`; once the interpreter's handlers
// are back, the stop reaches Python as the signal would have.

namespace shockmap::python {

// Nothing for 0; KeyboardInterrupt (thrown as pybind11::error_already_set) for SIGINT; any
// other signal raised again for the interpreter's own handling. Call with the GIL held.
void RaiseStop(int signal);

}  // namespace shockmap::python
