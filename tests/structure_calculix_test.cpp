// CalculiX as the truth for imported structures (docs/structures.md): the paper's cantilever
// (paper §2.1: EI = 1.5e5 N m^2, rho A = 127 kg/m, L = 1 m) meshed by ccx in B32R beams and in
// C3D20R bricks, imported through `structure import`'s path (a matrix-storage run of the same
// model). Its frequencies are ccx's own *FREQUENCY on the same deck, read in full precision from
// jobname.eig (*FREQUENCY, STORAGE=YES), and near the analytic clamped-free values; the local
// stiffness at the tip is 3 EI / L^3.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include "core/beam_properties.h"
#include "core/structure_modes.h"
#include "formats/calculix_job.h"
#include "tests/brick_block_deck.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

// The paper's beam as a rectangle 0.02 m (y, the bending plane) by 0.04 m (z), with E and rho
// giving its EI and rho A, Poisson's ratio 0.
constexpr double kDepth = 0.02, kWidth = 0.04;
const BeamProperties kBeam;
double Young() { return kBeam.ei_n_m2 / (kWidth * std::pow(kDepth, 3) / 12.0); }
double Density() { return kBeam.rho_a_kg_per_m / (kWidth * kDepth); }

std::string Material() {
  std::ostringstream deck;
  deck.precision(17);
  deck << "*MATERIAL, NAME=M\n*ELASTIC\n" << Young() << ", 0.0\n*DENSITY\n" << Density() << "\n";
  return deck.str();
}

// B32R beams along x, nodes 1..2n+1, clamped at node 1; the tip is node 2n+1.
std::string BeamModel(int n) {
  std::ostringstream deck;
  deck.precision(17);
  deck << "*NODE, NSET=NALL\n";
  for (int i = 0; i <= 2 * n; ++i)
    deck << i + 1 << ", " << kBeam.length_m * i / (2 * n) << ", 0, 0\n";
  deck << "*ELEMENT, TYPE=B32R, ELSET=EALL\n";
  for (int e = 0; e < n; ++e)
    deck << e + 1 << ", " << 2 * e + 1 << ", " << 2 * e + 2 << ", " << 2 * e + 3 << "\n";
  deck << Material() << "*BEAM SECTION, ELSET=EALL, MATERIAL=M, SECTION=RECT\n"
       << kDepth << ", " << kWidth << "\n0., 1., 0.\n*BOUNDARY\n1, 1, 6\n";
  return deck.str();
}

// C3D20R bricks: n along x, two through y and z (one alone leaves zero-energy modes of the
// reduced integration), with the beam's E and rho, Poisson's ratio 0. Clamped at x = 0; *tip is
// the middle node of the tip face's edge y = 0 (grid point (2n, 0, 2)).
std::string SolidModel(int n, int* tip) {
  testing::BrickBlock block;
  block.lx = kBeam.length_m;
  block.ly = kDepth;
  block.lz = kWidth;
  block.nx = n;
  block.ny = 2;
  block.nz = 2;
  block.young_pa = Young();
  block.poisson = 0.0;
  block.density_kg_m3 = Density();
  *tip = block.NodeIds().at({2 * n, 0, 2});
  return block.ModelDeck();
}

// ccx's own eigenpairs of a *FREQUENCY, STORAGE=YES run, from jobname.eig as Debian's ccx 2.20
// writes it: four 32-bit integers (cyclic symmetry 0, Hermitian 1, 0, the number of eigenvalues
// nev), the eigenvalues omega^2 as doubles, its matrices, and last the nev eigenvectors over the
// same rows as its matrix storage (neq doubles each).
struct CalculixEigen {
  std::vector<double> omega2;
  Eigen::MatrixXd shapes;
};

CalculixEigen ReadCalculixEigen(const std::filesystem::path& eig, int neq) {
  std::ifstream in(eig, std::ios::binary);
  std::int32_t header[4] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  EXPECT_EQ(header[0], 0) << "cyclic symmetry flag";
  EXPECT_EQ(header[1], 1) << "Hermitian flag";
  CalculixEigen e;
  const int nev = header[3] > 0 && header[3] < 10000 ? header[3] : 0;
  e.omega2.resize(nev);
  in.read(reinterpret_cast<char*>(e.omega2.data()), nev * sizeof(double));
  e.shapes.resize(neq, nev);
  in.seekg(-static_cast<std::streamoff>(e.shapes.size() * sizeof(double)), std::ios::end);
  in.read(reinterpret_cast<char*>(e.shapes.data()), e.shapes.size() * sizeof(double));
  EXPECT_TRUE(in.good()) << eig;
  return e;
}

