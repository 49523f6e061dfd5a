// WorkerPool (vissort/worker_pool.h): a generation counter under one mutex; workers sleep on a
// condition variable between runs. A second mutex lets one run at a time through, so that
// oracles on several threads can share the pool; growing takes it too, so a worker never joins
// in the middle of a run.

#include "vissort/worker_pool.h"

#include <atomic>
#include <cassert>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace vissort {

struct WorkerPool::State {
    void work(uint32_t index, uint64_t seen);
    void grow(uint32_t threads);

    std::mutex run_mutex; // held for a whole run, and while growing
    std::vector<std::thread> threads;
    std::mutex mutex; // guards what follows, up to thread_count
    std::condition_variable wake, done;
    uint64_t generation = 0; // bumped per run; workers wait for a new one
    uint32_t tasks = 0, pending = 0;
    void (*task)(void*, uint32_t) = nullptr;
    void* context = nullptr;
    bool stop = false;
    std::atomic<uint32_t> thread_count{1};
    std::atomic<uint64_t> runs{0};
};

// Under run_mutex: no run is in progress, so a new worker starts from the current generation.
void WorkerPool::State::grow(uint32_t count) {
    uint64_t seen;
    {
        std::lock_guard lock(mutex);
        seen = generation;
    }
    threads.reserve(count - 1);
    for (uint32_t i = uint32_t(threads.size()) + 1; i < count; ++i)
        threads.emplace_back([this, i, seen] { work(i, seen); });
    thread_count.store(count, std::memory_order_release);
}

void WorkerPool::State::work(uint32_t index, uint64_t seen) {
    for (;;) {
        void (*task_now)(void*, uint32_t);
        void* context_now;
        {
            std::unique_lock lock(mutex);
            wake.wait(lock, [&] { return stop || generation != seen; });
            if (stop)
                return;
            seen = generation;
            if (index >= tasks)
                continue; // not needed this run
            task_now = task;
            context_now = context;
        }
        task_now(context_now, index);
        std::lock_guard lock(mutex);
        if (--pending == 0)
            done.notify_one();
    }
}

WorkerPool::WorkerPool(uint32_t threads) : state_(std::make_unique<State>()) {
    assert(threads >= 1);
    if (threads > 1)
        state_->grow(threads);
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard lock(state_->mutex);
        state_->stop = true;
    }
    state_->wake.notify_all();
    for (std::thread& t : state_->threads)
        t.join();
}

WorkerPool& WorkerPool::shared() {
    static WorkerPool pool(1);
    return pool;
}

uint32_t WorkerPool::threadCount() const {
    return state_->thread_count.load(std::memory_order_acquire);
}

void WorkerPool::reserve(uint32_t threads) {
    if (threads <= threadCount())
        return;
    std::lock_guard run_lock(state_->run_mutex);
    if (threads > state_->thread_count.load(std::memory_order_relaxed))
        state_->grow(threads);
}

uint64_t WorkerPool::runCount() const {
    return state_->runs.load(std::memory_order_relaxed);
}

void WorkerPool::run(uint32_t tasks, void (*task)(void*, uint32_t), void* context) {
    State& s = *state_;
    assert(tasks >= 1 && tasks <= threadCount());
    std::lock_guard run_lock(s.run_mutex);
    s.runs.fetch_add(1, std::memory_order_relaxed);
    if (tasks > 1) {
        {
            std::lock_guard lock(s.mutex);
            s.tasks = tasks;
            s.pending = tasks - 1;
            s.task = task;
            s.context = context;
            ++s.generation;
        }
        s.wake.notify_all();
    }
    task(context, 0);
    if (tasks > 1) {
        std::unique_lock lock(s.mutex);
        s.done.wait(lock, [&] { return s.pending == 0; });
    }
}

} // namespace vissort
