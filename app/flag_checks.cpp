#include "app/flag_checks.h"

#include <cmath>
#include <sstream>

#include "formats/scene_file.h"
#include "validation/validity_criteria.h"

namespace shockmap {

void AddThresholdFlags(CLI::App* command, CriteriaOptions& thresholds) {
  command->add_option("--err-max", thresholds.err_max, "largest acceptable Err")
      ->capture_default_str()
      ->check(FiniteAbove(0.0, true) & CLI::Range(0.0, 1.0));
  command->add_option("--srf-min", thresholds.srf_min, "smallest acceptable SRf")
      ->capture_default_str()
      ->check(FiniteAbove(0.0, false) & CLI::Range(0.0, 1.0));
}

void AddAllowPathFlag(CLI::App* command, SceneFileAccess& access) {
  command
      ->add_option("--allow-path", access.allowed_folders,
                   "folder a scene's data files (base-motion CSV) may also be read from; by "
                   "default only the scene's own folder and below (repeatable)")
      ->check(CLI::ExistingDirectory);
}

CLI::Validator FiniteAbove(double lo, bool strict) {
  std::ostringstream allowed;
  allowed << "finite and " << (strict ? "> " : ">= ") << lo;
  const std::string description = allowed.str();
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        std::size_t used = 0;
        double value = 0.0;
        try {
          value = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size()) return "value '" + text + "' is not a number";
        if (!std::isfinite(value) || value < lo || (strict && value == lo)) {
          return "value " + text + " must be " + description;
        }
        return "";
      },
      description);
}

}  // namespace shockmap
