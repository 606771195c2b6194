#pragma once
// Exact reference signs in GMP integers, written independently of the predicates module: every
// double is m * 2^e with an integer m, so the coordinates of one call, scaled by the same power
// of two, are integers and the determinants are evaluated by plain cofactor expansion in mpz.
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>

namespace tubemesh::predicates::test {

// The coordinates of one call on a common integer scale. Holds up to 5 points; reuses its mpz
// storage between calls (the 10^6-case loops would otherwise spend most of their time in malloc).
class ScaledPoints {
public:
    // Scales the 3 coordinates of up to 5 points.
    void set(std::span<const double* const> points) {
        n_ = static_cast<int>(points.size());
        int emin = 0;
        bool any = false;
        std::int64_t mant[5][3];
        int expo[5][3];
        for (int p = 0; p < n_; ++p)
            for (int k = 0; k < 3; ++k) {
                const double x = points[p][k];
                int e = 0;
                const double f = std::frexp(x, &e);
                mant[p][k] = static_cast<std::int64_t>(std::ldexp(f, 53));
                expo[p][k] = e - 53;
                if (x != 0) {
                    emin = any ? std::min(emin, expo[p][k]) : expo[p][k];
                    any = true;
                }
            }
        for (int p = 0; p < n_; ++p)
            for (int k = 0; k < 3; ++k) {
                mpz_class& v = v_[p][k];
                v = static_cast<long>(mant[p][k]);
                if (mant[p][k] != 0)
                    mpz_mul_2exp(v.get_mpz_t(), v.get_mpz_t(), static_cast<unsigned long>(expo[p][k] - emin));
            }
    }
    const mpz_class& operator()(int p, int k) const { return v_[p][k]; }

private:
    mpz_class v_[5][3];
    int n_ = 0;
};

inline int sign_of(const mpz_class& v) {
    return mpz_sgn(v.get_mpz_t()) > 0 ? 1 : (mpz_sgn(v.get_mpz_t()) < 0 ? -1 : 0);
}

// Reference orient3d and insphere. Not thread-safe: the mpz storage is reused between calls.
class Reference {
public:
    // sign det[b-a, c-a, d-a]
    int orient3d(const double* a, const double* b, const double* c, const double* d) {
        const double* pts[4] = {a, b, c, d};
        s_.set(pts);
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) m_[r][k] = s_(r + 1, k) - s_(0, k);
        det3(0, 1, 2, {0, 1, 2}, det_);
        return sign_of(det_);
    }

    // -sign det4[[p - e, |p - e|^2]] for p = a, b, c, d (positive: e inside the sphere of the
    // positive tet abcd), by cofactor expansion along the first row.
    int insphere(const double* a, const double* b, const double* c, const double* d, const double* e) {
        const double* pts[5] = {a, b, c, d, e};
        s_.set(pts);
        for (int r = 0; r < 4; ++r) {
            m_[r][3] = 0;
            for (int k = 0; k < 3; ++k) {
                m_[r][k] = s_(r, k) - s_(4, k);
                m_[r][3] += m_[r][k] * m_[r][k];
            }
        }
        det_ = 0;
        for (int j = 0; j < 4; ++j) {
            std::array<int, 3> columns{};
            for (int c = 0, cc = 0; c < 4; ++c)
                if (c != j) columns[cc++] = c;
            det3(1, 2, 3, columns, minor_);
            if (j % 2 == 0)
                det_ += m_[0][j] * minor_;
            else
                det_ -= m_[0][j] * minor_;
        }
        return -sign_of(det_);
    }

    // sign det[b-a, c-a] in the coordinate plane (i, j)
    int orient2d(const double* a, const double* b, const double* c, int i, int j) {
        const double* pts[3] = {a, b, c};
        s_.set(pts);
        const mpz_class det =
            (s_(1, i) - s_(0, i)) * (s_(2, j) - s_(0, j)) - (s_(1, j) - s_(0, j)) * (s_(2, i) - s_(0, i));
        return sign_of(det);
    }

private:
    // det of rows r0, r1, r2 of m_ restricted to `col`, by cofactors along the first row.
    void det3(int r0, int r1, int r2, std::array<int, 3> col, mpz_class& out) {
        const auto& [c0, c1, c2] = col;
        t_ = m_[r1][c1] * m_[r2][c2];
        t_ -= m_[r1][c2] * m_[r2][c1];
        out = m_[r0][c0] * t_;
        t_ = m_[r1][c0] * m_[r2][c2];
        t_ -= m_[r1][c2] * m_[r2][c0];
        out -= m_[r0][c1] * t_;
        t_ = m_[r1][c0] * m_[r2][c1];
        t_ -= m_[r1][c1] * m_[r2][c0];
        out += m_[r0][c2] * t_;
    }

    ScaledPoints s_;
    mpz_class m_[4][4], t_, minor_, det_;
};

}  // namespace tubemesh::predicates::test
