#pragma once
// `shockmap completion bash`: a bash completion script generated from the command line's own
// definition, so that it names every command and option the binary has.

#include <CLI/CLI.hpp>
#include <string>

namespace shockmap {

// The bash script completing `app`'s commands, subcommands and options; after an option checked
// by CLI::IsMember, the values it accepts; after an option of type DIR, folders; where a stored
// study's name is expected (a positional STUDY not of type FILE), the names in the database of
// the line's --db (or the default one, as the command would open); after any other option that
// takes a value, or where nothing matches, file names.
std::string BashCompletion(CLI::App& app);

// Adds `completion bash` (and the hidden `completion study-names [--db FILE]` the script runs) to
// `app`; call it after every other command is added.
void AddCompletionCommand(CLI::App& app);

}  // namespace shockmap
