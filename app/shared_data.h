#pragma once
// Data shipped with shockmap that commands name by default (the criteria baseline of `advise
// SCENE.json`), found from any working folder: `cmake --install` puts studies/, scenes/ and
// examples/ in <prefix>/share/shockmap, beside <prefix>/bin/shockmap; a build tree links
// build/share/shockmap/<folder> to the sources, beside build/app/shockmap.

#include <filesystem>
#include <string>

namespace shockmap {

// The recorded outcomes of `check-advice` that `advise SCENE.json` reads (formats/
// advice_check_outcomes.h): the shipped bundles' advice checked on their ensembles.
inline constexpr const char* kAdviceChecks = "studies/baselines/advice_checks.json";

// <folder of the running binary (/proc/self/exe)>/../share/shockmap; empty when the binary's
// location cannot be read.
std::filesystem::path SharedDataFolder();

// A default data file `relative` (e.g. "studies/baselines/paper_fig4.json") of option `flag`:
// `relative` itself when it exists from the working folder, else its copy in SharedDataFolder().
// Throws InputError naming `flag`, the file and both places tried when neither exists. A path
// the user gave is never passed here: it is used as given.
std::string DefaultDataFile(const std::string& relative, const std::string& flag);

}  // namespace shockmap
