// BackgroundWriter: jobs run on a second thread, one at a time in the order posted, and a failed
// job stops the later ones and reaches the caller.
#include "common/BackgroundWriter.h"
#include "common/AtomicFile.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace gl = geolattice;

namespace {

/// What the jobs "wrote": per path, the sequence numbers of the writes in the order they ran.
struct Log {
  std::mutex mutex;
  std::map<std::string, std::vector<int>> writes;
  std::map<std::string, int> writing;  ///< jobs of a path running now
  int overlaps = 0;                    ///< a path written by two jobs at once
  void write(const std::string& path, int seq) {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      overlaps += writing[path]++ > 0;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200 + 37 * (seq % 7)));
    const std::lock_guard<std::mutex> lock(mutex);
    --writing[path];
    writes[path].push_back(seq);
  }
};

}  // namespace

TEST(BackgroundWriter, WritesEveryFileOnceAndTheSamePathInTheOrderPosted) {
  Log log;
  gl::BackgroundWriter writer;
  const std::vector<std::string> paths = {"a.vtu", "b.vtp", "a.vtu", "c.vtp", "b.vtp", "a.vtu"};
  for (int round = 0; round < 20; ++round) {
    for (size_t k = 0; k < paths.size(); ++k) {
      const int seq = round * 100 + static_cast<int>(k);
      writer.post(paths[k], [&log, path = paths[k], seq] { log.write(path, seq); });
    }
  }
  const auto done = writer.wait();
  EXPECT_EQ(done.size(), 120u);
  EXPECT_EQ(log.overlaps, 0);
  for (const auto& [path, seqs] : log.writes) {
    for (size_t i = 1; i < seqs.size(); ++i) {
      EXPECT_LT(seqs[i - 1], seqs[i]) << path;
    }
  }
  EXPECT_EQ(log.writes["a.vtu"].size(), 60u);
  EXPECT_EQ(log.writes["c.vtp"].size(), 20u);
  EXPECT_TRUE(writer.wait().empty());  // each finished job is returned once
}

TEST(BackgroundWriter, JobsRunOneAtATimeInTheOrderPostedOffTheCallersThread) {
  gl::BackgroundWriter writer;
  std::mutex mutex;
  std::vector<int> ran;
  std::vector<std::thread::id> threads;
  for (int k = 0; k < 40; ++k) {
    writer.post("f" + std::to_string(k % 3), [&, k] {
      std::this_thread::sleep_for(std::chrono::microseconds(300));
      const std::lock_guard<std::mutex> lock(mutex);
      ran.push_back(k);
      threads.push_back(std::this_thread::get_id());
    });
  }
  const auto done = writer.wait();
  ASSERT_EQ(ran.size(), 40u);
  for (int k = 0; k < 40; ++k) {
    EXPECT_EQ(ran[static_cast<size_t>(k)], k);
    EXPECT_EQ(done[static_cast<size_t>(k)].first, "f" + std::to_string(k % 3));
    EXPECT_NE(threads[static_cast<size_t>(k)], std::this_thread::get_id());
  }
}

TEST(BackgroundWriter, AFailedWriteSkipsTheLaterOnesAndReachesTheCaller) {
  gl::BackgroundWriter writer;
  std::atomic<int> written{0};
  writer.post("tets.vtu", [&] { ++written; });
  writer.post("layers.vtp", [] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // slow, then fails
    throw gl::FileWriteError("could not write layers.vtp");
  });
  for (const char* later : {"lattice.vtp", "toolpath.vtp", "toolpath.pvd"}) {
    writer.post(later, [&] { ++written; });
  }
  try {
    writer.wait();
    FAIL() << "wait() did not rethrow";
  } catch (const gl::FileWriteError& e) {
    EXPECT_NE(std::string(e.what()).find("layers.vtp"), std::string::npos);
  }
  EXPECT_EQ(written.load(), 1);  // nothing after the failure was written
  // What was written before the failure is still told (the CLI keeps it in report.json).
  const auto before = writer.finished();
  ASSERT_EQ(before.size(), 1u);
  EXPECT_EQ(before[0].first, "tets.vtu");
  EXPECT_TRUE(writer.finished().empty());
  EXPECT_THROW(writer.check(), gl::FileWriteError);
  writer.post("report.json", [&] { ++written; });  // skipped too: the run has failed
  EXPECT_THROW(writer.wait(), gl::FileWriteError);
  EXPECT_EQ(written.load(), 1);
}

TEST(BackgroundWriter, CheckDoesNotWaitAndTheDestructorFinishesThePostedJobs) {
  std::atomic<int> written{0};
  {
    gl::BackgroundWriter writer;
    writer.check();  // nothing posted: nothing to throw
    for (int k = 0; k < 10; ++k) {
      writer.post("f" + std::to_string(k), [&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        ++written;
      });
    }
    writer.check();  // no failure so far: returns at once
  }
  EXPECT_EQ(written.load(), 10);
}
