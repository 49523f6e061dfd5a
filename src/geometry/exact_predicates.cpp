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
//   lo = fma(p, z, -hi) is the exact remainder (fma rounds once, and the remainder, a multiple
//   of 2^-447 of at most 19 significant bits, is representable), so hi + lo == p * z exactly.

#include "geometry/exact_predicates.h"

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

inline int signOf(double value) {
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
        if (xy == 0 || z == 0)
            continue; // frequent on axis-aligned or integer inputs; saves the fma
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

// The filter on rounded differences: det[u, v, w] = u . (v x w), computed as the expansion
// along u, each minor of v and w rounded. This is Shewchuk's stage-A expression up to the order
// of rows and columns (a 3x3 determinant of the same nine rounded differences expanded along one
// line), so the same bound holds with the matching permanent. v x w and its permanent parts are
// shared by every u tested against the same pair.
struct Minors {
    double cross[3];     // v x w, each component rounded
    double magnitude[3]; // the sum of the two products' magnitudes behind each component
};

inline Minors minorsOf(const double v[3], const double w[3]) {
    Minors m;
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        const double left = v[i] * w[j], right = v[j] * w[i];
        m.cross[k] = left - right;
        m.magnitude[k] = std::fabs(left) + std::fabs(right);
    }
    return m;
}

// The sign of u . (v x w), or kUndecided when the filter cannot tell.
constexpr int kUndecided = 2;

inline int filteredSign(const double u[3], const Minors& m) {
    const double det = u[0] * m.cross[0] + u[1] * m.cross[1] + u[2] * m.cross[2];
    const double permanent = std::fabs(u[0]) * m.magnitude[0] + std::fabs(u[1]) * m.magnitude[1] +
                             std::fabs(u[2]) * m.magnitude[2];
    if (std::fabs(det) > kOrient3dBound * permanent)
        return signOf(det);
    // Without underflow a zero permanent means every product of the expansion is exactly zero
    // (a rounded difference is zero only when the exact one is): common for axis-aligned faces.
    return permanent == 0 ? 0 : kUndecided;
}

inline void difference(const float p[3], const float origin[3], double out[3]) {
    for (int k = 0; k < 3; ++k)
        out[k] = double(p[k]) - double(origin[k]);
}

} // namespace

int orient3d(const float a[3], const float b[3], const float c[3], const float d[3]) {
    // det[b - a, c - a, d - a] = (d - a) . ((b - a) x (c - a)).
    double u[3], v[3], w[3];
    difference(b, a, u);
    difference(c, a, v);
    difference(d, a, w);
    const int sign = filteredSign(w, minorsOf(u, v));
    return sign != kUndecided ? sign : orient3dExact(a, b, c, d);
}

void orient3dPlaneSides(const float a[3], const float b[3], const float c[3], const float* d0,
                        const float* d1, const float* d2, int sides[3]) {
    double u[3], v[3];
    difference(b, a, u);
    difference(c, a, v);
    const Minors plane = minorsOf(u, v);
    const float* const d[3] = {d0, d1, d2};
    for (int i = 0; i < 3; ++i) {
        double w[3];
        difference(d[i], a, w);
        const int sign = filteredSign(w, plane);
        sides[i] = sign != kUndecided ? sign : orient3dExact(a, b, c, d[i]);
    }
}

void orient3dEdgeSides(const float p[3], const float q[3], const float* t0, const float* t1,
                       const float* t2, int sides[3]) {
    // det[q - p, t_i - p, t_j - p] = (q - p) . ((t_i - p) x (t_j - p)).
    const float* const t[3] = {t0, t1, t2};
    double u[3], corner[3][3];
    difference(q, p, u);
    for (int i = 0; i < 3; ++i)
        difference(t[i], p, corner[i]);
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const int sign = filteredSign(u, minorsOf(corner[i], corner[j]));
        sides[i] = sign != kUndecided ? sign : orient3dExact(p, q, t[i], t[j]);
    }
}

int orient2d(const float a[2], const float b[2], const float c[2]) {
    const double left = (double(b[0]) - double(a[0])) * (double(c[1]) - double(a[1]));
    const double right = (double(b[1]) - double(a[1])) * (double(c[0]) - double(a[0]));
    const double det = left - right;
    // Shewchuk's bound with |left| + |right| as the permanent; when the products have opposite
    // signs (no cancellation) it holds a fortiori. Zero when both products are exactly zero.
    const double permanent = std::fabs(left) + std::fabs(right);
    if (std::fabs(det) > kOrient2dBound * permanent)
        return signOf(det);
    if (permanent == 0)
        return 0;
    return orient2dExact(a, b, c);
}

} // namespace vissort::detail
