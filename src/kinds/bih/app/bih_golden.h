#pragma once
// The golden model of seed 004's BIH core on a host's ray records (issue 27): each record traced
// through a BIH image (.bih, kinds/bih/bih_image.h) by the untimed shell of the BIH kind, in the
// image's own space, its integer grid. A .bih file keeps the scene box on the grid only (header
// words 11-13), not where the world lay, so a record's origin and direction are grid coordinates
// and must name model address 0; the job set-up of the BIH core (bih_job_setup.h) then clips the
// ray to [0, upper] and quantises it as for any world ray whose model header is the identity.
// World rays are traced by `render --core bih`, which builds the model header from the mesh.

#include <string>
#include <vector>

#include "app/results_csv.h"
#include "kinds/bih/bih_kind.h"
#include "rtu/ray_record.h"

namespace rtu {

struct BihGoldenRun {
  std::vector<ResultRow> rows;  // in record order: t in grid units along the record's direction
  uint64_t nodes = 0, triangleTests = 0, cost = 0;  // totals over the rays
  double seconds = 0;                               // host time of the traversals
};

// A BIH result's row: t its distance along the record's direction, the seed's (v, u) as rtusim's
// barycentrics at the image's `format` (2^(m-1+E)).
ResultRow bihResultRow(const BihResult& result, const FixedTriangleFormat& format);

// Throws std::runtime_error naming `raysPath` and the record for a model address other than 0,
// and as readBihFile for `image`'s words.
BihGoldenRun traceBihGolden(const std::vector<uint32_t>& image, const std::vector<RayRecord>& rays,
                            const std::string& raysPath);

}  // namespace rtu
