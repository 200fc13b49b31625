#pragma once
/// @file BackgroundWriter.h
/// @brief A queue of file writes run in order on a second thread.
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace geolattice {

/// Writes files on a thread of its own, one after another in the order posted, while the caller
/// goes on: the CLI writes each stage's VTK file while the next stages compute, so on two cores
/// the encoding of the files (LZ4 + base64, most of their time) overlaps the stages instead of
/// adding to them. A job must own what it writes (e.g. a deep copy of a VTK output: VTK caches
/// array ranges and bounds inside the arrays, so an array read by a writer and a filter at once
/// is a data race), and own it alone: a VTK object released on two threads at once is a data
/// race in VTK's reference counting (the last two releases both decide whether to delete it or
/// run the garbage collector on it; a `geolattice run` crashed so once in about 50 runs, found
/// with ThreadSanitizer). Move the only reference into the job. Once a job has failed the later ones are skipped, and check() and wait()
/// rethrow its error: the files are written as far as they would have been in line, no further.
class BackgroundWriter {
public:
  BackgroundWriter() = default;
  /// Finishes the posted jobs (their errors are dropped: call wait() to see them).
  ~BackgroundWriter();
  BackgroundWriter(const BackgroundWriter&) = delete;
  BackgroundWriter& operator=(const BackgroundWriter&) = delete;

  /// Queues `write` for `path` (may be empty: a job without a file of its own); the thread starts
  /// with the first job.
  void post(std::string path, std::function<void()> write);
  /// Throws the error of a failed job, if any, without waiting.
  void check();
  /// Waits for every posted job; returns (path, seconds) of each one finished since the last
  /// call, in the order posted. Throws the error of a failed job.
  std::vector<std::pair<std::string, double>> wait();
  /// The (path, seconds) of the jobs finished since the last call of this or wait(), without
  /// waiting: after wait() threw, the files written before the failure.
  std::vector<std::pair<std::string, double>> finished();

private:
  void work();
  struct Job {
    std::string path;
    std::function<void()> write;
  };
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> queue_;
  bool busy_ = false;  ///< a job is running
  std::vector<std::pair<std::string, double>> done_;
  std::exception_ptr error_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace geolattice
