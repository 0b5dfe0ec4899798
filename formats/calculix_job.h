#pragma once
// A CalculiX deck made a shockmap structure (docs/structures.md): ccx runs on a copy of the
// deck's model with a matrix-storage step (*FREQUENCY, SOLVER=MATRIXSTORAGE), as a child process
// without a shell, and its .sti, .mas and .dof are read with the deck's node coordinates.

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/fe_structure.h"

namespace shockmap {

// ccx could not be found or started, or was killed: not the user's deck (exit 1).
class CalculixError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The ccx executable: $SHOCKMAP_CCX when set, else `ccx` on the PATH; nullopt when neither is an
// executable file.
std::optional<std::filesystem::path> FindCalculixExecutable();

// Runs `ccx -i jobname` in `folder` (which holds jobname.inp) as a child process without a shell,
// stdin from /dev/null, stdout and stderr into folder/jobname.log; waits for it (killed if a
// signal ends this process) and returns waitpid's status. Throws CalculixError when it cannot
// be started.
int RunCalculixJob(const std::filesystem::path& ccx, const std::filesystem::path& folder,
                   const std::string& jobname);

// The deck's model part: its lines before the first *STEP, then the *BOUNDARY blocks of its
// first step (supports given in the step), then the matrix-storage step. *INCLUDE paths are
// made absolute (relative ones are relative to the deck's folder).
std::string MatrixStorageDeck(const std::filesystem::path& deck);

// Runs ccx on MatrixStorageDeck(deck) in a fresh temporary folder (removed afterwards) and reads
// the structure, named after the deck's file name. Throws InputError naming the deck and quoting
// ccx's log when ccx refuses the deck, CalculixError when ccx is missing or cannot run.
FeStructure ImportCalculixDeck(const std::filesystem::path& deck);

}  // namespace shockmap
