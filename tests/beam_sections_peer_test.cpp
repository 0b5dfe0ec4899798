// The shipped native non-uniform pin (scenes/fuel_pin_native.json) against CalculiX on the same
// pin (scenes/fuel_pin.inp: B32R beams, four materials, a point mass), an independent FE code
// (docs/scenes.md, "Non-uniform beams"). Skips, saying why, where ccx is absent.

#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>

#include "core/modal_basis.h"
#include "core/scene_model.h"
#include "formats/scene_file.h"
#include "tests/calculix_decks.h"
#include "tests/calculix_runner.h"
#include "tests/temp_dir.h"

namespace shockmap::testing {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(SHOCKMAP_SOURCE_DIR) / "scenes";

class NativePinPeer : public TempDirTest {};

// ccx's pin bends alike in y and z: each of its frequencies comes twice, and each pair is one
// mode of the native beam. Measured: the native beam's five lowest within ... of ccx's (whose
// B32R beams are expanded into bricks, with their shear and rotary inertia).
TEST_F(NativePinPeer, NativePinHasCcxsFrequencies) {
  if (!FindCalculix()) GTEST_SKIP() << CalculixMissingMessage();
  std::filesystem::copy_file(kScenes / "fuel_pin.inp", dir_ / "fuel_pin.inp");
  const CalculixRun run = RunCalculix(dir_, "fuel_pin");
  ASSERT_TRUE(run.Completed()) << run.Describe();
  const std::vector<double> ccx_hz = ReadEigenfrequenciesHz(dir_ / "fuel_pin.dat");
  ASSERT_EQ(ccx_hz.size(), 10u);

  const Scene scene = LoadScene((kScenes / "fuel_pin_native.json").string());
  const ModalBasis modes = ComputeLowestModes(AssembleSceneBeam(scene.beams.at(0)), 5);
  const double tolerance[5] = {1e-3, 1e-3, 1e-3, 1e-3, 1e-3};
  for (int i = 0; i < 5; ++i) {
    const double native_hz = modes.omega_rad_s[i] / (2.0 * std::numbers::pi);
    for (const int j : {2 * i, 2 * i + 1}) {
      EXPECT_NEAR(native_hz / ccx_hz[j], 1.0, tolerance[i])
          << "native mode " << i + 1 << " " << native_hz << " Hz, ccx mode " << j + 1 << " "
          << ccx_hz[j] << " Hz";
    }
  }
}

}  // namespace
}  // namespace shockmap::testing
