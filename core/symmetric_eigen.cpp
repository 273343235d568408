#include "core/symmetric_eigen.hpp"

#include <cmath>

namespace pilempm::core {

void symmetric_eigen3(const double* t, const double (*frame)[3], double d[3], double q[3][3]) {
    double a01, a02, a12;
    if (t[3] == 0.0 && t[4] == 0.0 && t[5] == 0.0) {
        d[0] = t[0];
        d[1] = t[1];
        d[2] = t[2];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) q[i][j] = i == j ? 1.0 : 0.0;
        return;
    }
    if (t[4] == 0.0 && t[5] == 0.0) {
        // A plane tensor (xy != 0): the in-plane pair in closed form, the rotation by its
        // half-angle's cosine and sine from cos 2a = (xx - yy) / (2 r), sin 2a = xy / r.
        const auto [mean, half, r] = plane_principal_pair(t);
        double c, sn;
        if (half >= 0.0) {
            c = std::sqrt(0.5 * (1.0 + half / r));
            sn = t[3] / (2.0 * r * c);
        } else {
            sn = std::copysign(std::sqrt(0.5 * (1.0 - half / r)), t[3]);
            c = t[3] / (2.0 * r * sn);
        }
        d[0] = mean + r;
        d[1] = mean - r;
        d[2] = t[2];
        q[0][0] = c, q[0][1] = sn, q[0][2] = 0.0;
        q[1][0] = -sn, q[1][1] = c, q[1][2] = 0.0;
        q[2][0] = 0.0, q[2][1] = 0.0, q[2][2] = 1.0;
        return;
    }
    if (frame) {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) q[i][j] = frame[i][j];
        double tq[3][3];  // t q_i
        for (int i = 0; i < 3; ++i) {
            const double* e = q[i];
            tq[i][0] = t[0] * e[0] + t[3] * e[1] + t[5] * e[2];
            tq[i][1] = t[3] * e[0] + t[1] * e[1] + t[4] * e[2];
            tq[i][2] = t[5] * e[0] + t[4] * e[1] + t[2] * e[2];
        }
        auto dot = [](const double* x, const double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
        d[0] = dot(q[0], tq[0]);
        d[1] = dot(q[1], tq[1]);
        d[2] = dot(q[2], tq[2]);
        a01 = dot(q[0], tq[1]);
        a02 = dot(q[0], tq[2]);
        a12 = dot(q[1], tq[2]);
    } else {
        d[0] = t[0];
        d[1] = t[1];
        d[2] = t[2];
        a01 = t[3];
        a12 = t[4];
        a02 = t[5];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) q[i][j] = i == j ? 1.0 : 0.0;
    }
    // Rotation in the (p, r) plane annihilating a_pr; x, y: the other two entries of the
    // row/column of the third index k (a_kp, a_kr).
    auto rotate = [&](int p, int r, double& apr, double& x, double& y) {
        const double theta = (d[r] - d[p]) / (2.0 * apr);
        const double tt = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(tt * tt + 1.0), sn = tt * c;
        d[p] -= tt * apr;
        d[r] += tt * apr;
        apr = 0.0;
        const double xp = c * x - sn * y, yr = sn * x + c * y;
        x = xp;
        y = yr;
        for (int j = 0; j < 3; ++j) {
            const double qp = q[p][j], qr = q[r][j];
            q[p][j] = c * qp - sn * qr;
            q[r][j] = sn * qp + c * qr;
        }
    };
    for (int sweep = 0; sweep < 12; ++sweep) {
        const double eps = 1e-17 * (std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2]));
        const bool r01 = std::abs(a01) > eps, r02 = std::abs(a02) > eps, r12 = std::abs(a12) > eps;
        if (!r01 && !r02 && !r12) break;
        if (r01) rotate(0, 1, a01, a02, a12);  // k = 2: a_20, a_21
        if (std::abs(a02) > eps) rotate(0, 2, a02, a01, a12);  // k = 1: a_10, a_12
        if (std::abs(a12) > eps) rotate(1, 2, a12, a01, a02);  // k = 0: a_01, a_02
    }
}

// The least eigenvalue of a plane tensor (yz = zx = 0): the out-of-plane normal entry or
// the least of the in-plane pair, in closed form.
double plane_minor_principal(const double* t) {
    const double mean = 0.5 * (t[0] + t[1]), half = 0.5 * (t[0] - t[1]);
    return std::min(t[2], mean - std::sqrt(half * half + t[3] * t[3]));
}

}  // namespace pilempm::core
