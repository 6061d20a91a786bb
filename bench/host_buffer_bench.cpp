// Reading and writing the host buffers of a 1280x720 frame (issue 9: the 29 MB job and result
// buffers together in under 50 ms): write and read the job buffer, then the result buffer, best
// of five. Files go to the directory given (default /tmp), so the page cache serves them. Not a
// test: run it and record the figures in docs/performance.md.
//   build/bench/host_buffer_bench [directory]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_frame.h"
#include "inputs/host_buffers.h"
#include "kinds/svo/golden_model.h"

using namespace rtu;

namespace {

template <typename Work>
double bestSecondsOf(Work&& work) {
  double best = 1e9;
  for (int run = 0; run < 5; ++run) {
    const auto start = std::chrono::steady_clock::now();
    work();
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string directory = argc > 1 ? argv[1] : "/tmp";
  const BenchFrame frame = benchFrame("menger", 6);
  const std::vector<TraversalResult> results =
      GoldenModel(frame.build.image.memory(), GoldenConfig{}).traceAll(frame.jobs);
  const std::string jobPath = directory + "/host_buffer_bench_jobs.bin";
  const std::string resultPath = directory + "/host_buffer_bench_results.bin";
  const double writeJobs = bestSecondsOf([&] { writeJobBuffer(jobPath, frame.jobs); });
  size_t jobsRead = 0;
  const double readJobs = bestSecondsOf([&] { jobsRead = readJobBuffer(jobPath).size(); });
  const double writeResults = bestSecondsOf([&] { writeResultBuffer(resultPath, results); });
  size_t resultsRead = 0;
  const double readResults =
      bestSecondsOf([&] { resultsRead = readResultBuffer(resultPath).size(); });
  std::remove(jobPath.c_str());
  std::remove(resultPath.c_str());
  const double megabytes = static_cast<double>(frame.jobs.size() * kRecordBytes) / 1e6;
  std::printf("%zu records, %.1f MB per buffer (best of 5)\n", frame.jobs.size(), megabytes);
  std::printf("write jobs    %6.1f ms\nread jobs     %6.1f ms\nwrite results %6.1f ms\n"
              "read results  %6.1f ms\nreplay's part (read jobs + write results) %.1f ms\n",
              1e3 * writeJobs, 1e3 * readJobs, 1e3 * writeResults, 1e3 * readResults,
              1e3 * (readJobs + writeResults));
  return jobsRead == frame.jobs.size() && resultsRead == results.size() ? 0 : 1;
}
