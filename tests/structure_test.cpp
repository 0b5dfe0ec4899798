// FE structures from their matrices (docs/structures.md): modes by shift-invert Lanczos against a
// spring chain's closed form, repeated frequencies, static and residual flexibility, the local
// stiffness, and the Matrix Market files written and read back.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <latch>
#include <memory>
#include <numbers>
#include <thread>
#include <vector>

#include "core/input_error.h"
#include "core/structure_modes.h"
#include "core/structure_modes_cache.h"
#include "formats/calculix_job.h"
#include "formats/structure_files.h"
#include "tests/structure_chain.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using testing::ChainOmega;
using testing::SpringChain;

constexpr double kK = 3.0e6, kM = 0.25;

// Phi^T M Phi = I and M^-1 K Phi = Phi diag(omega^2), each to `tolerance`.
void ExpectEigenpairs(const FeStructure& s, const ModalBasis& b, double tolerance) {
  const Eigen::MatrixXd modal_mass = b.shapes.transpose() * (s.mass * b.shapes);
  EXPECT_LT(
      (modal_mass - Eigen::MatrixXd::Identity(b.NumModes(), b.NumModes())).cwiseAbs().maxCoeff(),
      tolerance);
  for (int j = 0; j < b.NumModes(); ++j) {
    const Eigen::VectorXd residual =
        s.stiffness * b.shapes.col(j) - std::pow(b.omega_rad_s[j], 2) * (s.mass * b.shapes.col(j));
    EXPECT_LT(residual.norm() / (std::pow(b.omega_rad_s[j], 2) * (s.mass * b.shapes.col(j)).norm()),
              tolerance)
        << "mode " << j + 1;
  }
}

TEST(StructureModes, LanczosGivesTheChainsFrequencies) {
  const int n = 2000;
  const FeStructure s = SpringChain(n, kK, kM, {DofComponent::kUx});
  const ModalBasis b = LowestStructureModes(s, 30);
  ASSERT_EQ(b.NumModes(), 30);
  for (int j = 1; j <= 30; ++j) {
    EXPECT_NEAR(b.omega_rad_s[j - 1] / ChainOmega(n, kK, kM, j), 1.0, 1e-10) << "mode " << j;
  }
  ExpectEigenpairs(s, b, 1e-8);
}

TEST(StructureModes, SmallStructuresAreSolvedDenselyToTheSameFrequencies) {
  const int n = 50;
  const FeStructure s = SpringChain(n, kK, kM, {DofComponent::kUy});
  const ModalBasis b = LowestStructureModes(s, n + 7);  // More than it has: all of them.
  ASSERT_EQ(b.NumModes(), n);
  for (int j = 1; j <= n; ++j) {
    EXPECT_NEAR(b.omega_rad_s[j - 1] / ChainOmega(n, kK, kM, j), 1.0, 1e-12) << "mode " << j;
  }
  ExpectEigenpairs(s, b, 1e-10);
}

TEST(StructureModes, BelowATruncationCountsByInertia) {
  const int n = 1500;
  const FeStructure s = SpringChain(n, kK, kM, {DofComponent::kUx});
  // Halfway between the 12th and 13th frequencies.
  const double f_trunc =
      0.5 * (ChainOmega(n, kK, kM, 12) + ChainOmega(n, kK, kM, 13)) / (2 * std::numbers::pi);
  const ModalBasis b = StructureModesBelow(s, f_trunc);
  EXPECT_EQ(b.NumModes(), 12);
  EXPECT_LE(b.HighestFrequencyHz(), f_trunc);
}

// Each frequency twice (ux and uy): the basis of each pair spans its eigenspace, whatever the
// order or rotation within it.
TEST(StructureModes, RepeatedFrequenciesGiveABasisOfTheirEigenspace) {
  const int n = 800;
  const FeStructure s = SpringChain(n, kK, kM, {DofComponent::kUx, DofComponent::kUy});
  const ModalBasis b = LowestStructureModes(s, 20);
  ASSERT_EQ(b.NumModes(), 20);
  for (int j = 1; j <= 10; ++j) {
    for (int copy = 0; copy < 2; ++copy) {
      EXPECT_NEAR(b.omega_rad_s[2 * (j - 1) + copy] / ChainOmega(n, kK, kM, j), 1.0, 1e-10);
    }
  }
  ExpectEigenpairs(s, b, 1e-8);
}

