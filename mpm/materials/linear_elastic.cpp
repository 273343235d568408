#include <stdexcept>

#include "mpm/materials/constitutive_model.hpp"

namespace pilempm::mpm {

LinearElastic::LinearElastic(double E, double nu) {
    if (!(E > 0.0) || !(nu > -1.0 && nu < 0.5)) throw std::invalid_argument("linear elastic: E > 0, -1 < nu < 0.5");
    lambda_ = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    mu_ = E / (2.0 * (1.0 + nu));
}

void LinearElastic::update(int count, const int* points, const double* de, double* stress, double*,
                           int) const {
    for (int k = 0; k < count; ++k) {
        const int p = points[k];
        const double* e = de + 6 * p;
        double* s = stress + 6 * p;
        const double tr = lambda_ * (e[0] + e[1] + e[2]);
        s[0] += tr + 2.0 * mu_ * e[0];
        s[1] += tr + 2.0 * mu_ * e[1];
        s[2] += tr + 2.0 * mu_ * e[2];
        s[3] += mu_ * e[3];  // engineering shear strain: tau = G gamma
        s[4] += mu_ * e[4];
        s[5] += mu_ * e[5];
    }
}

}  // namespace pilempm::mpm
