#include <string>

#include "core/scene.h"

namespace shockmap {

std::string Scene::SideName(const SceneZone& z, bool side_b) const {
  const int beam = side_b ? z.beam_b : z.beam_a;
  const int structure = side_b ? z.structure_b : z.structure_a;
  if (structure >= 0) {
    return structures[static_cast<std::size_t>(structure)].name + "#" +
           std::to_string(side_b ? z.node_b : z.node_a);
  }
  return beam >= 0 ? beams[static_cast<std::size_t>(beam)].name : std::string("stop");
}

}  // namespace shockmap
