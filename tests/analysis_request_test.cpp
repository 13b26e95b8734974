// AnalyzeRequest from memory and its limits: part bytes and face groups as text give the
// same analysis as the files, max_faces, and a stop request that cancels inside one long
// surface (not only between surfaces).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#include <spdlog/logger.h>
#include <spdlog/sinks/ostream_sink.h>

#include "gvm/analysis.h"
#include "support/scratch_dir.h"

namespace gvm {
namespace {

using Clock = std::chrono::steady_clock;

std::string shared_part(const std::string& name) {
  return std::string(GVM_SHARED_DIR) + "/data/parts/" + name;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(AnalyzeRequest, PartBytesAndGroupsJsonAsFiles) {
  const std::string path = shared_part("prusa_endstop-block.stl");
  const std::string groups = R"({"top": [0, 1], "side": [5]})";
  const std::string groups_path = (test::scratch_dir() / "groups.json").string();
  std::ofstream(groups_path) << groups;

  AnalyzeRequest from_files;
  from_files.part_path = path;
  from_files.groups_path = groups_path;
  from_files.options.set_threads(2);
  auto a = analyze(from_files);
  ASSERT_TRUE(a.ok()) << a.status().message();

  const std::string bytes = slurp(path);
  AnalyzeRequest from_memory;
  from_memory.part_bytes = bytes;
  from_memory.part_format = MeshFormat::kStl;
  from_memory.part_name = "endstop from memory";
  from_memory.groups_json = groups;
  from_memory.options.set_threads(2);
  std::ostringstream log_lines;
  from_memory.logger = std::make_shared<spdlog::logger>(
      "request-17", std::make_shared<spdlog::sinks::ostream_sink_mt>(log_lines));
  auto b = analyze(from_memory);
  ASSERT_TRUE(b.ok()) << b.status().message();

  EXPECT_EQ(b->part().source, "endstop from memory");
  EXPECT_EQ(a->part().input_faces, b->part().input_faces);
  ASSERT_EQ(a->regions().size(), b->regions().size());
  ASSERT_EQ(a->features().size(), b->features().size());
  for (size_t i = 0; i < a->features().size(); ++i) {
    const Surface &x = a->features()[i], &y = b->features()[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.faces, y.faces);
    EXPECT_EQ(x.maps.status, y.maps.status);
    ASSERT_EQ(x.maps.gvm.has_value(), y.maps.gvm.has_value());
    if (x.maps.gvm) EXPECT_TRUE(*x.maps.gvm == *y.maps.gvm) << x.name;
  }
  // Messages name the part and the groups as given.
  from_memory.groups_json = R"({"top": [0, 99999]})";
  auto bad_groups = analyze(from_memory);
  EXPECT_EQ(bad_groups.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(bad_groups.status().message().find("face 99999 does not exist"), std::string::npos)
      << bad_groups.status().message();
  from_memory.groups_json.clear();
  from_memory.part_bytes = std::string_view(bytes).substr(0, 1000);
  auto cut = analyze(from_memory);
  EXPECT_EQ(cut.status().code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(cut.status().message().rfind("endstop from memory: ", 0), 0u) << cut.status().message();
}

TEST(AnalyzeRequest, MaxFaces) {
  AnalyzeRequest request;
  request.part_path = shared_part("prusa_endstop-block.stl");  // 308 faces
  request.max_faces = 300;
  auto r = analyze(request);
  ASSERT_EQ(r.status().code(), StatusCode::kResourceExhausted);
  EXPECT_NE(r.status().message().find("308 faces, more than the limit of 300"), std::string::npos)
      << r.status().message();
  request.max_faces = 308;
  request.options.set_lvm_only(true);
  EXPECT_TRUE(analyze(request).ok());
}

TEST(AnalyzeRequest, StopBeforeStart) {
  std::stop_source stop;
  stop.request_stop();
  AnalyzeRequest request;
  request.part_path = shared_part("prusa_endstop-block.stl");
  request.stop = stop.get_token();
  auto r = analyze(request);
  EXPECT_EQ(r.status().code(), StatusCode::kCancelled);
  EXPECT_EQ(r.status().message(), "analysis cancelled");
}

TEST(AnalyzeRequest, ProgressFalseCancels) {
  AnalyzeRequest request;
  request.part_path = shared_part("prusa_endstop-block.stl");
  request.progress = [](size_t, size_t) { return false; };
  EXPECT_EQ(analyze(request).status().code(), StatusCode::kCancelled);
}

// prusa_extruder-idler's feature F68 (|S| 174, |O_S| 1617, input faces 3383-3388 and
// 4143-4310) is the slowest surface of the Prusa parts: 1.4 s on one thread on an idle
// machine (x-end-idler's F36, used before, takes 0.16 s since the closures of the occluded
// directions are found in two passes). As user groups: that feature, and every other face
// as one feature "rest" (its LVM is empty). On one thread the surfaces run in order: the
// regions, "rest", then the long one.
// The stop comes 0.3 s after every surface but the long one is done (under sanitizers
// "rest" alone may take longer than 0.3 s, and a surface without long loops has no
// checks), so it lands inside the long one; analyze()
// must return kCancelled without finishing any surface after the stop: only the checks
// inside the long loops can do that (between surfaces, the running one would complete).
TEST(AnalyzeRequest, StopInsideOneLongSurface) {
  std::vector<uint32_t> slow;
  for (uint32_t f = 3383; f <= 3388; ++f) slow.push_back(f);
  for (uint32_t f = 4143; f <= 4310; ++f) slow.push_back(f);
  std::string json = R"({"a_slow": [)", rest = R"(], "rest": [)";
  for (size_t i = 0; i < slow.size(); ++i) json += (i ? "," : "") + std::to_string(slow[i]);
  bool first = true;
  for (uint32_t f = 0, k = 0; f < 4834; ++f) {
    if (k < slow.size() && slow[k] == f) {
      ++k;
      continue;
    }
    rest += (first ? "" : ",") + std::to_string(f);
    first = false;
  }
  json += rest + "]}";

  std::stop_source stop;
  AnalyzeRequest request;
  request.part_path = shared_part("prusa_extruder-idler.stl");
  request.groups_json = json;
  request.options.set_threads(1);
  request.stop = stop.get_token();
  std::mutex m;
  std::condition_variable cv;
  size_t done_at_stop = SIZE_MAX, done = 0;
  bool short_ones_done = false;
  request.progress = [&](size_t d, size_t total) {
    std::lock_guard lock(m);
    done = d;
    if (d + 1 == total) {
      short_ones_done = true;
      cv.notify_all();
    }
    return true;
  };
  Clock::time_point stopped_at;
  std::thread stopper([&] {
    std::unique_lock lock(m);
    if (!cv.wait_for(lock, std::chrono::minutes(10), [&] { return short_ones_done; })) return;
    lock.unlock();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    lock.lock();
    done_at_stop = done;
    stopped_at = Clock::now();
    stop.request_stop();
  });
  auto r = analyze(request);
  [[maybe_unused]] const auto returned_at = Clock::now();  // unused under sanitizers
  stopper.join();
  ASSERT_NE(done_at_stop, SIZE_MAX) << "the short surfaces never finished";
  ASSERT_EQ(r.status().code(), StatusCode::kCancelled)
      << (r.ok() ? "finished before the stop" : r.status().message());
  EXPECT_LT(done_at_stop, 4u);
  EXPECT_EQ(done, done_at_stop) << "a surface was finished after the stop";
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
  // Functional, with a wide margin: the interrupted surface alone takes several seconds;
  // the loops check every few hundred cheap iterations (milliseconds).
  EXPECT_LT(std::chrono::duration<double>(returned_at - stopped_at).count(), 2.0);
#endif
}

}  // namespace
}  // namespace gvm
