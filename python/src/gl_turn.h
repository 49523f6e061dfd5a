#pragma once
// OpenGL from Python threads: an EGL context is current on one thread at a time, and Python
// may call from any thread with the GIL released. Every use of the shared context takes a
// turn: one thread at a time, the context released from the thread when the turn ends, so the
// next caller (another thread) can make it current.

#include <memory>
#include <mutex>

#if VISSORT_WITH_GL
#include "vissort/gl_context.h"
#endif

namespace vissort::python {

#if VISSORT_WITH_GL
inline std::mutex& glMutex() {
    static std::mutex mutex;
    return mutex;
}

/// Holds the turn for its lifetime; no turn (and no lock) when context is null (no GL used).
/// Take it with the GIL released where the wait may be long (a call); destructors take it with
/// the GIL held, which cannot deadlock: a turn is never held while waiting for the GIL.
class GlTurn {
public:
    explicit GlTurn(std::shared_ptr<GlContext> context) : context_(std::move(context)) {
        if (context_)
            lock_ = std::unique_lock<std::mutex>(glMutex());
    }
    ~GlTurn() {
        if (context_)
            context_->releaseCurrent();
    }
    GlTurn(const GlTurn&) = delete;
    GlTurn& operator=(const GlTurn&) = delete;

private:
    std::shared_ptr<GlContext> context_;
    std::unique_lock<std::mutex> lock_;
};

/// The process's shared context (GlContext::shared, which makes it current on the calling
/// thread), obtained during a turn and released from this thread again.
inline Result<std::shared_ptr<GlContext>> sharedGlContext() {
    std::lock_guard<std::mutex> lock(glMutex());
    Result<std::shared_ptr<GlContext>> context = GlContext::shared();
    if (context)
        (*context.value)->releaseCurrent();
    return context;
}
#endif

} // namespace vissort::python
