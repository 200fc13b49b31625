#pragma once
/// @file ParallelFor.h
/// @brief The one worker pool of core: items 0..n-1 handed out one at a time to `threads`
/// workers (0 = hardware concurrency, never more than n). The first exception a worker throws
/// stops the hand-out and is rethrown on the calling thread after all workers have joined, so
/// errors propagate like in a serial loop. Progress callbacks stay on the calling thread:
/// `onDone` (optional) runs there once per finished item, with the number finished so far (1,
/// 2, ..., n in order; a late wake-up makes up the counts it missed).
#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace geolattice {

/// Worker count for `threads` (0 = hardware concurrency) and n items: in [1, max(n, 1)].
inline int workerCount(int threads, size_t n) {
  const int hw = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int want = threads > 0 ? threads : hw;
  return std::max(1, std::min(want, static_cast<int>(std::max<size_t>(n, 1))));
}

/// Runs work(item, worker) for every item in [0, n) on workerCount(threads, n) threads (worker
/// is 0..workers-1, e.g. to index per-worker scratch data).
inline void parallelFor(size_t n, int threads, const std::function<void(size_t, int)>& work,
                        const std::function<void(size_t)>& onDone = {}) {
  const int workers = workerCount(threads, n);
  if (workers == 1) {
    for (size_t i = 0; i < n; ++i) {
      work(i, 0);
      if (onDone) {
        onDone(i + 1);
      }
    }
    return;
  }
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex mutex;
  std::condition_variable changed;
  size_t done = 0;
  std::vector<std::thread> pool;
  for (int w = 0; w < workers; ++w) {
    pool.emplace_back([&, w] {
      for (size_t i = next++; i < n && !failed; i = next++) {
        try {
          work(i, w);
        } catch (...) {
          std::lock_guard<std::mutex> lock(mutex);
          if (!error) {
            error = std::current_exception();
          }
          failed = true;
        }
        {
          std::lock_guard<std::mutex> lock(mutex);
          ++done;
        }
        changed.notify_one();
      }
    });
  }
  {  // progress on the calling thread
    std::unique_lock<std::mutex> lock(mutex);
    size_t reported = 0;
    while (reported < n && !failed) {  // to n, also when the workers were done first
      changed.wait(lock, [&] { return done > reported || failed; });
      if (done > reported && !failed) {
        const size_t now = done;
        if (!onDone) {
          reported = now;
          continue;
        }
        lock.unlock();
        try {
          // Every count, also when this thread woke late and several items finished meanwhile:
          // callers report progress at counts of their choosing (e.g. each 64th of n).
          while (reported < now) {
            onDone(++reported);  // may throw, e.g. an abort: stop the workers, rethrow below
          }
        } catch (...) {
          lock.lock();
          if (!error) {
            error = std::current_exception();
          }
          failed = true;
          continue;
        }
        lock.lock();
      }
    }
  }
  for (std::thread& t : pool) {
    t.join();
  }
  if (error) {
    std::rethrow_exception(error);
  }
}

}  // namespace geolattice
