#pragma once
// `shockmap completion bash`: a bash completion script generated from the command line's own
// definition, so that it names every command and option the binary has.

#include <CLI/CLI.hpp>
#include <string>

namespace shockmap {

// The bash script completing `app`'s commands, subcommands and options: after an option that
// takes a value, or where nothing matches, file names.
std::string BashCompletion(const CLI::App& app);

// Adds `completion bash` to `app`; call it after every other command is added.
void AddCompletionCommand(CLI::App& app);

}  // namespace shockmap
