#pragma once
// Objective (Jaumann) stress update for a step: the stress and any tensor state are carried
// by the rotation R = (I - W/2)^-1 (I + W/2) of the spin increment W = skew(L) dt (Hughes &
// Winget 1980). R is exactly orthogonal, so a rigid rotation, however large its steps,
// leaves every invariant unchanged; to first order R s R^T = s + W s - s W, the Jaumann rate.
// Tensors are symmetric, Voigt [xx, yy, zz, xy, yz, zx] with tensor (not engineering) shear.
namespace pilempm::mpm {

struct Rotation {
    double R[3][3];
};

// W: the spin increment (skew, dimensionless).
inline Rotation rotation_of_spin(const double (&W)[3][3]) {
    // Cayley transform with A = W/2 and its axial vector a: R = I + 2 (A + A^2) / (1 + |a|^2).
    double A[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A[i][j] = 0.5 * W[i][j];
    const double a2 = A[2][1] * A[2][1] + A[0][2] * A[0][2] + A[1][0] * A[1][0];
    const double c = 2.0 / (1.0 + a2);
    Rotation r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double AA = 0.0;
            for (int k = 0; k < 3; ++k) AA += A[i][k] * A[k][j];
            r.R[i][j] = (i == j ? 1.0 : 0.0) + c * (A[i][j] + AA);
        }
    return r;
}

// t <- R t R^T.
inline void rotate_tensor(const Rotation& r, double* t) {
    const double S[3][3] = {{t[0], t[3], t[5]}, {t[3], t[1], t[4]}, {t[5], t[4], t[2]}};
    double RS[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) RS[i][j] = r.R[i][0] * S[0][j] + r.R[i][1] * S[1][j] + r.R[i][2] * S[2][j];
    auto out = [&](int i, int j) { return RS[i][0] * r.R[j][0] + RS[i][1] * r.R[j][1] + RS[i][2] * r.R[j][2]; };
    t[0] = out(0, 0);
    t[1] = out(1, 1);
    t[2] = out(2, 2);
    t[3] = out(0, 1);
    t[4] = out(1, 2);
    t[5] = out(0, 2);
}

// The same rotation for a plane spin (W_xy = w, the only component in 2D): R is the
// in-plane block [[r, q], [-q, r]] with R_zz = 1, r = (1 - a^2)/(1 + a^2), q = 2a/(1 + a^2),
// a = w/2; t <- R t R^T costs a third of the general product.
inline void rotate_tensor_in_plane(double w, double* t) {
    const double a = 0.5 * w, c = 2.0 / (1.0 + a * a);
    const double r = 1.0 - c * a * a, q = c * a;
    const double xx = t[0], yy = t[1], xy = t[3], yz = t[4], zx = t[5];
    t[0] = r * r * xx + 2.0 * r * q * xy + q * q * yy;
    t[1] = q * q * xx - 2.0 * r * q * xy + r * r * yy;
    t[3] = r * q * (yy - xx) + (r * r - q * q) * xy;
    t[5] = r * zx + q * yz;
    t[4] = r * yz - q * zx;
}

}  // namespace pilempm::mpm
