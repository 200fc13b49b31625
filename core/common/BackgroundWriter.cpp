#include "common/BackgroundWriter.h"

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
  changed_.wait(lock, [this] { return queue_.empty() && !busy_; });
  if (error_) {
    std::rethrow_exception(error_);
  }
  return std::exchange(done_, {});
}

std::vector<std::pair<std::string, double>> BackgroundWriter::finished() {
  const std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(done_, {});
}

void BackgroundWriter::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return stop_ || !queue_.empty(); });
    if (queue_.empty()) {
      return;  // stopped, and nothing is left to write
    }
    Job job = std::move(queue_.front());
    queue_.pop_front();
    if (error_) {
      changed_.notify_all();  // a job before it failed: skipped, as if the run had stopped there
      continue;
    }
    busy_ = true;
    lock.unlock();
    const auto start = std::chrono::steady_clock::now();
    std::exception_ptr error;
    try {
      job.write();
    } catch (...) {
      error = std::current_exception();
    }
    const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    job.write = nullptr;  // what it wrote (e.g. a deep copy) is released here, unlocked
    lock.lock();
    busy_ = false;
    if (error) {
      error_ = error;
    } else {
      done_.emplace_back(job.path, seconds.count());
    }
    changed_.notify_all();
  }
}

}  // namespace geolattice
