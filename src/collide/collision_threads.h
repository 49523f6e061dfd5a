#pragma once
// The threads a collider shares its per-object and per-pair work over: CollisionSettings::
// threads of CollisionSettings::pool (or the process's shared pool), each with its own scratch
// and results (a Worker), so that the threads never write to the same memory. Used by the
// vissort method and by the Bullet peer alike, so that both run on the same resources. Internal.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <thread>
#include <vector>

#include "vissort/collision.h"
#include "vissort/worker_pool.h"

namespace vissort::detail {

/// The thread count CollisionSettings::threads asks for: 0 is one per core.
inline uint32_t collisionThreadCount(const CollisionSettings& settings) {
    return settings.threads != 0 ? settings.threads
                                 : std::max(1u, std::thread::hardware_concurrency());
}

template <class Worker> class CollisionThreads {
public:
    explicit CollisionThreads(const CollisionSettings& settings)
        : threads_(collisionThreadCount(settings)), workers_(threads_) {
        if (threads_ > 1) {
            pool_ = settings.pool != nullptr ? settings.pool : &WorkerPool::shared();
            pool_->reserve(threads_);
            threads_ = std::min(threads_, pool_->threadCount());
        }
    }

    uint32_t count() const { return threads_; }
    /// One per thread; forEach hands thread i workers()[i].
    std::vector<Worker>& workers() { return workers_; }

    /// body(i, worker) for i = 0..count-1, items claimed one at a time by the threads (pairs
    /// differ widely in cost); on the calling thread alone when single-threaded or count < 2.
    template <class Body> void forEach(std::size_t count, Body&& body) {
        if (!pool_ || count < 2) {
            for (std::size_t i = 0; i < count; ++i)
                body(i, workers_[0]);
            return;
        }
        struct Context {
            Body* body;
            std::vector<Worker>* workers;
            std::size_t count;
            std::atomic<std::size_t> next{0};
        } context{&body, &workers_, count};
        pool_->run(
            uint32_t(std::min<std::size_t>(threads_, count)),
            [](void* c, uint32_t thread) {
                Context& context = *static_cast<Context*>(c);
                for (std::size_t i;
                     (i = context.next.fetch_add(1, std::memory_order_relaxed)) < context.count;)
                    (*context.body)(i, (*context.workers)[thread]);
            },
            &context);
    }

private:
    uint32_t threads_;
    std::vector<Worker> workers_; // never resized: a Worker need not be movable
    WorkerPool* pool_ = nullptr;  // the caller's or the shared one; null: single-threaded
};

} // namespace vissort::detail
