// What the readers of an FE structure's files refuse (docs/structures.md, "What the readers
// refuse"): each message names the file, the entry (line, row, column), the value and what is
// allowed; through the command line, exit code 2 and nothing written.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/structure_modes.h"
#include "formats/structure_files.h"
#include "tests/run_command.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using testing::RunShockmap;
using testing::WriteText;

// A supported two-mass chain: K = [[2, -1], [-1, 1]] 1e6, M = diag(1, 1).
const std::string kStiffness =
    "%%MatrixMarket matrix coordinate real symmetric\n"
    "% a comment\n"
    "2 2 3\n"
    "1 1 2e6\n"
    "2 1 -1e6\n"
    "2 2 1e6\n";
const std::string kMass =
    "%%MatrixMarket matrix coordinate real general\n"
    "2 2 2\n"
    "1 1 1.0\n"
    "2 2 1.0\n";
const std::string kDofs = "node,component\n1,ux\n2,ux\n";
const std::string kNodes = "node,x,y,z\n1,0,0,0\n2,1,0,0\n";

class StructureRefusals : public testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    WriteText(Path("stiffness.mtx"), kStiffness);
    WriteText(Path("mass.mtx"), kMass);
    WriteText(Path("dofs.csv"), kDofs);
    WriteText(Path("nodes.csv"), kNodes);
  }

  FeStructure Read() {
    return ReadMatrixMarketStructure(Path("stiffness.mtx"), Path("mass.mtx"), Path("dofs.csv"),
                                     Path("nodes.csv"));
  }

  // Replaces `file` with `text`, then expects the read refused with a message holding each of
  // `parts`, and the command line to exit 2 with the same message; puts the file back.
  void ExpectRefused(const std::string& file, const std::string& text,
                     const std::vector<std::string>& parts) {
    const std::string before = testing::ReadBytes(Path(file));
    WriteText(Path(file), text);
    Refused(parts);
    WriteText(Path(file), before);
  }

  void Refused(const std::vector<std::string>& parts) {
    std::string message;
    try {
      Read();
      ADD_FAILURE() << "not refused";
      return;
    } catch (const InputError& e) {
      message = e.what();
    }
    for (const std::string& part : parts) {
      EXPECT_NE(message.find(part), std::string::npos) << "\"" << part << "\" not in: " << message;
    }
    const auto outcome = RunShockmap("structure modes " + dir_.string() + " --count 1");
    EXPECT_EQ(outcome.exit_code, 2) << outcome.output;
    EXPECT_NE(outcome.output.find(message), std::string::npos) << outcome.output;
  }
};

TEST_F(StructureRefusals, TheValidFilesAreRead) {
  const FeStructure s = Read();
  EXPECT_EQ(s.Size(), 2);
  EXPECT_EQ(s.stiffness.coeff(0, 1), -1e6);
  const auto outcome = RunShockmap("structure modes " + dir_.string() + " --count 2");
  EXPECT_EQ(outcome.exit_code, 0) << outcome.output;
  // omega^2 = (3 -+ sqrt 5) / 2 1e6: f1 = 98.363... Hz.
  const double f1 = std::sqrt((3 - std::sqrt(5.0)) / 2 * 1e6) / (2 * std::numbers::pi);
  EXPECT_NE(outcome.output.find("1," + std::to_string(f1).substr(0, 8)), std::string::npos)
      << outcome.output << " expected f1 " << f1;
}

TEST_F(StructureRefusals, NonSymmetric) {
  ExpectRefused("stiffness.mtx",
                "%%MatrixMarket matrix coordinate real general\n2 2 4\n1 1 2e6\n2 1 -1e6\n"
                "1 2 -0.9e6\n2 2 1e6\n",
                {"stiffness.mtx: line 5", "not symmetric", "row 2 (node 2 ux), column 1 = -1000000",
                 "row 1 (node 1 ux), column 2 = -900000", "symmetric to a relative 1e-09"});
}

TEST_F(StructureRefusals, NonSymmetricMissingMirror) {
  ExpectRefused(
      "stiffness.mtx",
      "%%MatrixMarket matrix coordinate real general\n2 2 3\n1 1 2e6\n2 1 -1e6\n"
      "2 2 1e6\n",
      {"stiffness.mtx: line 4", "not symmetric", "row 1 (node 1 ux), column 2 is not given"});
}

