#pragma once
// A GTKWave save file (.gtkw) for a trace: the trace to open, its signals grouped per module in
// pipeline order (job manager = host in, scheduler, cores, memory, result manager, reorder buffer
// = host out), full hierarchical names with an alias within the group, and a marker. Signals with
// named values show the names: an FST carries them as enum tables; for a VCD a translate filter
// file is written next to the trace (t.state.txt for the core states of t.vcd).

#include <cstdint>
#include <string>
#include <vector>

namespace rtu {

struct SaveFileSignal {
  std::string scope, name;  // scope: dot-separated module path, e.g. rtu.core_3.in
  int width;
  std::vector<std::string> valueNames;  // names of the values 0, 1, ...; empty for numbers
};

// The save file's path: the trace's with ".gtkw" appended (t.fst.gtkw, t.vcd.gtkw: a VCD and an
// FST of one name keep their own).
std::string saveFilePath(const std::string& tracePath);

// What the save file shows first, in GTKWave's time unit (TraceTimeUnit::viewerFactor): the
// marker, and the view from `start` to before `end` (the window), zoomed to fit a window of the
// size the save file sets.
struct SaveFileView {
  uint64_t marker = 0, start = 0, end = 1;
};

// Writes saveFilePath(tracePath), the group of `firstModule` (e.g. "core_3") first when it is
// not empty; throws std::runtime_error when it cannot be written.
void writeSaveFile(const std::string& tracePath, const std::vector<SaveFileSignal>& signals,
                   const SaveFileView& view, const std::string& firstModule = {});
// GTKWave's zoom (the save file's "*" line) that shows `span` time units in its window of the
// save file's size, a little to spare.
double zoomToFit(uint64_t span);

}  // namespace rtu
