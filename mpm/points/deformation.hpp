#pragma once
// The determinant J of a point's deformation gradient (D x D, row-major).
namespace pilempm::mpm {

template <int D>
inline double determinant(const double* F) {
    if constexpr (D == 2) return F[0] * F[3] - F[1] * F[2];
    else
        return F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
}

}  // namespace pilempm::mpm
