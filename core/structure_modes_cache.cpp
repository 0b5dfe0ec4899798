#include "core/structure_modes_cache.h"

#include <atomic>
#include <bit>
#include <cstdint>
#include <string_view>

#include "core/solution_cache.h"

namespace shockmap {
namespace {

// 64-bit FNV-1a, fed one word at a time.
class ContentHash {
 public:
  void Add(std::uint64_t word) {
    for (int byte = 0; byte < 8; ++byte) {
      hash_ = (hash_ ^ ((word >> (8 * byte)) & 0xffu)) * 0x100000001b3u;
    }
  }
  void Add(double value) { Add(std::bit_cast<std::uint64_t>(value)); }
  void Add(std::string_view text) {
    Add(static_cast<std::uint64_t>(text.size()));
    for (const char c : text) Add(static_cast<std::uint64_t>(static_cast<unsigned char>(c)));
  }
  std::uint64_t Value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325u;
};

void AddMatrix(ContentHash& hash, const Eigen::SparseMatrix<double>& a) {
  hash.Add(static_cast<std::uint64_t>(a.rows()));
  hash.Add(static_cast<std::uint64_t>(a.cols()));
  for (Eigen::Index j = 0; j < a.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it) {
      hash.Add(static_cast<std::uint64_t>(it.index()));
      hash.Add(it.value());
    }
    hash.Add(~std::uint64_t{0});  // The column's end.
  }
}

// Equal stored entries, in the same order, bit for bit (0.0 and -0.0 differ, as NaNs do not).
bool SameStoredEntries(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros()) return false;
  for (Eigen::Index j = 0; j < a.outerSize(); ++j) {
    Eigen::SparseMatrix<double>::InnerIterator ia(a, j), ib(b, j);
    for (; ia && ib; ++ia, ++ib) {
      if (ia.index() != ib.index() ||
          std::bit_cast<std::uint64_t>(ia.value()) != std::bit_cast<std::uint64_t>(ib.value())) {
        return false;
      }
    }
    if (ia || ib) return false;
  }
  return true;
}

bool SameDofs(const std::vector<StructureDof>& a, const std::vector<StructureDof>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].node != b[i].node || a[i].component != b[i].component) return false;
  }
  return true;
}

double StoredBytes(const Eigen::SparseMatrix<double>& a) {
  return static_cast<double>(a.nonZeros()) * (sizeof(double) + sizeof(int)) +
         static_cast<double>(a.outerSize() + 1) * sizeof(int);
}

// What the cache keeps for a solution: its shapes and frequencies, and the structure its key
// holds.
double KeptBytes(const SceneStructureModes& m) {
  return static_cast<double>(m.basis.shapes.size() + m.basis.omega_rad_s.size()) * sizeof(double) +
         StoredBytes(m.fe->stiffness) + StoredBytes(m.fe->mass) +
         static_cast<double>(m.fe->dofs.size() * sizeof(StructureDof));
}

std::atomic<std::int64_t> solves{0};

struct StructureModesKey {
  std::shared_ptr<const FeStructure> fe;
  std::uint64_t content_hash = 0;
  std::optional<double> f_trunc_hz;
  double ratio = 0.0;
  std::vector<int> static_nodes;

  bool operator==(const StructureModesKey& o) const {
    return content_hash == o.content_hash && f_trunc_hz == o.f_trunc_hz && ratio == o.ratio &&
           static_nodes == o.static_nodes && SameStructureContent(*fe, *o.fe);
  }
};

}  // namespace

std::uint64_t StructureContentHash(const FeStructure& s) {
  ContentHash hash;
  hash.Add(s.name);
  AddMatrix(hash, s.stiffness);
  AddMatrix(hash, s.mass);
  hash.Add(static_cast<std::uint64_t>(s.dofs.size()));
  for (const StructureDof& dof : s.dofs) {
    hash.Add(static_cast<std::uint64_t>(static_cast<std::uint32_t>(dof.node)));
    hash.Add(static_cast<std::uint64_t>(dof.component));
  }
  return hash.Value();
}

bool SameStructureContent(const FeStructure& a, const FeStructure& b) {
  return &a == &b ||
         (a.name == b.name && SameDofs(a.dofs, b.dofs) &&
          SameStoredEntries(a.stiffness, b.stiffness) && SameStoredEntries(a.mass, b.mass));
}

std::int64_t StructureModeSolves() { return solves.load(); }

SceneStructureModes StructureModesCached(std::shared_ptr<const FeStructure> fe,
                                         std::optional<double> f_trunc_hz, double ratio,
                                         const std::vector<int>& static_nodes) {
  static SolutionCache<StructureModesKey, SceneStructureModes> cache(kStructureModesCacheBytes);
  const StructureModesKey key{fe, StructureContentHash(*fe), f_trunc_hz, ratio, static_nodes};
  SceneStructureModes modes = *cache.Get(
      key,
      [&] {
        ++solves;
        return MakeStructureModes(fe, f_trunc_hz, ratio, static_nodes);
      },
      KeptBytes);
  modes.fe = std::move(fe);
  return modes;
}

}  // namespace shockmap
