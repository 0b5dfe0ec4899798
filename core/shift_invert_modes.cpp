#include "core/shift_invert_modes.h"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cassert>
#include <stdexcept>

namespace shockmap {
namespace {

using LongSparse = Eigen::SparseMatrix<long double>;
using LongVector = Eigen::Matrix<long double, Eigen::Dynamic, 1>;

// y = (K - sigma M)^-1 x for Spectra, factorized and solved in long double: the lowest modes of
// a fine mesh are lost to the cancellation in K x of a smooth x when it is done in double.
class LongDoubleShiftSolve {
 public:
  using Scalar = double;

  LongDoubleShiftSolve(const Eigen::SparseMatrix<double>& k, const Eigen::SparseMatrix<double>& m)
      : k_(k.cast<long double>()), m_(m.cast<long double>()) {}

  Eigen::Index rows() const { return k_.rows(); }
  Eigen::Index cols() const { return k_.cols(); }

  void set_shift(double sigma) {
    const LongSparse shifted = k_ - static_cast<long double>(sigma) * m_;
    factor_.compute(shifted);
    if (factor_.info() != Eigen::Success || (factor_.vectorD().array() <= 0.0L).any()) {
      throw std::logic_error("shift-invert modes: K - sigma M is not positive definite");
    }
  }

  void perform_op(const double* x, double* y) const {
    const Eigen::Index n = rows();
    const LongVector in = Eigen::Map<const Eigen::VectorXd>(x, n).cast<long double>();
    Eigen::Map<Eigen::VectorXd>(y, n) = factor_.solve(in).cast<double>();
  }

 private:
  LongSparse k_, m_;
  Eigen::SimplicialLDLT<LongSparse> factor_;
};

// Ritz values are converged to this relative residual; their error is then of its square.
constexpr double kShiftInvertLanczosTolerance = 1e-13;
constexpr int kShiftInvertLanczosIterations = 1000;

}  // namespace

ModalBasis LowestModesShiftInvert(const FeBeamModel& model, int count, double shift) {
  const int n = model.Size();
  assert(count >= 1 && count < n - 1);
  LongDoubleShiftSolve op(model.stiffness, model.mass);
  Spectra::SparseSymMatProd<double> mass(model.mass);
  const int subspace = std::min(n, std::max(2 * count + 1, count + 20));
  Spectra::SymGEigsShiftSolver<LongDoubleShiftSolve, Spectra::SparseSymMatProd<double>,
                               Spectra::GEigsMode::ShiftInvert>
      solver(op, mass, count, subspace, shift);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, kShiftInvertLanczosIterations,
                 kShiftInvertLanczosTolerance, Spectra::SortRule::SmallestAlge);
  if (solver.info() != Spectra::CompInfo::Successful) {
    throw std::runtime_error("shift-invert modes: the Lanczos iteration did not converge");
  }
  ModalBasis basis;
  basis.shapes = solver.eigenvectors();
  NormalizeModeSigns(basis.shapes);
  basis.omega_rad_s = solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  return basis;
}

}  // namespace shockmap
