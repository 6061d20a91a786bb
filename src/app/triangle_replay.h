#pragma once
// `replay` of triangle ray records (issue 28 §2): the image file of the kind `--core` names (a
// .bvh, .bih or .kd image, recognised by its header's magic word and checked as `validate` checks
// it), traced in its own space as `golden --accel-file` traces it: an identity model header after
// the image, the records (each naming model address 0, as golden's) aimed at it, so a BVH's or
// k-d tree's records are in the mesh's coordinates and a BIH's on its grid. Results as the CSV
// rows of app/results_csv.h.

#include <string>
#include <vector>

#include "app/results_csv.h"
#include "kinds/registry.h"
#include "rtu/ray_record.h"

namespace rtu {

struct TriangleReplayInput {
  std::vector<uint32_t> words;      // the image at word 0, then its identity model header
  std::vector<HostRecord> records;  // the rays, naming that header
};

// Throws std::invalid_argument when the file holds no image of the kind `core`, and
// std::runtime_error naming the file for an unsound image, or naming `raysPath` and the record
// for a model address other than 0.
TriangleReplayInput triangleReplayInput(const std::string& core, const std::string& imagePath,
                                        const std::vector<RayRecord>& rays,
                                        const std::string& raysPath);

// The rows of a triangle kind's results, in their order (KindImageFile::rows): t along the record's
// direction, the triangle's index in the mesh as built, rtusim's barycentrics
// (hit = (1-u-v) v0 + u v1 + v v2). `words` is the replayed image (a BIH's formats scale its
// barycentrics).
std::vector<ResultRow> triangleResultRows(const std::string& core,
                                          const std::vector<CoreKindResult>& results,
                                          const std::vector<uint32_t>& words);

}  // namespace rtu
