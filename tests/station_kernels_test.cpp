// The contact stations' kernels (core/station_kernels.h) against the scalar formulas they
// vectorize, bit for bit, whichever clone (AVX-512, AVX2 or baseline) this CPU runs: at every
// count of modes, stations and zones a group of 8, 4 or 2 lanes splits differently.

#include "core/station_kernels.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

namespace shockmap {
namespace {

// Reproducible values of both signs spread over several magnitudes, so that the order of a sum
// shows in its last bits.
std::vector<double> Values(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0), exponent(-3.0, 3.0);
  std::vector<double> v(static_cast<std::size_t>(n));
  for (double& x : v) x = mantissa(rng) * std::pow(10.0, exponent(rng));
  return v;
}

TEST(StationKernels, StationDotIsEigensRowDot) {
  std::mt19937 rng(1);
  for (int n = 0; n <= 40; ++n) {
    const std::vector<double> f = Values(rng, n), p = Values(rng, n);
    const Eigen::Map<const Eigen::VectorXd> row(f.data(), n), x(p.data(), n);
    EXPECT_EQ(StationDot(f.data(), p.data(), n), row.dot(x)) << "n = " << n;
  }
}

// Every station of a block reads what StationDot of its own row gives, in y and z side by side,
// at widths that take the scalar sum, one pair, groups of 4, of 8, and 8 then 4; a planar beam
// (no z) reads 0 in z.
TEST(StationKernels, EvaluatedStationsEqualTheirOwnRowsDot) {
  std::mt19937 rng(2);
  for (bool planar : {false, true}) {
    for (int count : {1, 2, 3, 4, 7, 8, 11, 12, 16}) {
      for (int modes = 0; modes <= 13; ++modes) {
        const int width = StationWidth(count);
        ASSERT_GE(width, count);
        const StationBlock b{.y = 0,
                             .z = planar ? -1 : modes,
                             .modes = modes,
                             .first = 1,
                             .width = width,
                             .count = count};
        const std::vector<double> shapes = Values(rng, modes * width), x = Values(rng, 2 * modes);
        std::vector<double> out(2 * static_cast<std::size_t>(width + 1), -1.0);
        EvaluateStations({&b, 1}, shapes.data(), x.data(), out.data());
        EXPECT_EQ(out[0], -1.0) << "slot 0 belongs to no block";
        EXPECT_EQ(out[1], -1.0) << "slot 0 belongs to no block";
        for (int h = 0; h < width; ++h) {
          std::vector<double> row(static_cast<std::size_t>(modes));
          for (int i = 0; i < modes; ++i) row[i] = shapes[i * width + h];
          const double z = planar ? 0.0 : StationDot(row.data(), x.data() + modes, modes);
          EXPECT_EQ(out[2 * (1 + h)], StationDot(row.data(), x.data(), modes))
              << "count " << count << ", modes " << modes << ", station " << h;
          EXPECT_EQ(out[2 * (1 + h) + 1], z)
              << "count " << count << ", modes " << modes << ", station " << h;
        }
      }
    }
  }
}

// Forces and the closed list of n zones over random stations, with zones exactly
// at contact (d = 0: open) and a station that is not a number (its zones open, force 0).
TEST(StationKernels, PenaltyForcesFollowTheScalarFormula) {
  std::mt19937 rng(3);
  constexpr int kSlots = 9;
  for (int n = 0; n <= 37; ++n) {
    std::vector<double> u = Values(rng, 2 * kSlots);  // (y, z) per slot.
    u[0] = u[1] = 0.0;                                // The base.
    u[10] = std::nan("");                             // Slot 5's y.
    auto uy = [&](int slot) { return u[2 * slot]; };
    auto uz = [&](int slot) { return u[2 * slot + 1]; };
    std::vector<int> a(static_cast<std::size_t>(n)), b = a;
    std::uniform_int_distribution<int> slot(0, kSlots - 1);
    for (int i = 0; i < n; ++i) a[i] = slot(rng), b[i] = slot(rng);
    std::vector<double> ny = Values(rng, n), nz = Values(rng, n), gap = Values(rng, n);
    std::vector<double> k = Values(rng, n);
    for (double& ki : k) ki = std::abs(ki) * 1e6;
    if (n > 2) {  // Exactly at contact.
      a[2] = 1, b[2] = 0, ny[2] = 1.0, nz[2] = 0.0, gap[2] = uy(1);
    }
    const PenaltyZones zones{a.data(), b.data(), ny.data(), nz.data(), gap.data(), k.data(), n};
    std::vector<double> force(static_cast<std::size_t>(n));
    std::vector<int> closed(static_cast<std::size_t>(n), -1);
    const int n_closed = LinearPenaltyForces(zones, u.data(), force.data(), closed.data());
    std::vector<int> expected_closed;
    for (int i = 0; i < n; ++i) {
      const double d =
          ny[i] * uy(a[i]) + nz[i] * uz(a[i]) - ny[i] * uy(b[i]) - nz[i] * uz(b[i]) - gap[i];
      EXPECT_EQ(force[i], k[i] * std::max(0.0, d)) << "n " << n << ", zone " << i;
      if (d > 0.0) expected_closed.push_back(i);
    }
    ASSERT_EQ(n_closed, static_cast<int>(expected_closed.size())) << "n " << n;
    for (int j = 0; j < n_closed; ++j) EXPECT_EQ(closed[j], expected_closed[j]);
    if (n > 2) {
      EXPECT_EQ(force[2], 0.0) << "a zone exactly at contact is open";
    }
  }
}

// Forces on stations added in order to their beams' modes, as the scalar loop adds them: two
// beams bending in y and z, one in y only, and several forces on the same station.
TEST(StationKernels, StationForcesAddInOrder) {
  std::mt19937 rng(4);
  for (int modes = 1; modes <= 19; ++modes) {
    // Slots 1, 2 on beam 0 (y at 0, z at modes), slot 3 on beam 1 (y at 2 modes, no z).
    const std::vector<double> rows = Values(rng, 3 * modes);
    const std::vector<int> row = {-1, 0, modes, 2 * modes}, y = {-1, 0, 0, 2 * modes};
    const std::vector<int> z = {-1, modes, modes, -1}, count = {0, modes, modes, modes};
    const StationLayout layout{rows.data(), row.data(), y.data(), z.data(), count.data()};
    std::vector<StationForce> forces;
    const std::vector<double> f = Values(rng, 14);
    for (int j = 0; j < 7; ++j) forces.push_back({1 + j % 3, f[2 * j], f[2 * j + 1]});
    std::vector<double> a = Values(rng, 3 * modes), expected = a;
    AddStationForces(forces, layout, a.data());
    for (const StationForce& s : forces) {
      for (int i = 0; i < modes; ++i) {
        expected[y[s.slot] + i] += s.y * rows[row[s.slot] + i];
        if (z[s.slot] >= 0) expected[z[s.slot] + i] += s.z * rows[row[s.slot] + i];
      }
    }
    for (int i = 0; i < 3 * modes; ++i) EXPECT_EQ(a[i], expected[i]) << modes << " modes, " << i;
  }
}

}  // namespace
}  // namespace shockmap
