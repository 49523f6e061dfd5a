#include "vissort/vis_sort_1d.h"

#include <algorithm>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace vissort {
namespace {

std::vector<int> longestNonDecreasingLength(const std::vector<int>& v) {
    // Patience sorting: the length of the longest non-decreasing subsequence.
    std::vector<int> tails;
    for (int x : v) {
        auto it = std::upper_bound(tails.begin(), tails.end(), x);
        if (it == tails.end())
            tails.push_back(x);
        else
            *it = x;
    }
    return tails;
}

// Elements out of place: the fewest that must move for the rest to be sorted.
std::size_t outOfPlace(const std::vector<int>& v) {
    return v.size() - longestNonDecreasingLength(v).size();
}

TEST(VisSort1d, ReproducesThePapersTable1Trace) {
    const std::vector<int> input{1, 3, 2, 4};
    const auto result = visSort1d<int>(input, std::less<int>(), true);
    ASSERT_EQ(result.trace.size(), 2u);
    EXPECT_EQ(result.trace[0].monotone_run, (std::vector<int>{1, 2, 4}));
    EXPECT_EQ(result.trace[0].sorted, (std::vector<int>{1, 2}));
    EXPECT_EQ(result.trace[0].unsorted, (std::vector<int>{3, 4}));
    EXPECT_EQ(result.trace[1].monotone_run, (std::vector<int>{3, 4}));
    EXPECT_EQ(result.trace[1].sorted, (std::vector<int>{1, 2, 3, 4}));
    EXPECT_TRUE(result.trace[1].unsorted.empty());
    EXPECT_EQ(result.iterations, 2u);
}

TEST(VisSort1d, EmptyAndSingle) {
    const std::vector<int> empty;
    EXPECT_TRUE(visSort1d<int>(empty, std::less<int>()).sorted.empty());
    const std::vector<int> one{7};
    const auto r = visSort1d<int>(one, std::less<int>());
    EXPECT_EQ(r.sorted, one);
    EXPECT_EQ(r.comparisons, 0u);
}

TEST(VisSort1d, SortsRandomInputWithDuplicatesStably) {
    std::mt19937 rng(5);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<std::pair<int, int>> v(rng() % 60);
        for (std::size_t i = 0; i < v.size(); ++i)
            v[i] = {int(rng() % 10), int(i)};
        auto by_key = [](const auto& a, const auto& b) { return a.first < b.first; };
        const auto r = visSort1d<std::pair<int, int>>(v, by_key);
        auto expected = v;
        std::stable_sort(expected.begin(), expected.end(), by_key);
        // Equal keys keep no particular order in Vis-sort; compare keys and the multiset.
        ASSERT_EQ(r.sorted.size(), v.size());
        for (std::size_t i = 0; i < v.size(); ++i)
            ASSERT_EQ(r.sorted[i].first, expected[i].first);
        auto a = r.sorted, b = v;
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        ASSERT_EQ(a, b);
    }
}

TEST(VisSort1d, SortedInputTakesOneIterationAndFewerThan2nComparisons) {
    std::vector<int> v(1000);
    for (int i = 0; i < 1000; ++i)
        v[i] = i;
    const auto r = visSort1d<int>(v, std::less<int>());
    EXPECT_EQ(r.sorted, v);
    EXPECT_EQ(r.iterations, 1u);
    EXPECT_LE(r.comparisons, 2u * v.size());
}

TEST(VisSort1d, NearlySortedInputStaysWithinThe4kPlus2nBound) {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 300; ++trial) {
        const int n = 50 + int(rng() % 500);
        std::vector<int> v(n);
        for (int i = 0; i < n; ++i)
            v[i] = i;
        // Move a few elements to random places.
        const int moves = int(rng() % 8);
        for (int m = 0; m < moves; ++m) {
            const int from = int(rng() % n), to = int(rng() % n);
            const int x = v[from];
            v.erase(v.begin() + from);
            v.insert(v.begin() + to, x);
        }
        const std::size_t k = outOfPlace(v);
        const auto r = visSort1d<int>(v, std::less<int>());
        std::vector<int> expected = v;
        std::sort(expected.begin(), expected.end());
        ASSERT_EQ(r.sorted, expected);
        ASSERT_LE(r.comparisons, (4 * k + 2) * std::size_t(n)) << "k=" << k << " n=" << n;
    }
}

TEST(VisSort1d, ReverseSortedInputIsStillSorted) {
    std::vector<int> v(300);
    for (int i = 0; i < 300; ++i)
        v[i] = 300 - i;
    const auto r = visSort1d<int>(v, std::less<int>());
    EXPECT_TRUE(std::is_sorted(r.sorted.begin(), r.sorted.end()));
    EXPECT_EQ(r.sorted.size(), v.size());
}

} // namespace
} // namespace vissort