TEST(StructureModes, StaticFlexibilityIsTheChainsClosedForm) {
  const int n = 600;
  const FeStructure s = SpringChain(n, kK, kM, {DofComponent::kUx});
  const std::vector<int> rows = {599, 17, 300};
  const Eigen::MatrixXd g = StaticFlexibility(s, rows);
  for (int i = 0; i < 3; ++i) {
    for (int l = 0; l < 3; ++l) {
      EXPECT_NEAR(g(i, l) * kK / std::min(rows[i] + 1, rows[l] + 1), 1.0, 1e-10);
    }
  }
  EXPECT_NEAR(LocalStiffness(s, n, Eigen::Vector3d::UnitX()) * n / kK, 1.0, 1e-10);
}

TEST(StructureModes, ResidualFlexibilityIsTheHigherModesShare) {
  const int n = 120;
  const FeStructure s = SpringChain(n, kK, kM, {DofComponent::kUx});
  const ModalBasis all = LowestStructureModes(s, n);
  const std::vector<int> rows = {n - 1, 40};
  const ModalBasis low = FirstModes(all, 10);
  Eigen::MatrixXd higher = Eigen::MatrixXd::Zero(2, 2);
  for (int j = 10; j < n; ++j) {
    const Eigen::Vector2d phi(all.shapes(rows[0], j), all.shapes(rows[1], j));
    higher += phi * phi.transpose() / std::pow(all.omega_rad_s[j], 2);
  }
  const Eigen::MatrixXd residual = ResidualFlexibility(s, low, rows);
  EXPECT_LT((residual - higher).cwiseAbs().maxCoeff() / higher.cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_GT(higher(0, 0), 0.0);
}

// A node with two copies of ux (as CalculiX names its expanded beams' nodes), each on its own
// spring k to the ground: a force F shared equally moves each copy, and so their mean, by
// F / (2 k): the local stiffness is 2 k.
TEST(StructureModes, LocalStiffnessAveragesANodesCopies) {
  FeStructure s;
  s.name = "copies";
  s.dofs = {{7, DofComponent::kUx}, {7, DofComponent::kUx}, {7, DofComponent::kUy}};
  s.node_coordinates_m[7] = Eigen::Vector3d::Zero();
  s.stiffness.resize(3, 3);
  s.stiffness.insert(0, 0) = kK;
  s.stiffness.insert(1, 1) = kK;
  s.stiffness.insert(2, 2) = 5 * kK;
  s.mass = s.stiffness / kK;
  EXPECT_NEAR(LocalStiffness(s, 7, Eigen::Vector3d::UnitX()) / (2 * kK), 1.0, 1e-14);
  EXPECT_NEAR(LocalStiffness(s, 7, Eigen::Vector3d::UnitY()) / (5 * kK), 1.0, 1e-14);
  EXPECT_THROW(LocalStiffness(s, 7, Eigen::Vector3d::UnitZ()), InputError);
}

TEST(StructureModes, AnUnsupportedStructureIsRefused) {
  FeStructure s = SpringChain(10, kK, kM, {DofComponent::kUx});
  s.stiffness.coeffRef(0, 0) = kK;  // No spring to the ground: a rigid translation.
  try {
    LowestStructureModes(s, 3);
    FAIL() << "expected a refusal";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos) << e.what();
  }
}

// The process's cache of structure modes (core/structure_modes_cache.h). Each test names its
// structures apart, since the cache outlives a test.
FeStructure CacheChain(const std::string& name) {
  FeStructure s = SpringChain(500, kK, kM, {DofComponent::kUx});
  s.name = name;
  return s;
}

