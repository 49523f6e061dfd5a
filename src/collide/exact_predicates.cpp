// Exact orientation predicates on float coordinates.
//
// This work is based on: Jonathan Richard Shewchuk. Adaptive Precision Floating-Point Arithmetic
// and Fast Robust Geometric Predicates. Discrete & Computational Geometry 18(3):305-363, 1997.
// From it come the stage-A error bounds of the filter, the two-sum and the grow-expansion with
// zero elimination; the exact stage here is simpler than the paper's adaptive stages B to D
// because the inputs are floats (below).
//
// Number formats. Inputs are IEEE binary32 (24-bit significands, exponents -149 .. 127), all
// arithmetic is IEEE binary64 (53-bit significands) rounded to nearest, and this file is
// compiled with -ffp-contract=off so that no a * b + c is fused behind our back: the filter's
// error bounds assume every operation is rounded on its own.
// - No overflow or underflow can occur: a float is 0 or of magnitude in [2^-149, 2^128), so a
//   nonzero difference of two floats is a multiple of 2^-149 below 2^129, a nonzero product of
//   three such numbers lies in [2^-447, 2^390), and every sum here has at most 48 such terms.
//   Double covers [2^-1022, 2^1024) with normal numbers, so each rounding is a relative one, as
//   the error analysis of the filter requires, and a computed product is 0 only when a factor is.
// - A product of two floats has at most 48 significant bits: exact in double.
// - A product of that with a third float has at most 72 bits: fl(p * z) = hi, and
//   lo = fma(p, z, -hi) is the exact remainder (fma rounds once, and the remainder fits in 53
//   bits above 2^-447), so hi + lo == p * z exactly.

#include "collide/exact_predicates.h"

#include <array>
#include <cmath>

