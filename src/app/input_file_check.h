#pragma once
// The command-line check of an option that names an input file: CLI::ExistingFile takes a FIFO
// or a device for a file, so options check with the input rule of base/input_file.h instead.

#include <CLI/CLI.hpp>

namespace rtu {

// Accepts a regular file only; the message names the path and what it is.
CLI::Validator regularInputFile();

}  // namespace rtu