void ExpectSameBitForBit(const SceneStructureModes& a, const SceneStructureModes& b) {
  EXPECT_EQ(a.f1_hz, b.f1_hz);
  EXPECT_EQ(a.f_trunc_hz, b.f_trunc_hz);
  EXPECT_TRUE(a.basis.omega_rad_s == b.basis.omega_rad_s);
  EXPECT_TRUE(a.basis.shapes == b.basis.shapes);
}

// A structure read again (a new object of equal content, as each study point reads its scene's
// files) gets the solution of the first, equal bit for bit to a fresh solve, without a solve.
TEST(StructureModesCache, AnEqualStructureGetsTheFreshSolutionWithoutASolve) {
  const std::vector<int> static_nodes = {3, 250};
  const auto first = std::make_shared<const FeStructure>(CacheChain("cache equal"));
  const std::int64_t before = StructureModeSolves();
  const SceneStructureModes cached = StructureModesCached(first, std::nullopt, 10.0, static_nodes);
  EXPECT_EQ(StructureModeSolves(), before + 1);
  const auto again = std::make_shared<const FeStructure>(CacheChain("cache equal"));
  const SceneStructureModes second = StructureModesCached(again, std::nullopt, 10.0, static_nodes);
  EXPECT_EQ(StructureModeSolves(), before + 1) << "the structure read again was solved again";
  EXPECT_EQ(second.fe, again);
  const SceneStructureModes fresh = MakeStructureModes(again, std::nullopt, 10.0, static_nodes);
  // Five modes below 10 f1 (f_j nearly proportional to 2j - 1) and the two nodes' corrections.
  ASSERT_EQ(fresh.N(), 7);
  ExpectSameBitForBit(cached, fresh);
  ExpectSameBitForBit(second, fresh);
  // Another truncation, or other static nodes, is another solution.
  StructureModesCached(again, std::nullopt, 20.0, static_nodes);
  StructureModesCached(again, std::nullopt, 10.0, {3});
  EXPECT_EQ(StructureModeSolves(), before + 3);
}

// One stiffness entry changed in its last bit: a different content, hash and basis.
TEST(StructureModesCache, StructuresDifferingInOneEntryGetTheirOwnBases) {
  const FeStructure s = CacheChain("cache one entry");
  FeStructure changed = s;
  changed.stiffness.coeffRef(250, 250) = std::nextafter(s.stiffness.coeff(250, 250), 0.0);
  EXPECT_FALSE(SameStructureContent(s, changed));
  EXPECT_NE(StructureContentHash(s), StructureContentHash(changed));
  FeStructure renumbered = s;
  renumbered.dofs[7].node = 9999;
  EXPECT_FALSE(SameStructureContent(s, renumbered));
  EXPECT_TRUE(SameStructureContent(s, CacheChain("cache one entry")));

  const auto a = std::make_shared<const FeStructure>(s);
  const auto b = std::make_shared<const FeStructure>(changed);
  const SceneStructureModes modes_a = StructureModesCached(a, std::nullopt, 10.0, {});
  const SceneStructureModes modes_b = StructureModesCached(b, std::nullopt, 10.0, {});
  EXPECT_FALSE(modes_a.basis.shapes == modes_b.basis.shapes);
  ExpectSameBitForBit(modes_b, MakeStructureModes(b, std::nullopt, 10.0, {}));
  ExpectSameBitForBit(modes_a, MakeStructureModes(a, std::nullopt, 10.0, {}));
}

// Threads asking at once for one structure (each its own copy) solve it once.
TEST(StructureModesCache, ThreadsAskingAtOnceSolveOnce) {
  constexpr int kThreads = 4;
  std::vector<std::shared_ptr<const FeStructure>> copies;
  for (int t = 0; t < kThreads; ++t) {
    copies.push_back(std::make_shared<const FeStructure>(CacheChain("cache threads")));
  }
  std::vector<SceneStructureModes> seen(kThreads);
  std::latch start(kThreads);
  const std::int64_t before = StructureModeSolves();
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      start.arrive_and_wait();
      seen[t] = StructureModesCached(
          copies[t], 30.0 * ChainOmega(500, kK, kM, 1) / (2 * std::numbers::pi), 0.0, {17});
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(StructureModeSolves(), before + 1);
  for (int t = 0; t < kThreads; ++t) {
    EXPECT_EQ(seen[t].fe, copies[t]);
    ExpectSameBitForBit(seen[t], seen.front());
  }
}

