#pragma once
// A small persistent pool for FastCpuOracle's screen bands: threads started once, woken per pass,
// no allocation per pass. The calling thread runs task 0 itself.

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace vissort::detail {

class FastWorkerPool {
public:
    /// Starts workers - 1 threads (the caller is the other one).
    explicit FastWorkerPool(uint32_t workers);
    ~FastWorkerPool();
    FastWorkerPool(const FastWorkerPool&) = delete;
    FastWorkerPool& operator=(const FastWorkerPool&) = delete;

    /// Runs task(context, i) for i = 0..tasks-1 and returns when all are done: task 0 on the
    /// calling thread, task i on worker i - 1. tasks must be in [1, workers].
    void run(uint32_t tasks, void (*task)(void* context, uint32_t index), void* context);

private:
    void work(uint32_t index);

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    uint64_t generation_ = 0;  // bumped per run; workers wait for a new one
    uint32_t tasks_ = 0, pending_ = 0;
    void (*task_)(void*, uint32_t) = nullptr;
    void* context_ = nullptr;
    bool stop_ = false;
};

} // namespace vissort::detail
