#pragma once
// The loops of a contact-station step (core/contact_stations.h), each compiled for x86-64-v4
// (AVX-512), x86-64-v3 (AVX2) and the baseline x86-64, the loader choosing. No multiply and add
// is fused (the file is compiled without contraction) and every value is computed with the same
// operations in the same order as one scalar at a time would, so the three clones give equal
// results bit for bit; a wider register only computes more stations or zones per instruction
// (docs/performance.md, "The contact stations' kernels").

#include <span>

namespace shockmap {

// phi . p[0 .. n), summed in the order of Eigen's reduction of row.dot(x) on 2-wide packets
// (SSE2): two pairs of partial sums over blocks of four, folded, then the tail. A station thus
// reads the same displacement as a row of the same values does (an observed output).
double StationDot(const double* phi, const double* p, int n);

// The `width` lanes the stations of one beam are padded to, for `count` stations: a multiple of
// the kernel's groups (1, 2, or 4 and 8).
int StationWidth(int count);

// The stations of one beam: slots [first, first + width), width = StationWidth(count), padded
// with zero shapes; its shapes at `shapes` in mode-major order (modes x width); its first
// coordinate in y and in z (-1 when it does not bend that way).
struct StationBlock {
  int y = -1, z = -1, modes = 0, first = 0, width = 0, count = 0, shapes = 0;
};

// For every block, out[2 (first + h)] = sum_i shapes[i * width + h] x[y + i] and
// out[2 (first + h) + 1] the same over z (0 in a direction the beam does not bend in), h <
// width: each slot's (y, z) side by side, each sum in StationDot's order.
void EvaluateStations(std::span<const StationBlock> blocks, const double* shapes, const double* x,
                      double* out);

// The zones as the linear penalty reads them (structure of arrays, zone order).
struct PenaltyZones {
  const int* slot_a;
  const int* slot_b;
  const double* normal_y;
  const double* normal_z;
  const double* gap;
  const double* stiffness;
  int count;
};

// Every zone's force k max(0, d), d = n . (u_a - u_b) - gap from its stations' displacements
// (u: each slot's (y, z) side by side; 0 when open or not a number), and the closed zones (d > 0)
// listed in zone order into `closed` (one int per zone), their number returned.
int LinearPenaltyForces(const PenaltyZones& zones, const double* u, double* force, int* closed);

// A force on one station: (y, z) components, added to its beam's modes through its row.
struct StationForce {
  int slot;
  double y, z;
};

// Where each slot's row and modes are (per slot: row offset, first y and z coordinates, -1 for
// none, and the number of modes).
struct StationLayout {
  const double* rows;
  const int* row;
  const int* y;
  const int* z;
  const int* modes;
};

// a[y + i] += f.y row[i] and a[z + i] += f.z row[i] for each force in order (the order in
// which a station's forces are added is the zones' order, which fixes the sums' roundings).
void AddStationForces(std::span<const StationForce> forces, const StationLayout& layout, double* a);

}  // namespace shockmap
