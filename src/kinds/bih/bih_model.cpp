#include "kinds/bih/bih_model.h"

namespace rtu {

ModelPlacement gridPlacement(const SceneGrid& grid, const ModelPlacement& placement) {
  ModelPlacement onGrid = placement;
  onGrid.scale = placement.scale / grid.scale();
  onGrid.translation =
      placement.translation + placement.rotation * (placement.scale * grid.box().lower);
  return onGrid;
}

uint32_t appendBihModelHeader(std::vector<uint32_t>& words, const SceneGrid& grid,
                              const ModelPlacement& placement) {
  const auto address = static_cast<uint32_t>(words.size());
  const ModelHeaderWords header =
      encodeModelHeader(makeModelHeader(gridPlacement(grid, placement), 0));
  words.insert(words.end(), header.begin(), header.end());
  return address;
}

}  // namespace rtu
