#include "app/structure_command.h"

#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>

#include "core/input_error.h"
#include "core/structure_modes.h"
#include "formats/calculix_job.h"
#include "formats/output_file.h"
#include "formats/structure_files.h"

namespace shockmap {
namespace {

struct StructureFlags {
  std::string deck;
  std::string out;
  std::vector<std::string> files;
  int count = 10;
};

// Nothing is left in --out (nor --out itself, when this made it) unless every file is written.
void Import(const StructureFlags& f) {
  CheckPathLength(f.out, "--out");
  FeStructure s;
  WriteIntoDirectory(f.out, "--out", [&] {
    s = ImportCalculixDeck(f.deck);
    WriteMatrixMarketStructure(s, f.out);
  });
  std::cout << fmt::format("{}: {} DOFs at {} nodes, written to {}\n", s.name, s.Size(),
                           s.node_coordinates_m.size(), f.out);
}

// A folder holding stiffness.mtx, mass.mtx, dofs.csv and nodes.csv, or those four files.
FeStructure ReadStructureFiles(const std::vector<std::string>& files) {
  if (files.size() == 1) {
    const std::filesystem::path dir(files.front());
    if (!std::filesystem::is_directory(dir)) {
      throw InputError(files.front() +
                       ": not a folder; give a folder holding stiffness.mtx, "
                       "mass.mtx, dofs.csv and nodes.csv, or those four files");
    }
    return ReadMatrixMarketStructure((dir / "stiffness.mtx").string(), (dir / "mass.mtx").string(),
                                     (dir / "dofs.csv").string(), (dir / "nodes.csv").string());
  }
  if (files.size() != 4) {
    throw InputError(
        fmt::format("{} files given; give one folder, or four files: the stiffness "
                    "and mass (.mtx), the DOF table and the nodes (.csv)",
                    files.size()));
  }
  return ReadMatrixMarketStructure(files[0], files[1], files[2], files[3]);
}

void PrintModes(const StructureFlags& f) {
  if (f.count < 1) throw InputError(fmt::format("--count: {}; allowed: 1 or more", f.count));
  const FeStructure s = ReadStructureFiles(f.files);
  const ModalBasis modes = LowestStructureModes(s, f.count);
  std::cout << "mode,f_hz\n";
  for (int k = 0; k < modes.NumModes(); ++k) {
    std::cout << fmt::format("{},{:.12g}\n", k + 1, modes.omega_rad_s[k] / (2 * std::numbers::pi));
  }
}

}  // namespace

void AddStructureCommand(CLI::App& app) {
  auto flags = std::make_shared<StructureFlags>();
  CLI::App* cmd = app.add_subcommand(
      "structure", "Structures from an FE code: import a CalculiX deck, print their modes");
  cmd->require_subcommand(1);
  CLI::App* import = cmd->add_subcommand(
      "import",
      "Run CalculiX's ccx on a deck's model to store its stiffness, mass and DOF "
      "table, and write them as Matrix Market and CSV files");
  import->add_option("DECK", flags->deck, "CalculiX input deck (.inp)")->required();
  import->add_option("--out", flags->out, "folder to write into")->required();
  import->callback([flags] { Import(*flags);
});
CLI::App* modes =
    cmd->add_subcommand("modes", "Print the lowest natural frequencies of a structure's files");
modes
    ->add_option("FILES", flags->files,
                 "a folder of stiffness.mtx, mass.mtx, dofs.csv, nodes.csv, or the four files")
    ->required();
modes->add_option("--count", flags->count, "number of modes (default 10)");
modes->callback([flags] { PrintModes(*flags); });
}  // namespace shockmap

}  // namespace shockmap
