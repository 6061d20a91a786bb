#include <catch2/catch.hpp>

#include <string>

#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"
#include "kinds/svo/svo_size_estimate.h"

namespace rtu {

// The estimate decides whether a build is refused, so it must not fall below the real size and
// must stay close enough to let every tree that fits be built.
TEST_CASE("size estimate: bounds the built tree from above, within a small factor", "[builder]") {
  for (const std::string name : {"sphere", "shell", "menger", "terrain", "noise"}) {
    for (int depth : {3, 6, 9}) {
      const auto source = makeProceduralScene(name, depth);
      const SvoBuild build = buildSvo(*source);
      const SvoSizeEstimate estimate = estimateSvoSize(*source, 0);
      INFO(name << " at depth " << depth << ": " << build.stats.descriptors << " descriptors, "
                << estimate.descriptors << " estimated");
      CHECK(estimate.descriptors >= static_cast<double>(build.stats.descriptors));
      // noise answers Mixed for every node above its voxels, so the count cannot see the empty
      // ones that collapse: 3.3 times the built tree at depth 6 and 9.
      CHECK(estimate.descriptors <= 4.0 * static_cast<double>(build.stats.descriptors) + 8);
      CHECK(estimate.imageBytes == 4.0 * estimate.descriptors);
    }
  }
}

TEST_CASE("size estimate: counts the zero words before the root", "[builder]") {
  const auto source = makeProceduralScene("sphere", 4);
  const SvoSizeEstimate atZero = estimateSvoSize(*source, 0);
  const SvoSizeEstimate moved = estimateSvoSize(*source, 1000);
  CHECK(moved.imageBytes == atZero.imageBytes + 4000.0);
  CHECK(moved.peakBytes > atZero.peakBytes);
}

}  // namespace rtu
