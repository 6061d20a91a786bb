#pragma once
// Checks of a command's files before any long work starts: every output can be written, no two
// outputs are one file, and no output is one of the inputs (golden --jobs j.bin --out j.bin
// destroyed its input).

#include <string>
#include <vector>

#include "config/run_config.h"

namespace rtu {

struct NamedPath {
  std::string option;  // "--out"
  std::string path;    // empty: not given
};

// The files a run reads: --svo, --accel-file, --mesh, --binvox, --jobs, --rays.
std::vector<NamedPath> inputPaths(const RunConfig& settings);

// Throws std::invalid_argument naming the option and the path of the first output that cannot be
// created or written, is a directory, is given twice or is also an input.
void checkOutputPaths(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

// The JSON lines file written beside a CSV of rows (sweep, fps): rows.csv -> rows.jsonl.
std::string jsonLinesPath(const std::string& csvPath);

// Creates the folder `folder.path` and its parents if missing (as plot and animate do); throws
// std::invalid_argument naming the option when it cannot, or when it is a file.
void createOutputFolder(const NamedPath& folder);

}  // namespace rtu
