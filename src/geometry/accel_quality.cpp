#include "geometry/accel_quality.h"

#include <nlohmann/json.hpp>

namespace rtu {

void to_json(nlohmann::json& json, const AccelQuality& quality) {
  json = nlohmann::json{{"triangles", quality.triangles},
                        {"nodes", quality.nodes},
                        {"leaves", quality.leaves},
                        {"empty_leaves", quality.emptyLeaves},
                        {"depth", quality.depth},
                        {"list_entries", quality.listEntries},
                        {"triangles_per_leaf_mean", quality.trianglesPerLeafMean},
                        {"triangles_per_leaf_max", quality.trianglesPerLeafMax},
                        {"sah", quality.sah},
                        {"sah_seed", quality.sahSeed},
                        {"bytes", quality.bytes},
                        {"build_seconds", quality.buildSeconds}};
}

}  // namespace rtu
