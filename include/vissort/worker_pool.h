#pragma once
// A small persistent thread pool for pass-level work (CpuOracle's screen bands): threads
// started once, woken per run, no allocation per run. The calling thread runs task 0 itself.
// One pool per process is the intent: WorkerPool::shared() is the one every oracle uses unless
// its caller passes its own (CpuOracleOptions::pool), so that one oracle per view direction
// does not multiply threads. Standard library only.
//
// Layer: vissort::core (the package's `order` component; docs/architecture.md).

#include <cstdint>
#include <memory>

namespace vissort {

class WorkerPool {
public:
    /// Starts threads - 1 worker threads (the caller of run is the other one). threads >= 1.
    explicit WorkerPool(uint32_t threads);
    /// Joins the workers. No run may be in progress.
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    /// The process-wide pool: created on first use with 1 thread (no worker), grown by reserve;
    /// its workers are joined at exit.
    static WorkerPool& shared();

    /// Threads a run may use, the calling thread included (at least 1; never decreases).
    uint32_t threadCount() const;
    /// Grows the pool to at least threads threads (the calling thread included). Waits for a run
    /// in progress to end; must not be called from inside a task of this pool.
    void reserve(uint32_t threads);

    /// Runs task(context, i) for i = 0..tasks-1 and returns when all are done: task 0 on the
    /// calling thread, task i on worker i - 1. tasks must be in [1, threadCount()].
    /// Thread-safe: runs from several threads at once take turns (one run at a time). Must not
    /// be called from inside a task of this pool (it would wait for itself).
    void run(uint32_t tasks, void (*task)(void* context, uint32_t index), void* context);

    /// Runs so far (every call of run, those of one task included): for tests and benchmarks.
    uint64_t runCount() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace vissort
