#include "common/BackgroundWriter.h"

#include <algorithm>
#include <chrono>

namespace geolattice {

BackgroundWriter::~BackgroundWriter() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) {
    thread_.join();
  }
}

void BackgroundWriter::post(std::string path, std::function<void()> write) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back({std::move(path), std::move(write)});
    if (!thread_.joinable()) {
      thread_ = std::thread([this] { this->work(); });
    }
  }
  changed_.notify_all();
}

void BackgroundWriter::check() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (error_) {
    std::rethrow_exception(error_);
  }
}

std::vector<std::pair<std::string, double>> BackgroundWriter::wait() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!queue_.empty() || !running_.empty()) {
    if (!this->runNext(lock)) {
      changed_.wait(lock);
    }
  }
  if (error_) {
    std::rethrow_exception(error_);
  }
  return std::exchange(done_, {});
}

bool BackgroundWriter::runNext(std::unique_lock<std::mutex>& lock) {
  if (queue_.empty() ||
      std::find(running_.begin(), running_.end(), queue_.front().path) != running_.end()) {
    return false;  // the same file must be written in the order posted
  }
  Job job = std::move(queue_.front());
  queue_.pop_front();
  if (error_) {
    changed_.notify_all();  // a job failed: no other one starts
    return true;
  }
  running_.push_back(job.path);
  lock.unlock();
  const auto start = std::chrono::steady_clock::now();
  std::exception_ptr error;
  try {
    job.write();
  } catch (...) {
    error = std::current_exception();
  }
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  job.write = nullptr;  // what it wrote (e.g. a deep copy) is released on this thread, unlocked
  lock.lock();
  running_.erase(std::find(running_.begin(), running_.end(), job.path));
  if (error) {
    error_ = error;
  } else {
    done_.emplace_back(job.path, seconds.count());
  }
  changed_.notify_all();
  return true;
}

void BackgroundWriter::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    if (!this->runNext(lock)) {
      if (stop_ && queue_.empty()) {
        return;  // stopped, and nothing is left to write
      }
      changed_.wait(lock);
    }
  }
}

}  // namespace geolattice
