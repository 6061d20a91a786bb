#pragma once
// The worker processes of fps, sweep and animate: `-j N` / `--workers N`. `--jobs N` still sets
// them, with a deprecation warning: in replay and golden `--jobs` is a job-buffer file.

#include <string>

#include <CLI/CLI.hpp>

namespace rtu {

// Registers the options on `command`, writing the count into `workers` (which must outlive
// parsing), in 1 .. `maxWorkers`.
void addWorkersOption(CLI::App& command, int& workers, const std::string& help, int maxWorkers);

}  // namespace rtu
