#include "common/thread_pool.h"

#include "common/denormals.h"

namespace facet {

ThreadPool::ThreadPool(int threads) : size_(threads < 1 ? 1 : threads) {
  for (int w = 1; w < size_; ++w) threads_.emplace_back([this, w] { loop(w); });
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  start_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void ThreadPool::runOne(const FunctionRef<void(int)>& work, int worker) {
  const FlushDenormals flush;
  try {
    work(worker);
  } catch (...) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!failure_) failure_ = std::current_exception();
  }
}

void ThreadPool::run(FunctionRef<void(int)> work) {
  if (size_ > 1) {
    std::lock_guard<std::mutex> lock(mutex_);
    work_ = &work;
    running_ = size_ - 1;
    ++generation_;
  }
  start_.notify_all();
  runOne(work, 0);
  std::exception_ptr failure;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return running_ == 0; });
    work_ = nullptr;
    failure = failure_;
    failure_ = nullptr;
  }
  if (failure) std::rethrow_exception(failure);
}

void ThreadPool::loop(int worker) {
  unsigned long seen = 0;
  for (;;) {
    const FunctionRef<void(int)>* work = nullptr;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      start_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
      work = work_;
    }
    runOne(*work, worker);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (--running_ == 0) done_.notify_one();
    }
  }
}

void forEachRange(ThreadPool& pool, std::size_t n, FunctionRef<void(std::size_t, std::size_t, int)> work) {
  const auto workers = static_cast<std::size_t>(pool.size());
  pool.run([&](int w) {
    const auto i = static_cast<std::size_t>(w);
    const std::size_t begin = n * i / workers, end = n * (i + 1) / workers;
    work(begin, end, w);  // an empty range too: phase 2 clears the worker's bins
  });
}

}  // namespace facet
