#pragma once
// A cohesionless friction cone through the origin, Matsuoka-Nakai (I1 I2 / I3 = (9 - sin^2
// phi) / (1 - sin^2 phi)) or circular (Drucker-Prager matched in triaxial compression),
// written as q / p' = M(cos 3theta); and the return of a stress outside it back onto it at
// constant p' and Lode angle (an isochoric plastic potential g = q). The critical-state
// models use it for their critical state surface and for the cone that bounds their stress.
namespace pilempm::mpm {

struct FrictionCone {
    double M_c = 0.0;     // q / p' in triaxial compression (0: no cone)
    double k = 0.0;       // Matsuoka-Nakai's I1 I2 / I3
    double alpha4 = 1.0;  // (M_e / M_c)^4
    bool circular = false;

    static FrictionCone of_angle(double degrees, bool circular);
    bool exists() const { return M_c > 0.0; }
    // q / p' on the cone at c = cos 3theta (1: triaxial compression, -1: extension).
    double ratio_at(double cos3theta) const;
    // Brings a Voigt stress (tension positive, tensor shear) outside the cone onto it: the
    // deviator scaled at constant p' (at p' <= 0 a cohesionless point carries nothing, the
    // stress zeroed). Returns the tensor norm of the deviator removed (0: it was inside).
    double return_to(double* stress) const;
};

// cos 3theta of a Voigt stress, compression giving 1 (0 at q = 0).
double lode_cos3theta(const double* stress);

}  // namespace pilempm::mpm
