#include "reference/rank_one_update.h"

#include <cassert>
#include <stdexcept>
#include <string>

extern "C" void dlaed9_(const int* k, const int* kstart, const int* kstop, const int* n, double* d,
                        double* q, const int* ldq, const double* rho, double* dlamda, double* w,
                        double* s, const int* lds, int* info);

namespace shockmap {

RankOneEigen EigenOfRankOneUpdate(const Eigen::VectorXd& d, const Eigen::VectorXd& z, double rho) {
  const int n = static_cast<int>(d.size());
  assert(z.size() == n && n >= 1 && rho > 0.0);
  RankOneEigen e;
  e.values.resize(n);
  e.vectors.resize(n, n);
  // dlaed4 takes |z| = 1: the update is (rho |z|^2) (z / |z|)(z / |z|)^T.
  const double norm = z.norm();
  Eigen::VectorXd w = z / norm;
  Eigen::VectorXd poles = d;
  Eigen::MatrixXd work(n, n);
  const double scaled_rho = rho * norm * norm;
  const int one = 1;
  int info = 0;
  dlaed9_(&n, &one, &n, &n, e.values.data(), work.data(), &n, &scaled_rho, poles.data(), w.data(),
          e.vectors.data(), &n, &info);
  if (info != 0) {
    throw std::runtime_error("rank-one eigenproblem: dlaed9 returned info = " +
                             std::to_string(info));
  }
  return e;
}

}  // namespace shockmap
