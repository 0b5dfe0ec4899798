#pragma once
// The model part of a CalculiX deck: a block lx by ly by lz meshed in nx by ny by nz 20-node
// bricks (C3D20R), clamped on its face x = 0, for the structure tests and benchmarks. Its nodes
// sit on the grid of half elements (i, j, k), 0 <= i <= 2 nx, ..., except where two or more of
// i, j, k are odd (no face or body centres); they are numbered in the grid's order from 1.

#include <array>
#include <map>
#include <sstream>
#include <string>

namespace shockmap::testing {

struct BrickBlock {
  double lx = 1.0, ly = 0.1, lz = 0.1;
  int nx = 10, ny = 1, nz = 1;
  double young_pa = 2.1e11, poisson = 0.3, density_kg_m3 = 7800.0;

  // Node ids by grid point.
  std::map<std::array<int, 3>, int> NodeIds() const {
    std::map<std::array<int, 3>, int> ids;
    for (int i = 0; i <= 2 * nx; ++i)
      for (int j = 0; j <= 2 * ny; ++j)
        for (int k = 0; k <= 2 * nz; ++k)
          if ((i % 2) + (j % 2) + (k % 2) < 2) ids[{i, j, k}] = static_cast<int>(ids.size()) + 1;
    return ids;
  }

  // *NODE, *ELEMENT (set EALL), *MATERIAL, *SOLID SECTION and the clamp's *BOUNDARY.
  std::string ModelDeck() const {
    const auto ids = NodeIds();
    const auto id = [&](int i, int j, int k) { return ids.at({i, j, k}); };
    std::ostringstream deck;
    deck.precision(17);
    deck << "*NODE, NSET=NALL\n";
    for (const auto& [g, n] : ids) {
      deck << n << ", " << lx * g[0] / (2 * nx) << ", " << ly * g[1] / (2 * ny) << ", "
           << lz * g[2] / (2 * nz) << "\n";
    }
    deck << "*ELEMENT, TYPE=C3D20R, ELSET=EALL\n";
    int element = 0;
    for (int ex = 0; ex < nx; ++ex)
      for (int ey = 0; ey < ny; ++ey)
        for (int ez = 0; ez < nz; ++ez) {
          const int a = 2 * ex, b = a + 2, mx = a + 1, c = 2 * ey, d = c + 2, my = c + 1;
          const int z0 = 2 * ez, z1 = z0 + 2, mz = z0 + 1;
          // Corners of the face z-, of z+, mid-edges of z-, of z+, then the edges along z.
          const int n[20] = {id(a, c, z0),  id(b, c, z0),  id(b, d, z0),  id(a, d, z0),
                             id(a, c, z1),  id(b, c, z1),  id(b, d, z1),  id(a, d, z1),
                             id(mx, c, z0), id(b, my, z0), id(mx, d, z0), id(a, my, z0),
                             id(mx, c, z1), id(b, my, z1), id(mx, d, z1), id(a, my, z1),
                             id(a, c, mz),  id(b, c, mz),  id(b, d, mz),  id(a, d, mz)};
          deck << ++element;
          for (int q = 0; q < 20; ++q) deck << (q == 15 ? ",\n" : ", ") << n[q];
          deck << "\n";
        }
    deck << "*MATERIAL, NAME=M\n*ELASTIC\n"
         << young_pa << ", " << poisson << "\n*DENSITY\n"
         << density_kg_m3 << "\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n*BOUNDARY\n";
    for (const auto& [g, n] : ids)
      if (g[0] == 0) deck << n << ", 1, 3\n";
    return deck.str();
  }

  // The free DOFs: 3 per node off the clamped face.
  int FreeDofs() const {
    int free = 0;
    for (const auto& [g, n] : NodeIds()) free += g[0] == 0 ? 0 : 3;
    return free;
  }
};

}  // namespace shockmap::testing
