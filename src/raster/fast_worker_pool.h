#pragma once
// The screen bands' pool is now vissort::WorkerPool (vissort/worker_pool.h, in vissort_core);
// this name remains for the collision detector until it moves to WorkerPool.

#include "vissort/worker_pool.h"

namespace vissort::detail {

using FastWorkerPool = WorkerPool;

} // namespace vissort::detail
