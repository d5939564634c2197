#pragma once
// A fixed set of worker threads kept for the renderer's lifetime, so a frame
// starts no thread. run(work) calls work(worker) once on every worker
// (worker 0 is the calling thread) and returns when all have finished, with
// denormals flushed while the work runs (denormals.h). An exception thrown
// by the work on any worker reaches the caller of run, after every worker
// has finished (the first one thrown; the others are dropped).
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "common/function_ref.h"

namespace facet {

class ThreadPool {
 public:
  explicit ThreadPool(int threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int size() const { return size_; }
  void run(FunctionRef<void(int worker)> work);

 private:
  void loop(int worker);
  // work(worker) with denormals flushed; an exception is kept in failure_.
  void runOne(const FunctionRef<void(int)>& work, int worker);

  int size_;
  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  const FunctionRef<void(int)>* work_ = nullptr;
  unsigned long generation_ = 0;
  int running_ = 0;
  bool stop_ = false;
  std::exception_ptr failure_;
};

// Splits [0, n) into one contiguous range per worker: work(begin, end, worker).
void forEachRange(ThreadPool& pool, std::size_t n, FunctionRef<void(std::size_t, std::size_t, int)> work);

}  // namespace facet
