#pragma once
// Vis-sort in one dimension: Govindaraju, Henson, Lin, Manocha, "Interactive Visibility Ordering
// and Transparency Computations among Geometric Primitives in Complex Environments", I3D 2005,
// Algorithm 3.1. A sort that only ever compares an element with the running minimum of a subset,
// which is what an occlusion query can do in 3D (vis_sort.h). Linear on nearly sorted input.
//
// Layer: vissort::core (the package's `order` component; docs/architecture.md).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace vissort {

/// The state after one iteration (pass 1 + pass 2), for tracing the algorithm.
template <class T> struct VisSort1dStep {
    std::vector<T> monotone_run; // M after pass 1, front to back
    std::vector<T> sorted;       // S after pass 2
    std::vector<T> unsorted;     // I after pass 2
};

template <class T> struct VisSort1dResult {
    std::vector<T> sorted;
    uint64_t comparisons = 0; // calls to the strict weak order
    uint32_t iterations = 0;
    std::vector<VisSort1dStep<T>> trace; // filled when requested
};

/// Sorts input ascending with Vis-sort, comparing elements only against running minima.
/// less must be a strict weak order; x <= min is evaluated as !less(min, x). The first element a
/// pass meets is compared with nothing (the running minimum starts at +infinity).
/// Set keep_trace to record every iteration's M, S and I.
template <class T, class Less>
VisSort1dResult<T> visSort1d(std::span<const T> input, Less less, bool keep_trace = false) {
    VisSort1dResult<T> result;
    std::vector<T> unsorted(input.begin(), input.end());
    std::vector<uint8_t> in_monotone_run(unsorted.size(), 0); // M, persistent across iterations
    auto counted_less = [&](const T& a, const T& b) {
        ++result.comparisons;
        return less(a, b);
    };

    while (!unsorted.empty()) {
        ++result.iterations;
        // Pass 1, back to front: x joins M if x <= the minimum of everything after it.
        const T* running_min = nullptr;
        for (std::size_t i = unsorted.size(); i-- > 0;) {
            const T& x = unsorted[i];
            if (!in_monotone_run[i] && (!running_min || !counted_less(*running_min, x)))
                in_monotone_run[i] = 1;
            if (!running_min || counted_less(x, *running_min))
                running_min = &x;
        }
        if (keep_trace) {
            VisSort1dStep<T> step;
            for (std::size_t i = 0; i < unsorted.size(); ++i)
                if (in_monotone_run[i])
                    step.monotone_run.push_back(unsorted[i]);
            result.trace.push_back(std::move(step));
        }
        // Pass 2, front to back: x in M moves to S if x <= the minimum of the unsorted elements
        // before it; everything after it is >= x already, because x is in M.
        std::vector<T> still_unsorted;
        std::vector<uint8_t> still_in_run;
        std::size_t min_index = SIZE_MAX; // index into still_unsorted
        for (std::size_t i = 0; i < unsorted.size(); ++i) {
            const T& x = unsorted[i];
            if (in_monotone_run[i] &&
                (min_index == SIZE_MAX || !counted_less(still_unsorted[min_index], x))) {
                result.sorted.push_back(x);
                continue;
            }
            still_unsorted.push_back(x);
            still_in_run.push_back(in_monotone_run[i]);
            if (min_index == SIZE_MAX || counted_less(x, still_unsorted[min_index]))
                min_index = still_unsorted.size() - 1;
        }
        unsorted = std::move(still_unsorted);
        in_monotone_run = std::move(still_in_run);
        if (keep_trace) {
            result.trace.back().sorted = result.sorted;
            result.trace.back().unsorted = unsorted;
        }
    }
    return result;
}

} // namespace vissort
