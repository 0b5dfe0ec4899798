#include "core/fused_sums.h"

#include <cassert>

namespace shockmap {

namespace {
SumPacket Load(const double* p) { return Eigen::internal::ploadu<SumPacket>(p); }
}  // namespace

std::array<double, 2> DotBoth(const Eigen::VectorXd& row, const Eigen::VectorXd& x,
                              const Eigen::VectorXd& v) {
  assert(row.size() == x.size() && row.size() == v.size());
  const double *r = row.data(), *px = x.data(), *pv = v.data();
  return FusedSums<2>(
      row.size(),
      [&](Eigen::Index i) {
        const SumPacket ri = Load(r + i);
        return PacketTerms<2>{
            {Eigen::internal::pmul(ri, Load(px + i)), Eigen::internal::pmul(ri, Load(pv + i))}};
      },
      [&](Eigen::Index i) {
        return std::array<double, 2>{r[i] * px[i], r[i] * pv[i]};
      });
}

std::array<double, 2> KineticAndStrainSums(const Eigen::VectorXd& v, const Eigen::VectorXd& w,
                                           const Eigen::VectorXd& x) {
  assert(v.size() == w.size() && v.size() == x.size());
  const double *pv = v.data(), *pw = w.data(), *px = x.data();
  return FusedSums<2>(
      v.size(),
      [&](Eigen::Index i) {
        const SumPacket vi = Load(pv + i), xi = Load(px + i);
        return PacketTerms<2>{{Eigen::internal::pmul(vi, vi),
                               Eigen::internal::pmul(Load(pw + i), Eigen::internal::pmul(xi, xi))}};
      },
      [&](Eigen::Index i) {
        return std::array<double, 2>{pv[i] * pv[i], pw[i] * (px[i] * px[i])};
      });
}

std::array<double, 2> WeightedSquareAndDot(const Eigen::VectorXd& w, const Eigen::VectorXd& v,
                                           const Eigen::VectorXd& s) {
  assert(w.size() == v.size() && w.size() == s.size());
  const double *pw = w.data(), *pv = v.data(), *ps = s.data();
  return FusedSums<2>(
      v.size(),
      [&](Eigen::Index i) {
        const SumPacket vi = Load(pv + i);
        return PacketTerms<2>{{Eigen::internal::pmul(Load(pw + i), Eigen::internal::pmul(vi, vi)),
                               Eigen::internal::pmul(Load(ps + i), vi)}};
      },
      [&](Eigen::Index i) {
        return std::array<double, 2>{pw[i] * (pv[i] * pv[i]), ps[i] * pv[i]};
      });
}

}  // namespace shockmap