namespace vissort::detail {
namespace {

// Half an ulp of 1.0 in double: the unit roundoff of round to nearest.
constexpr double kEpsilon = 0x1p-53;
// Shewchuk's stage-A bounds: |computed - exact| <= bound * permanent, the permanent being the
// same expression with every product replaced by its absolute value.
constexpr double kOrient2dBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr double kOrient3dBound = (7.0 + 56.0 * kEpsilon) * kEpsilon;

int signOf(double value) {
    return (value > 0) - (value < 0);
}

// sum + error == a + b exactly, for any a, b of round to nearest that do not overflow (Knuth).
inline void twoSum(double a, double b, double& sum, double& error) {
    sum = a + b;
    const double b_virtual = sum - a;
    const double a_virtual = sum - b_virtual;
    error = (a - a_virtual) + (b - b_virtual);
}

// A nonoverlapping expansion: components[0 .. size) are nonzero, ordered by increasing
// magnitude, and sum exactly to the represented value, so its sign is the sign of the last one.
template <int kCapacity> class Expansion {
public:
    // Shewchuk's GROW-EXPANSION with zero elimination: the length grows by at most one per
    // addition, so kCapacity additions always fit.
    void add(double value) {
        if (value == 0)
            return;
        int kept = 0;
        for (int i = 0; i < size_; ++i) {
            double error;
            twoSum(value, components_[i], value, error);
            if (error != 0)
                components_[kept++] = error;
        }
        if (value != 0)
            components_[kept++] = value;
        size_ = kept;
    }
    int sign() const { return size_ == 0 ? 0 : signOf(components_[size_ - 1]); }

private:
    std::array<double, kCapacity> components_;
    int size_ = 0;
};

// A signed monomial of a determinant whose first column is all ones: which row gives each of
// the other columns, and the sign of the permutation.
template <int kColumns> struct Monomial {
    std::array<int, kColumns> row{}; // row[0] gives the one
    int sign = 1;
};

// Every permutation of the rows (the Leibniz expansion), with its sign by counting inversions.
template <int kSize, int kCount> constexpr std::array<Monomial<kSize>, kCount> leibnizTerms() {
    std::array<Monomial<kSize>, kCount> terms{};
    std::array<int, kSize> perm{};
    for (int i = 0; i < kSize; ++i)
        perm[i] = i;
    for (int t = 0; t < kCount; ++t) {
        terms[t].row = perm;
        int inversions = 0;
        for (int i = 0; i < kSize; ++i)
            for (int j = i + 1; j < kSize; ++j)
                inversions += perm[i] > perm[j];
        terms[t].sign = inversions % 2 == 0 ? 1 : -1;
        // Next permutation in lexicographic order.
        int i = kSize - 2;
        while (i >= 0 && perm[i] >= perm[i + 1])
            --i;
        if (i < 0)
            break;
        int j = kSize - 1;
        while (perm[j] <= perm[i])
            --j;
        std::swap(perm[i], perm[j]);
        for (int l = i + 1, r = kSize - 1; l < r; ++l, --r)
            std::swap(perm[l], perm[r]);
    }
    return terms;
}

constexpr auto kTerms3 = leibnizTerms<3, 6>();
constexpr auto kTerms4 = leibnizTerms<4, 24>();

// det of the rows (1, p.x, p.y, p.z) for p = a, b, c, d, which equals det[b - a, c - a, d - a]
// (subtract the first row from the others and expand along the ones). Each of its 24 monomials
// is x * y * z of three distinct points: x * y exact in double, times z exact as hi + lo, and
// the 48 doubles summed without error.
int orient3dExact(const float a[3], const float b[3], const float c[3], const float d[3]) {
    const float* const points[4] = {a, b, c, d};
    Expansion<48> sum;
    for (const Monomial<4>& term : kTerms4) {
        const double xy = double(points[term.row[1]][0]) * double(points[term.row[2]][1]);
        const double z = term.sign * double(points[term.row[3]][2]);
        const double hi = xy * z;
        const double lo = std::fma(xy, z, -hi);
        sum.add(hi);
        sum.add(lo);
    }
    return sum.sign();
}

// det of the rows (1, p.x, p.y) for p = a, b, c, which equals det[b - a, c - a]: 6 products of
// two floats, each exact in double, summed without error.
int orient2dExact(const float a[2], const float b[2], const float c[2]) {
    const float* const points[3] = {a, b, c};
    Expansion<6> sum;
    for (const Monomial<3>& term : kTerms3)
        sum.add(term.sign * (double(points[term.row[1]][0]) * double(points[term.row[2]][1])));
    return sum.sign();
}

} // namespace

int orient3d(const float a[3], const float b[3], const float c[3], const float d[3]) {
    // u, v, w: the rows, each difference rounded once (the filter's bound accounts for it).
    const double ux = double(b[0]) - double(a[0]), uy = double(b[1]) - double(a[1]),
                 uz = double(b[2]) - double(a[2]);
    const double vx = double(c[0]) - double(a[0]), vy = double(c[1]) - double(a[1]),
                 vz = double(c[2]) - double(a[2]);
    const double wx = double(d[0]) - double(a[0]), wy = double(d[1]) - double(a[1]),
                 wz = double(d[2]) - double(a[2]);
    const double ux_vy = ux * vy, uy_vx = uy * vx;
    const double vx_wy = vx * wy, vy_wx = vy * wx;
    const double wx_uy = wx * uy, wy_ux = wy * ux;
    const double det = wz * (ux_vy - uy_vx) + uz * (vx_wy - vy_wx) + vz * (wx_uy - wy_ux);
    const double permanent = (std::fabs(ux_vy) + std::fabs(uy_vx)) * std::fabs(wz) +
                             (std::fabs(vx_wy) + std::fabs(vy_wx)) * std::fabs(uz) +
                             (std::fabs(wx_uy) + std::fabs(wy_ux)) * std::fabs(vz);
    const double bound = kOrient3dBound * permanent;
    if (det > bound)
        return 1;
    if (-det > bound)
        return -1;
    // Without underflow a zero permanent means every product of the expansion is exactly zero
    // (a rounded difference is zero only when the exact one is): common for axis-aligned faces.
    if (permanent == 0)
        return 0;
    return orient3dExact(a, b, c, d);
}

int orient2d(const float a[2], const float b[2], const float c[2]) {
    const double left = (double(b[0]) - double(a[0])) * (double(c[1]) - double(a[1]));
    const double right = (double(b[1]) - double(a[1])) * (double(c[0]) - double(a[0]));
    const double det = left - right;
    // Products of opposite signs (or a zero one) cannot cancel: the sign is the computed one.
    if ((left > 0 && right <= 0) || (left < 0 && right >= 0) || left == 0)
        return signOf(det);
    const double bound = kOrient2dBound * std::fabs(left + right);
    if (det > bound)
        return 1;
    if (-det > bound)
        return -1;
    return orient2dExact(a, b, c);
}

} // namespace vissort::detail
