// core::symmetric_eigen3 against tensors built from known eigenpairs: T = sum_i l_i v_i v_i^T
// with v_i the rows of a rotation, so the reference is independent of the solver. The plane
// closed form is checked in all four quadrants of Mohr's circle (the sign of (xx - yy) / 2
// picks its branch, the sign of xy the rotation's), the Jacobi sweeps from the Cartesian axes
// and from a nearby frame, as a constitutive update calls them.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/symmetric_eigen.hpp"

namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;

// Rotation about the unit axis n by angle a (Rodrigues); its rows are the eigenvectors.
Mat3 rotation(std::array<double, 3> n, double a) {
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n) x /= len;
    const double c = std::cos(a), s = std::sin(a), k = 1.0 - c;
    return {{{c + n[0] * n[0] * k, n[0] * n[1] * k - n[2] * s, n[0] * n[2] * k + n[1] * s},
             {n[1] * n[0] * k + n[2] * s, c + n[1] * n[1] * k, n[1] * n[2] * k - n[0] * s},
             {n[2] * n[0] * k - n[1] * s, n[2] * n[1] * k + n[0] * s, c + n[2] * n[2] * k}}};
}

// sum_i l_i v_i v_i^T in Voigt order [xx yy zz xy yz zx].
std::array<double, 6> tensor(const std::array<double, 3>& l, const Mat3& v) {
    auto entry = [&](int a, int b) { return l[0] * v[0][a] * v[0][b] + l[1] * v[1][a] * v[1][b] + l[2] * v[2][a] * v[2][b]; };
    return {entry(0, 0), entry(1, 1), entry(2, 2), entry(0, 1), entry(1, 2), entry(2, 0)};
}

// The computed pairs decompose t: t q_i = d_i q_i, q orthonormal, the eigenvalues those of
// the reference; where the reference's eigenvalues are well apart, each q_i is one of its
// eigenvectors too (|q_i . v_j| = 1: in a repeated eigenvalue's plane any basis is right).
void expect_decomposes(const std::array<double, 6>& t, const std::array<double, 3>& l, const Mat3& v,
                       const double (*frame)[3] = nullptr) {
    double d[3], q[3][3];
    pilempm::core::symmetric_eigen3(t.data(), frame, d, q);
    const double scale = std::max({std::abs(l[0]), std::abs(l[1]), std::abs(l[2])});
    std::array<double, 3> got = {d[0], d[1], d[2]}, want = l;
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 1e-13 * scale) << "eigenvalue " << i;
    const bool apart = want[1] - want[0] > 1e-6 * scale && want[2] - want[1] > 1e-6 * scale;
    for (int i = 0; i < 3; ++i) {
        const double* e = q[i];
        const double tq[3] = {t[0] * e[0] + t[3] * e[1] + t[5] * e[2], t[3] * e[0] + t[1] * e[1] + t[4] * e[2],
                              t[5] * e[0] + t[4] * e[1] + t[2] * e[2]};
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(tq[k], d[i] * e[k], 1e-13 * scale) << "t q_" << i << " - d q_" << i;
        for (int k = 0; k < 3; ++k) {
            const double dot = q[i][0] * q[k][0] + q[i][1] * q[k][1] + q[i][2] * q[k][2];
            EXPECT_NEAR(dot, i == k ? 1.0 : 0.0, 1e-13) << i << " . " << k;
        }
        if (!apart) continue;
        double best = 0.0;
        for (int j = 0; j < 3; ++j) best = std::max(best, std::abs(e[0] * v[j][0] + e[1] * v[j][1] + e[2] * v[j][2]));
        EXPECT_NEAR(best, 1.0, 1e-12) << "eigenvector " << i;
    }
}

}  // namespace

TEST(SymmetricEigen, APlaneTensorInEachQuadrantOfMohrsCircleIsSolvedInClosedForm) {
    const std::array<double, 3> l = {-120.0e3, -310.0e3, -205.0e3};  // stresses, tension +
    for (double deg : {10.0, 35.0, 44.9, 60.0, 95.0, 130.0, 170.0, -25.0, -80.0}) {
        const Mat3 v = rotation({0.0, 0.0, 1.0}, deg * std::numbers::pi / 180.0);
        const auto t = tensor(l, v);
        ASSERT_EQ(t[4], 0.0);
        ASSERT_EQ(t[5], 0.0);
        SCOPED_TRACE(deg);
        expect_decomposes(t, l, v);
        // The closed form orders the in-plane pair: the first the greater.
        double d[3], q[3][3];
        pilempm::core::symmetric_eigen3(t.data(), nullptr, d, q);
        EXPECT_GE(d[0], d[1]);
        EXPECT_EQ(d[2], t[2]);
        const auto p = pilempm::core::plane_principal_pair(t.data());
        EXPECT_NEAR(p.mean + p.radius, l[0], 1e-13 * 310.0e3);
        EXPECT_NEAR(p.mean - p.radius, l[1], 1e-13 * 310.0e3);
    }
}

TEST(SymmetricEigen, ADiagonalTensorKeepsItsEntriesExactly) {
    const std::array<double, 6> t = {-1.0, 3.5, 2.0e-9, 0.0, 0.0, 0.0};
    double d[3], q[3][3];
    pilempm::core::symmetric_eigen3(t.data(), nullptr, d, q);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(d[i], t[i]);
        for (int j = 0; j < 3; ++j) EXPECT_EQ(q[i][j], i == j ? 1.0 : 0.0);
    }
}

TEST(SymmetricEigen, AGeneralTensorIsSolvedFromTheAxesAndFromANearbyFrame) {
    const std::array<std::array<double, 3>, 4> spectra = {
        {{-50.0, -200.0, -125.0}, {3.0, -1.0, 7.5}, {-100.0, -100.0 * (1.0 + 1e-9), -40.0}, {1.0, 1.0, -2.0}}};
    for (const auto& l : spectra)
        for (const auto& [axis, angle] : std::array<std::pair<std::array<double, 3>, double>, 3>{
                 {{{1.0, 2.0, 3.0}, 0.7}, {{-0.3, 1.0, 0.2}, 2.1}, {{0.0, 1.0, 1.0}, -1.3}}}) {
            const Mat3 v = rotation(axis, angle);
            const auto t = tensor(l, v);
            SCOPED_TRACE(testing::Message() << l[0] << " " << l[1] << " " << l[2] << ", angle " << angle);
            expect_decomposes(t, l, v);
            // A frame from a nearby step: the eigenvectors turned by 0.01 rad.
            const Mat3 w = rotation({0.2, -0.5, 1.0}, 0.01);
            double frame[3][3];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) frame[i][j] = w[0][j] * v[i][0] + w[1][j] * v[i][1] + w[2][j] * v[i][2];
            expect_decomposes(t, l, v, frame);
        }
}
