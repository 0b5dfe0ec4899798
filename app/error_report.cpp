#include "app/error_report.h"

#include <CLI/CLI.hpp>
#include <iostream>

#include "app/exit_codes.h"
#include "core/input_error.h"
#include "db/sqlite_handle.h"
#include "views/gnuplot.h"

namespace shockmap {

int ReportFailure(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();  // A verdict already printed (criteria check, a signal).
  } catch (const InputError& e) {
    std::cerr << "shockmap: error: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const DbError& e) {
    // The database named by the user is missing, foreign, corrupt, newer, locked, or the SQL
    // given is invalid or would write: all input the user can fix.
    std::cerr << "shockmap: database error: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const PlotError& e) {
    std::cerr << "shockmap: plot error: " << e.what() << '\n';
    return kExitFailure;
  } catch (const std::exception& e) {
    std::cerr << "shockmap: internal error: " << e.what() << '\n';
    return kExitFailure;
  }
}

}  // namespace shockmap