TEST_F(StructureRefusals, UpperEntryInASymmetricFile) {
  ExpectRefused(
      "stiffness.mtx",
      "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 2e6\n1 2 -1e6\n"
      "2 2 1e6\n",
      {"stiffness.mtx: line 4", "row 1 column 2 is above the diagonal", "lower triangle"});
}

// Eigenvalues -1 and 3: a combination with negative kinetic energy.
TEST_F(StructureRefusals, MassNotPositiveSemidefinite) {
  ExpectRefused("mass.mtx",
                "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 1.0\n2 1 2.0\n"
                "2 2 1.0\n",
                {"mass.mtx", "the mass is not positive semi-definite", "(node ", "ux) (diagonal 1)",
                 "the pivot of the factorization of M + 1e-10 diag(M) is -",
                 "no combination of DOFs may have a negative kinetic energy"});
}

TEST_F(StructureRefusals, NegativeMass) {
  ExpectRefused("mass.mtx",
                "%%MatrixMarket matrix coordinate real symmetric\n2 2 2\n1 1 -1.0\n2 2 1.0\n",
                {"mass.mtx", "row 1 (node 1 ux) has the mass -1 on its diagonal",
                 "every DOF needs a positive mass"});
}

// M = [[1, 1], [1, 1]] is singular but not refused (as the consistent mass of reduced-integration
// bricks): its one finite mode is found, omega^2 = 1 / ((1, 1) K^-1 (1, 1)) = 1e6 / 5.
TEST_F(StructureRefusals, ASingularMassIsRead) {
  WriteText(Path("mass.mtx"),
            "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 1.0\n2 1 1.0\n2 2 1.0\n");
  const FeStructure s = Read();
  const ModalBasis modes = LowestStructureModes(s, 2);
  ASSERT_EQ(modes.NumModes(), 1);
  EXPECT_NEAR(std::pow(modes.omega_rad_s[0], 2) / 2e5, 1.0, 1e-12);
}

TEST_F(StructureRefusals, ADofRowWithoutEntries) {
  ExpectRefused("mass.mtx", "%%MatrixMarket matrix coordinate real symmetric\n2 2 1\n1 1 1.0\n",
                {"mass.mtx", "row 2 (node 2 ux) has no nonzero entry"});
}

TEST_F(StructureRefusals, ANodeWithoutCoordinates) {
  ExpectRefused("nodes.csv", "node,x,y,z\n1,0,0,0\n",
                {"dofs.csv: row 2: node 2 has no coordinates in", "nodes.csv"});
}

TEST_F(StructureRefusals, SizesThatDoNotMatch) {
  ExpectRefused("dofs.csv", "node,component\n1,ux\n2,ux\n2,uy\n",
                {"stiffness.mtx: 2 rows, but", "dofs.csv names 3 DOFs"});
}

TEST_F(StructureRefusals, NotSquare) {
  ExpectRefused("mass.mtx", "%%MatrixMarket matrix coordinate real general\n2 3 2\n1 1 1\n2 2 1\n",
                {"mass.mtx: line 2", "size 2 x 3", "must be square"});
}

TEST_F(StructureRefusals, NaN) {
  ExpectRefused("stiffness.mtx",
                "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 2e6\n2 1 nan\n"
                "2 2 1e6\n",
                {"stiffness.mtx: line 4", "row 2 column 1: value \"nan\" is not a finite number"});
}

TEST_F(StructureRefusals, Infinite) {
  ExpectRefused("mass.mtx",
                "%%MatrixMarket matrix coordinate real symmetric\n2 2 2\n1 1 1e400\n2 2 1\n",
                {"mass.mtx: line 3", "row 1 column 1: value \"1e400\" is not a finite number"});
  ExpectRefused("nodes.csv", "node,x,y,z\n1,0,inf,0\n2,1,0,0\n",
                {"nodes.csv: line 2", "y \"inf\" is not a finite number"});
}

