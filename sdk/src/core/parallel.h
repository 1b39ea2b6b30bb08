// A small persistent worker pool: per-frame work is ~0.1-1 ms, too short to pay for spawning threads.
#pragma once
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace octocap::internal {

class WorkerPool {
 public:
  // threads = total threads including the caller; 0 = hardware concurrency, 1 = run inline.
  explicit WorkerPool(unsigned threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  unsigned threads() const { return static_cast<unsigned>(workers_.size()) + 1; }
  // Calls fn(i) for i in [0, n), spread over the pool; returns when all are done. fn must not throw.
  void parallel_for(size_t n, const std::function<void(size_t)>& fn);

 private:
  void worker_loop();
  void run_share();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(size_t)>* job_ = nullptr;
  size_t job_size_ = 0;
  size_t next_ = 0;
  size_t active_ = 0;
  unsigned long generation_ = 0;
  bool stop_ = false;
};

}  // namespace octocap::internal
