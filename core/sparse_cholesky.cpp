#include "core/sparse_cholesky.h"

#include <cholmod.h>

#include <cassert>
#include <cmath>
#include <new>

namespace shockmap {

// One factorization's CHOLMOD state. cholmod_common is also the workspace of every solve, hence
// mutable: a SparseCholesky is not for concurrent use.
struct SparseCholesky::Factor {
  mutable cholmod_common common{};
  cholmod_factor* l = nullptr;

  explicit Factor(Form form) {
    cholmod_start(&common);
    common.print = 0;  // refusals are the caller's to word
    // L L^T with dense fronts even when small, or L D L^T kept as such.
    common.supernodal = form == Form::kLlt ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
    common.final_ll = form == Form::kLlt;
  }
  ~Factor() {
    cholmod_free_factor(&l, &common);
    cholmod_finish(&common);
  }

  // A view of an Eigen column-major matrix as CHOLMOD's dense type (no copy).
  static cholmod_dense View(const Eigen::MatrixXd& m) {
    cholmod_dense d{};
    d.nrow = d.d = static_cast<std::size_t>(m.rows());
    d.ncol = static_cast<std::size_t>(m.cols());
    d.nzmax = d.nrow * d.ncol;
    d.x = const_cast<double*>(m.data());
    d.xtype = CHOLMOD_REAL;
    d.dtype = CHOLMOD_DOUBLE;
    return d;
  }

  // The solve of `system` (CHOLMOD_P, CHOLMOD_L, ...) on x.
  Eigen::MatrixXd Solve(int system, const Eigen::MatrixXd& x) const {
    cholmod_dense b = View(x);
    cholmod_dense* y = cholmod_solve(system, l, &b, &common);
    if (y == nullptr) throw std::bad_alloc();
    Eigen::MatrixXd result =
        Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(y->x), x.rows(), x.cols());
    cholmod_free_dense(&y, &common);
    return result;
  }
};

SparseCholesky::SparseCholesky(const Eigen::SparseMatrix<double>& a, Form form)
    : form_(form), factor_(std::make_unique<Factor>(form)) {
  Eigen::SparseMatrix<double> upper = a.triangularView<Eigen::Upper>();
  upper.makeCompressed();
  cholmod_sparse view{};
  view.nrow = view.ncol = static_cast<std::size_t>(upper.rows());
  view.nzmax = static_cast<std::size_t>(upper.nonZeros());
  view.p = upper.outerIndexPtr();
  view.i = upper.innerIndexPtr();
  view.x = upper.valuePtr();
  view.stype = 1;  // symmetric, upper triangle stored
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = view.packed = 1;
  cholmod_common& common = factor_->common;
  factor_->l = cholmod_analyze(&view, &common);
  if (factor_->l == nullptr || !cholmod_factorize(&view, factor_->l, &common) ||
      common.status == CHOLMOD_OUT_OF_MEMORY) {
    throw std::bad_alloc();
  }
}

SparseCholesky::~SparseCholesky() = default;
SparseCholesky::SparseCholesky(SparseCholesky&&) noexcept = default;
SparseCholesky& SparseCholesky::operator=(SparseCholesky&&) noexcept = default;

int SparseCholesky::Size() const { return static_cast<int>(factor_->l->n); }

bool SparseCholesky::Succeeded() const { return factor_->l->minor == factor_->l->n; }

int SparseCholesky::FailedRow() const {
  if (Succeeded()) return -1;
  return static_cast<const int*>(factor_->l->Perm)[factor_->l->minor];
}

Eigen::VectorXd SparseCholesky::PivotsByRow() const {
  const cholmod_factor& l = *factor_->l;
  const auto* x = static_cast<const double*>(l.x);
  const auto* perm = static_cast<const int*>(l.Perm);
  const auto reached = static_cast<int>(l.minor);  // the columns factorized
  Eigen::VectorXd pivots = Eigen::VectorXd::Constant(Size(), std::nan(""));
  if (form_ == Form::kLdlt) {
    // Simplicial L D L^T: column j starts at p[j] with D's entry in place of L's unit diagonal.
    const auto* p = static_cast<const int*>(l.p);
    for (int j = 0; j < reached; ++j) pivots[perm[j]] = x[p[j]];
    return pivots;
  }
  // Supernode k holds columns super[k] .. super[k+1]-1 of L as a dense column-major block of
  // pi[k+1]-pi[k] rows from x[px[k]], its diagonal first.
  const auto* super = static_cast<const int*>(l.super);
  const auto* pi = static_cast<const int*>(l.pi);
  const auto* px = static_cast<const int*>(l.px);
  for (std::size_t k = 0; k < l.nsuper; ++k) {
    const int rows = pi[k + 1] - pi[k];
    for (int j = 0; j < super[k + 1] - super[k] && super[k] + j < reached; ++j) {
      pivots[perm[super[k] + j]] = x[px[k] + j * (rows + 1)];
    }
  }
  return pivots;
}

Eigen::MatrixXd SparseCholesky::Solve(const Eigen::MatrixXd& rhs) const {
  return factor_->Solve(CHOLMOD_A, rhs);
}

Eigen::MatrixXd SparseCholesky::SolveLowerPermuted(const Eigen::MatrixXd& x) const {
  assert(form_ == Form::kLlt);
  return factor_->Solve(CHOLMOD_L, factor_->Solve(CHOLMOD_P, x));
}

Eigen::MatrixXd SparseCholesky::SolveUpperPermuted(const Eigen::MatrixXd& x) const {
  assert(form_ == Form::kLlt);
  return factor_->Solve(CHOLMOD_Pt, factor_->Solve(CHOLMOD_Lt, x));
}

}  // namespace shockmap
