#pragma once
// Several sums over the same index range in one pass, each summed in exactly the order of
// Eigen's own reduction (`a.dot(b)`, `v.squaredNorm()`, `(a.cwiseProduct(b)).sum()` of dynamic
// size): two packet accumulators over pairs of packets, a last whole packet, the horizontal sum,
// then the remaining coefficients one by one (Eigen 3.4, Redux.h, LinearVectorizedTraversal).
// The result is therefore equal bit for bit to the separate Eigen reductions, while the
// independent sums overlap instead of each waiting on its own chain of additions: what a run
// records at every step (docs/performance.md, "Explicit steps and bundles").

#include <Eigen/Core>
#include <array>
#include <cstddef>

namespace shockmap {

using SumPacket = Eigen::internal::packet_traits<double>::type;

// K packets, one per sum (a plain array: a packet type's attributes would be lost as a template
// argument).
template <std::size_t K>
struct PacketTerms {
  SumPacket sum[K];
};

// Sums of the K terms term(i) = {t_0(i), ..., t_{K-1}(i)}, i in [0, n): `packets(i)` gives the
// K packets (PacketTerms<K>) of terms i .. i + kPacket - 1 (loaded unaligned), `coeffs(i)` the K
// scalar terms at i. Both must compute a term with the same operations in the same order (e.g. a[i]
// * b[i]).
template <std::size_t K, typename Packets, typename Coeffs>
std::array<double, K> FusedSums(Eigen::Index n, Packets packets, Coeffs coeffs) {
  constexpr Eigen::Index kPacket = Eigen::internal::packet_traits<double>::size;
  const Eigen::Index whole2 = (n / (2 * kPacket)) * (2 * kPacket), whole = (n / kPacket) * kPacket;
  std::array<double, K> res{};
  if (whole == 0) {  // Too short for a packet: Eigen sums the coefficients in order.
    for (Eigen::Index i = 0; i < n; ++i) {
      const std::array<double, K> t = coeffs(i);
      for (std::size_t k = 0; k < K; ++k) res[k] = i == 0 ? t[k] : res[k] + t[k];
    }
    return res;
  }
  PacketTerms<K> acc0 = packets(0), acc1{};
  if (whole > kPacket) {
    acc1 = packets(kPacket);
    for (Eigen::Index i = 2 * kPacket; i < whole2; i += 2 * kPacket) {
      const PacketTerms<K> p0 = packets(i), p1 = packets(i + kPacket);
      for (std::size_t k = 0; k < K; ++k) {
        acc0.sum[k] = Eigen::internal::padd(acc0.sum[k], p0.sum[k]);
        acc1.sum[k] = Eigen::internal::padd(acc1.sum[k], p1.sum[k]);
      }
    }
    for (std::size_t k = 0; k < K; ++k)
      acc0.sum[k] = Eigen::internal::padd(acc0.sum[k], acc1.sum[k]);
    if (whole > whole2) {
      const PacketTerms<K> p = packets(whole2);
      for (std::size_t k = 0; k < K; ++k)
        acc0.sum[k] = Eigen::internal::padd(acc0.sum[k], p.sum[k]);
    }
  }
  for (std::size_t k = 0; k < K; ++k) res[k] = Eigen::internal::predux(acc0.sum[k]);
  for (Eigen::Index i = whole; i < n; ++i) {
    const std::array<double, K> t = coeffs(i);
    for (std::size_t k = 0; k < K; ++k) res[k] += t[k];
  }
  return res;
}

// {row . x, row . v}: equal bit for bit to row.dot(x) and row.dot(v). Sizes must agree.
std::array<double, 2> DotBoth(const Eigen::VectorXd& row, const Eigen::VectorXd& x,
                              const Eigen::VectorXd& v);

// {v . v, w . (x .* x)}: equal bit for bit to v.squaredNorm() and w.dot(x.cwiseProduct(x)),
// the kinetic and strain sums of a modal state. Sizes must agree.
std::array<double, 2> KineticAndStrainSums(const Eigen::VectorXd& v, const Eigen::VectorXd& w,
                                           const Eigen::VectorXd& x);

// {w . (v .* v), s . v}: equal bit for bit to w.dot(v.cwiseProduct(v)) and s.dot(v), a modal
// damping's power and a load's. Sizes must agree.
std::array<double, 2> WeightedSquareAndDot(const Eigen::VectorXd& w, const Eigen::VectorXd& v,
                                           const Eigen::VectorXd& s);

}  // namespace shockmap
