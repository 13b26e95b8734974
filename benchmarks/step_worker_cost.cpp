// gvm_step_worker_cost: what reading a STEP file in gvm-step-worker costs against reading
// it in this process (the STEP module called directly, as the worker itself does): wall
// seconds of each, alternating run by run, and the size of the worker's reply.
//
//   gvm_step_worker_cost OUT.json RUNS PART.stp ...
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gvm/step.h"
#include "gvm/v1/benchmark.pb.h"
#include "step_loader/step_module_loader.h"
#include "step_loader/step_worker_messages.h"
#include "support/shared_parts.h"

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class Read>
double timed(Read read) {
  const auto t0 = Clock::now();
  if (!read().ok()) return -1;
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: gvm_step_worker_cost OUT.json RUNS PART.stp ...\n");
    return 2;
  }
  const int runs = std::max(1, std::atoi(argv[2]));
  gvm::v1::StepWorkerCostBenchmark out;
  out.set_machine("2-core Debian 12 VM");
  for (int i = 3; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    const std::string data = bytes.str(), source = argv[i];
    const gvm::StepOptions options;
    auto part = gvm::step_internal::read_step_in_process(data, options, source);
    if (!part.ok()) {
      std::fprintf(stderr, "%s: %s\n", argv[i], part.status().message().c_str());
      continue;
    }
    gvm::v1::StepWorkerCost& row = *out.add_parts();
    row.set_model(std::filesystem::path(source).filename().string());
    row.set_file_bytes(data.size());
    row.set_reply_bytes(gvm::step_internal::worker_reply(*part).ByteSizeLong());
    row.set_triangles(static_cast<uint32_t>(part->mesh.faces.size()));
    row.set_runs(static_cast<uint32_t>(runs));
    std::vector<double> here, worker;
    for (int r = 0; r < runs; ++r) {
      here.push_back(timed([&] { return gvm::step_internal::read_step_in_process(data, options, source); }));
      worker.push_back(timed([&] { return gvm::read_step(std::string_view(data), options, source); }));
    }
    row.set_in_process_seconds(median(here));
    row.set_worker_seconds(median(worker));
    std::printf("%-40s %8zu B  reply %9llu B  in process %.3f s  worker %.3f s  (+%.3f s)\n", row.model().c_str(),
                data.size(), static_cast<unsigned long long>(row.reply_bytes()), row.in_process_seconds(),
                row.worker_seconds(), row.worker_seconds() - row.in_process_seconds());
  }
  return gvm::bench::write_json(out, argv[1]) ? 0 : 1;
}