TEST_F(StructureRefusals, MalformedLines) {
  ExpectRefused("stiffness.mtx",
                "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 2e6\n2 1\n2 2 1e6\n",
                {"stiffness.mtx: line 4", "entry \"2 1\"", "expected \"row column value\""});
  ExpectRefused("stiffness.mtx",
                "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 2e6x\n2 1 -1\n2 2 1\n",
                {"stiffness.mtx: line 3", "value \"2e6x\" is not a number"});
  ExpectRefused("stiffness.mtx",
                "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 2e6\n3 1 -1\n2 2 1\n",
                {"stiffness.mtx: line 4", "row 3 is outside 1..2"});
  ExpectRefused("stiffness.mtx",
                "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 2e6\n2 2 1\n",
                {"stiffness.mtx: line 4", "ends after 2 entries; its size line announces 3"});
  ExpectRefused("stiffness.mtx",
                "%%MatrixMarket matrix coordinate real symmetric\n2 2 4\n1 1 2e6\n2 1 -1e6\n"
                "2 1 -1e6\n2 2 1\n",
                {"stiffness.mtx: line 5", "column 1 = -1000000 is given again (line 4"});
  ExpectRefused("mass.mtx", "%%MatrixMarket matrix array real general\n2 2\n1\n0\n0\n1\n",
                {"mass.mtx: line 1", "allowed: \"%%MatrixMarket matrix coordinate real general\""});
  ExpectRefused("dofs.csv", "node,component\n1,ux\n2,uw\n",
                {"dofs.csv: line 3", "component \"uw\"; allowed: ux, uy, uz, rx, ry, rz"});
  ExpectRefused("dofs.csv", "node;component\n1;ux\n2;ux\n",
                {"dofs.csv: line 1", "expected the header \"node,component\""});
  ExpectRefused("nodes.csv", "node,x,y,z\n1,0,0\n2,1,0,0\n",
                {"nodes.csv: line 2", "expected \"node,x,y,z\", got \"1,0,0\""});
}

TEST_F(StructureRefusals, CalculixStorage) {
  WriteText(Path("job.dof"), "1.1\n2.1\n");
  WriteText(Path("job.inp"), "*NODE, NSET=NALL\n1, 0, 0, 0\n2, 1., 0., 0.\n*ELEMENT\n");
  WriteText(Path("job.mas"), "1 1 1.0\n2 2 1.0\n");
  WriteText(Path("job.sti"), "1 1 2e6\n1 2 -1e6\n2 2 1e6\n");
  const FeStructure s = ReadCalculixMatrixStorage(Path("job"), Path("job.inp"));
  EXPECT_EQ(s.stiffness.coeff(1, 0), -1e6);
  EXPECT_EQ(s.node_coordinates_m.at(2), Eigen::Vector3d(1, 0, 0));
  const auto refused = [&](const std::string& file, const std::string& text,
                           const std::string& part) {
    const std::string before = testing::ReadBytes(Path(file));
    WriteText(Path(file), text);
    try {
      ReadCalculixMatrixStorage(Path("job"), Path("job.inp"));
      ADD_FAILURE() << file << " was not refused";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
    WriteText(Path(file), before);
  };
  refused("job.sti", "1 1 2e6\n2 1 -1e6\n2 2 1e6\n",
          "job.sti: line 2: row 2 column 1 is below the diagonal");
  refused("job.dof", "1.1\n2.7\n",
          "job.dof: line 2: DOF \"2.7\"; allowed: a node >= 1 and a direction 1..6");
  refused("job.dof", "1.1\n2.1\n1.2\n", "job.sti: row 3 (node 1 uy) has no nonzero entry");
  refused("job.dof", "1.1\n2.1\n3.1\n", "job.dof: row 3: node 3 has no coordinates in");
  refused("job.inp", "*NODE\n1, 0, 0, 0\n", "job.dof: row 2: node 2 has no coordinates in");
  refused("job.mas", "1 1 1.0\n2 2 0.0\n", "job.mas: row 2 (node 2 ux) has no nonzero entry");
}

// A deck ccx refuses: exit 2, its log quoted, --out not created.
TEST_F(StructureRefusals, ImportOfABadDeckWritesNothing) {
  WriteText(Path("bad.inp"), "*NODE\n1, 0, 0, 0\n*ELEMENT, TYPE=C3D8, ELSET=E\n1, 1, 2\n");
  const auto outcome = RunShockmap("structure import " + Path("bad.inp") + " --out " + Path("out"));
  if (outcome.output.find("ccx was not found") != std::string::npos) {
    GTEST_SKIP() << outcome.output;
  }
  EXPECT_EQ(outcome.exit_code, 2) << outcome.output;
  EXPECT_NE(outcome.output.find("bad.inp: ccx did not store its matrices"), std::string::npos)
      << outcome.output;
  EXPECT_FALSE(std::filesystem::exists(Path("out")));
}

}  // namespace
}  // namespace shockmap