class StructureFiles : public testing::TempDirTest {};

TEST_F(StructureFiles, WrittenAndReadBackUnchanged) {
  const FeStructure s = SpringChain(40, kK, kM, {DofComponent::kUz, DofComponent::kRx});
  WriteMatrixMarketStructure(s, dir_.string());
  const FeStructure back = ReadMatrixMarketStructure(Path("stiffness.mtx"), Path("mass.mtx"),
                                                     Path("dofs.csv"), Path("nodes.csv"));
  ASSERT_EQ(back.Size(), s.Size());
  EXPECT_EQ(Eigen::MatrixXd(back.stiffness), Eigen::MatrixXd(s.stiffness));
  EXPECT_EQ(Eigen::MatrixXd(back.mass), Eigen::MatrixXd(s.mass));
  for (int i = 0; i < s.Size(); ++i) {
    EXPECT_EQ(back.dofs[i].node, s.dofs[i].node);
    EXPECT_EQ(back.dofs[i].component, s.dofs[i].component);
  }
  EXPECT_EQ(back.node_coordinates_m, s.node_coordinates_m);
}

// The copy ccx runs on: the model before the first *STEP, that step's supports, the
// matrix-storage step; an included deck's path made absolute; later steps left out.
// The cache keys a structure by its content, not its files: the same files read again share the
// solution, and the same paths rewritten with one entry changed are solved again.
TEST_F(StructureFiles, RewrittenFilesAreSolvedAgain) {
  FeStructure s = SpringChain(450, kK, kM, {DofComponent::kUy});
  s.name = "cache files";
  const auto read = [&] {
    FeStructure r = ReadMatrixMarketStructure(Path("stiffness.mtx"), Path("mass.mtx"),
                                              Path("dofs.csv"), Path("nodes.csv"));
    r.name = s.name;
    return StructureModesCached(std::make_shared<const FeStructure>(std::move(r)), std::nullopt,
                                10.0, {});
  };
  WriteMatrixMarketStructure(s, dir_.string());
  const std::int64_t before = StructureModeSolves();
  const SceneStructureModes first = read();
  ExpectSameBitForBit(read(), first);
  EXPECT_EQ(StructureModeSolves(), before + 1);
  s.mass.coeffRef(100, 100) *= 2.0;
  WriteMatrixMarketStructure(s, dir_.string());
  const SceneStructureModes rewritten = read();
  EXPECT_EQ(StructureModeSolves(), before + 2);
  EXPECT_LT(rewritten.f1_hz, first.f1_hz);  // A heavier mass lowers every frequency.
}

TEST_F(StructureFiles, TheMatrixStorageDeckKeepsTheModelAndTheFirstStepsSupports) {
  std::ofstream(Path("model.inp"))
      << "** comment\n*INCLUDE, INPUT=mesh.inp\n*BOUNDARY\n1, 1, 3\n*STEP\n*STATIC\n"
         "*BOUNDARY\n2, 2, 2, 0.001\n*CLOAD\n3, 2, 1.\n*END STEP\n*STEP\n"
         "*BOUNDARY\n4, 1, 1\n*END STEP\n";
  const std::string deck = MatrixStorageDeck(Path("model.inp"));
  EXPECT_EQ(deck, "** comment\n*INCLUDE, INPUT=" + Path("mesh.inp") +
                      "\n*BOUNDARY\n1, 1, 3\n*BOUNDARY\n2, 2, 2, 0.001\n"
                      "*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP\n");
}

}  // namespace
}  // namespace shockmap
