// FastWorkerPool (fast_worker_pool.h): a generation counter under one mutex; workers sleep on a
// condition variable between passes.

#include "raster/fast_worker_pool.h"

#include <cassert>

namespace vissort::detail {

FastWorkerPool::FastWorkerPool(uint32_t workers) {
    assert(workers >= 1);
    threads_.reserve(workers - 1);
    for (uint32_t i = 1; i < workers; ++i) threads_.emplace_back([this, i] { work(i); });
}

FastWorkerPool::~FastWorkerPool() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void FastWorkerPool::run(uint32_t tasks, void (*task)(void*, uint32_t), void* context) {
    assert(tasks >= 1 && tasks <= threads_.size() + 1);
    if (tasks > 1) {
        {
            std::lock_guard lock(mutex_);
            tasks_ = tasks;
            pending_ = tasks - 1;
            task_ = task;
            context_ = context;
            ++generation_;
        }
        wake_.notify_all();
    }
    task(context, 0);
    if (tasks > 1) {
        std::unique_lock lock(mutex_);
        done_.wait(lock, [&] { return pending_ == 0; });
    }
}

void FastWorkerPool::work(uint32_t index) {
    uint64_t seen = 0;
    for (;;) {
        void (*task)(void*, uint32_t);
        void* context;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
            if (stop_) return;
            seen = generation_;
            if (index >= tasks_) continue;  // not needed this run
            task = task_;
            context = context_;
        }
        task(context, index);
        std::lock_guard lock(mutex_);
        if (--pending_ == 0) done_.notify_one();
    }
}

} // namespace vissort::detail
