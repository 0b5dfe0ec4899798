#include "app/simulate_command.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <iostream>
#include <memory>

#include "app/flag_checks.h"
#include "core/input_error.h"
#include "engine/progress_reporter.h"
#include "formats/counted.h"
#include "formats/output_file.h"
#include "formats/scene_file.h"
#include "formats/scene_outputs.h"
#include "views/contact_force_map.h"

namespace shockmap {
namespace {

struct SimulateFlags {
  std::string scene_file;
  std::string out_dir;
  bool json = false;
  bool quiet = false;
  SceneFileAccess access;
};

// "10 modes per plane" when every beam keeps as many, "8 to 10 modes per beam and plane"
// otherwise.
std::string ModesKept(const std::vector<int>& modes_per_beam) {
  if (modes_per_beam.empty()) return "no beam";
  const auto [fewest, most] = std::minmax_element(modes_per_beam.begin(), modes_per_beam.end());
  if (*fewest == *most) return Counted(*most, "mode") + " per plane";
  return fmt::format("{} to {} per beam and plane", *fewest, Counted(*most, "mode"));
}

void PrintHuman(const Scene& scene, const SceneRun& run) {
  const RunSummary& s = run.result.summary;
  fmt::print("shockmap simulate: {}, {} s simulated\n", scene.name, scene.solver.end_time_s);
  fmt::print("  status            {}{} (max energy ratio {:.4g})\n", ToString(s.status),
             s.message.empty() ? "" : " (" + s.message + ")", s.max_energy_ratio);
  fmt::print("  model             {}, {}, {} ({}, R_ftrunc = {:g}), {}\n",
             Counted(static_cast<long long>(scene.beams.size()), "beam"),
             Counted(static_cast<long long>(scene.zones.size()), "zone"),
             Counted(run.coordinates, "modal coordinate"), ModesKept(run.modes_per_beam),
             scene.solver.r_ftrunc,
             Counted(run.distinct_bases, "distinct modal basis", "distinct modal bases"));
  if (!scene.structures.empty()) {
    std::vector<std::string> structures;
    for (std::size_t i = 0; i < scene.structures.size(); ++i) {
      structures.push_back(fmt::format("{} ({})", scene.structures[i].name,
                                       Counted(run.modes_per_structure[i], "mode")));
    }
    fmt::print("  structures        {}\n", fmt::join(structures, ", "));
  }
  fmt::print("  dt used           {:.4g} s (asked {:.4g} s), {}\n", s.dt_used_s, s.dt_requested_s,
             Counted(s.steps_taken, "step"));
  fmt::print("  stability bounds  paper 1/(4 f_trunc) = {:.4g} s, sharp 2/omega_max = {:.4g} s\n",
             run.bounds.dt_paper_s, run.bounds.dt_sharp_s);
  fmt::print(
      "  wall time         build {:.3f} s, integration {:.3f} s (CPU {:.3f} s), {:.3f} s per "
      "simulated second\n",
      run.build_wall_s, s.wall_s, s.cpu_s, s.wall_s / scene.solver.end_time_s);
  if (!run.max_contact_force_n.empty()) {
    const auto largest =
        std::max_element(run.max_contact_force_n.begin(), run.max_contact_force_n.end());
    const auto touched =
        std::count_if(run.max_contact_force_n.begin(), run.max_contact_force_n.end(),
                      [](double f) { return f > 0; });
    fmt::print(
        "  contact           {} of {} touched; largest force {:.4g} N in {}\n", touched,
        Counted(static_cast<long long>(scene.zones.size()), "zone"), *largest,
        scene.zones[static_cast<std::size_t>(largest - run.max_contact_force_n.begin())].name);
  }
  if (!run.shocks.empty()) {
    std::size_t shocks = 0;
    for (const auto& z : run.shocks) shocks += z.size();
    fmt::print("  shocks            {} over all zones (rest duration {:g} s)\n",
               Counted(static_cast<long long>(shocks), "shock"), scene.outputs.rest_duration_s);
  }
}

// The longest name written into the output directory.
constexpr const char* kLongestOutput = "contact_force_map.zones.dat";

// Writes the outputs the scene asks for into f.out_dir; the files written.
std::vector<std::filesystem::path> WriteOutputs(const SimulateFlags& f, const Scene& scene,
                                                const SceneRun& run) {
  auto written = WriteSceneOutputs(scene, run, f.out_dir);
  if (!run.max_contact_force_n.empty() && !scene.zones.empty()) {
    const auto map = std::filesystem::path(f.out_dir) / "contact_force_map.png";
    DrawContactForceMap(scene, run.max_contact_force_n, map);
    written.push_back(map);
  }
  return written;
}

// The outputs are checked before the run and written before anything is reported, so that
// success is printed only for files that exist.
void Run(const SimulateFlags& f) {
  const Scene scene = LoadScene(f.scene_file, f.access);
  if (!f.out_dir.empty()) {
    PrepareOutputDirectory(f.out_dir, "--out");
    CheckPathLength(std::filesystem::path(f.out_dir) / kLongestOutput,
                    "--out (with the names of the files written into it)");
  }
  SceneRun run;
  ProgressReporter progress("simulate " + scene.name, "s simulated", scene.solver.end_time_s,
                            stderr, !f.quiet);
  try {
    run = RunScene(scene, [&](double t_s) { progress.Update(t_s); });
    progress.Finish(run.result.summary.dt_used_s *
                    static_cast<double>(run.result.summary.steps_taken));
  } catch (const InputError& e) {
    throw InputError(f.scene_file + ": " + e.what());
  }
  const auto written =
      f.out_dir.empty() ? std::vector<std::filesystem::path>{} : WriteOutputs(f, scene, run);
  if (f.json) {
    std::cout << SceneRunToJson(scene, run).dump(2) << '\n';
    return;
  }
  PrintHuman(scene, run);
  for (const auto& file : written) fmt::print("  wrote             {}\n", file.string());
}

}  // namespace

void AddSimulateCommand(CLI::App& app) {
  auto flags = std::make_shared<SimulateFlags>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Run a scene file (beams, contact zones, effects) with the explicit modal solver and write "
      "the outputs it requests");
  cmd->add_option("scene", flags->scene_file, "scene file (JSON), e.g. scenes/bundle_row.json")
      ->type_name("FILE")
      ->required();
  cmd->add_option("--out", flags->out_dir,
                  "directory for the requested histories (CSV), summary.json and the contact-force "
                  "map");
  cmd->add_flag("--json", flags->json, "print the summary as one JSON object");
  cmd->add_flag("--quiet", flags->quiet, "no progress on stderr");
  AddAllowPathFlag(cmd, flags->access);
  cmd->callback([flags] { Run(*flags); });
}

}  // namespace shockmap
