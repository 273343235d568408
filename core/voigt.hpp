#pragma once
// Stress and strain in Voigt order [xx, yy, zz, xy, yz, zx], tension positive, strains
// with engineering shear (gamma = 2 eps). In 2D, x is horizontal (r when axisymmetric),
// y is up, and zz is the out-of-plane component (theta-theta when axisymmetric).
namespace pilempm {

inline double mean_stress(const double* s) { return (s[0] + s[1] + s[2]) / 3.0; }  // tension +

}  // namespace pilempm