class CalculixStructure : public testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    ccx_ = FindCalculixExecutable();
    if (!ccx_) GTEST_SKIP() << "CalculiX's ccx is not installed (apt-get install calculix-ccx)";
  }

  // ccx's eigenpairs of the model, and the structure imported from the same model.
  std::pair<CalculixEigen, FeStructure> Run(const std::string& model, int modes) {
    std::ofstream(Path("cantilever.inp")) << model << "*STEP\n*FREQUENCY, STORAGE=YES\n"
                                          << modes << "\n*END STEP\n";
    const int status = RunCalculixJob(*ccx_, dir_, "cantilever");
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << Path("cantilever.log");
    FeStructure s = ImportCalculixDeck(Path("cantilever.inp"));
    return {ReadCalculixEigen(Path("cantilever.eig"), s.Size()), std::move(s)};
  }

  std::optional<std::filesystem::path> ccx_;
};

double AnalyticOmega(double b) { return kBeam.OmegaOf(b); }
// Roots of 1 + cosh b cos b = 0.
constexpr double kRoots[] = {1.8751040687119611, 4.6940911329741745};

// shockmap's omega^2 against ccx's: each of ccx's eigenvectors is one of the imported pencil's
// (relative residual below 1e-4; measured at most 2.1e-6) and its Rayleigh quotient with the
// imported K and M is shockmap's omega^2 to 1e-8 relative (measured at most 3.0e-9); ccx's own
// eigenvalues agree to what its Lanczos convergence gives (measured at most 3.1e-6: asserted
// 1e-5). Within a cluster of equal frequencies only values are compared, never shapes.
void ExpectSameEigenvalues(const FeStructure& s, const CalculixEigen& ccx, const ModalBasis& ours) {
  ASSERT_EQ(ours.NumModes(), static_cast<int>(ccx.omega2.size()));
  for (int j = 0; j < ours.NumModes(); ++j) {
    const Eigen::VectorXd phi = ccx.shapes.col(j);
    const Eigen::VectorXd m_phi = s.mass * phi;
    const double rayleigh = phi.dot(s.stiffness * phi) / phi.dot(m_phi);
    const double residual =
        (s.stiffness * phi - ccx.omega2[j] * m_phi).norm() / (ccx.omega2[j] * m_phi.norm());
    EXPECT_LT(residual, 1e-4) << "mode " << j + 1;
    EXPECT_NEAR(std::pow(ours.omega_rad_s[j], 2) / rayleigh, 1.0, 1e-8) << "mode " << j + 1;
    EXPECT_NEAR(std::pow(ours.omega_rad_s[j], 2) / ccx.omega2[j], 1.0, 1e-5) << "mode " << j + 1;
  }
}

// The two lowest bending frequencies in y (the depth, the lowest family) are the clamped-free
// Euler-Bernoulli ones within the mesh's and the section's (shear, rotary inertia) difference:
// measured -2.3e-4 (beams) and -2.6e-4 (bricks) for the first, -1.6e-3 for the second; bending
// in z (twice as wide) interleaves, so the second is the mode nearest its analytic value.
void ExpectClampedFreeBending(const ModalBasis& ours) {
  EXPECT_NEAR(ours.omega_rad_s[0] / AnalyticOmega(kRoots[0]), 1.0, 1e-3);
  const double omega2 = AnalyticOmega(kRoots[1]);
  double nearest = 0.0;
  for (int j = 0; j < ours.NumModes(); ++j) {
    if (std::abs(ours.omega_rad_s[j] - omega2) < std::abs(nearest - omega2)) {
      nearest = ours.omega_rad_s[j];
    }
  }
  EXPECT_NEAR(nearest / omega2, 1.0, 5e-3);
}

// The tip's stiffness along -y is 3 EI / L^3 within the mesh's difference (measured -2.0e-4 for
// beams, the section's mean motion; -2.6e-4 for bricks, at the mid-width node of the tip's
// lower edge).
TEST_F(CalculixStructure, BeamElementsGiveCalculixsFrequencies) {
  const int n = 20, modes = 8;
  const auto [ccx, s] = Run(BeamModel(n), modes);
  const ModalBasis ours = LowestStructureModes(s, modes);
  ExpectSameEigenvalues(s, ccx, ours);
  ExpectClampedFreeBending(ours);
  const double k_tip = LocalStiffness(s, 2 * n + 1, -Eigen::Vector3d::UnitY());
  EXPECT_NEAR(k_tip / kBeam.TipBendingStiffness(), 1.0, 1e-3);
}

TEST_F(CalculixStructure, SolidElementsGiveCalculixsFrequencies) {
  const int n = 20, modes = 6;
  int tip = 0;
  const auto [ccx, s] = Run(SolidModel(n, &tip), modes);
  const ModalBasis ours = LowestStructureModes(s, modes);
  ExpectSameEigenvalues(s, ccx, ours);
  ExpectClampedFreeBending(ours);
  const double k_tip = LocalStiffness(s, tip, -Eigen::Vector3d::UnitY());
  EXPECT_NEAR(k_tip / kBeam.TipBendingStiffness(), 1.0, 1e-3);
}

}  // namespace
}  // namespace shockmap
