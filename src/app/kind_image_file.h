#pragma once
// Each core kind's memory image as a file (issue 26): how `validate` recognises and checks it,
// how `replay --core <kind> --accel-file` reads it and writes its results as CSV rows, and how
// `golden --accel-file` traces ray records through it (image_files.h chooses the kind by the
// file's header). A kind plugs in by specialising KindImageFile<Kind> in its own folder,
// kinds/<kind>/app/ (cmake/KindPlugins.cmake includes every header there as
// "kind_app_plugins.h"), with:
//   kByHeader      whether a file of its image is recognised by its header (the SVO's image has
//                  none: a file no kind recognises is read as an SVO image, `validate`'s default);
// and, with a header:
//   recognises     whether `words` begin with its header;
//   describeValid  "valid BVH image, 12 nodes, ..." for a sound image; throws std::runtime_error
//                  naming the file and its problems otherwise;
//   read           the validated image at `path` (throws as describeValid);
//   rows           the CSV rows (app/results_csv.h) of replayed results, in their order: t along
//                  the record's direction, the mesh's triangle, rtusim's barycentrics
//                  (hit = (1-u-v) v0 + u v1 + v v2), `words` the image;
//   golden         the untimed golden model on ray records in the image's own space, their rows
//                  appended to `rows`, the report text returned; or throws std::invalid_argument
//                  saying what traces the image instead.

#include <string>
#include <vector>

#include "app/results_csv.h"
#include "config/run_config.h"
#include "kinds/registry.h"
#include "rtu/ray_record.h"

namespace rtu {

template <class Kind>
struct KindImageFile;

}  // namespace rtu
