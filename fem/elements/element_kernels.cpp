#include "fem/elements/element_kernels.hpp"

#include "core/conventions.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pilempm::fem {

const char* element_kind_name(ElementKind kind) {
    switch (kind) {
        case ElementKind::Rod2: return "rod2";
        case ElementKind::AxisymQuad4: return "axisymmetric_quad4";
    }
    return "unknown";
}

double LinearElasticSteel::wave_speed() const { return std::sqrt(youngs_modulus / density); }

void rod2_operators(const double z[2], double area, const LinearElasticSteel& steel,
                    double* K, double* mass, double* stress_row) {
    const double L = z[1] - z[0];
    if (!(L > 0.0)) throw std::invalid_argument("rod element of non-positive length");
    const double k = steel.youngs_modulus * area / L;
    K[0] = k; K[1] = -k; K[2] = -k; K[3] = k;
    mass[0] = mass[1] = 0.5 * steel.density * area * L;
    stress_row[0] = -steel.youngs_modulus / L;
    stress_row[1] = steel.youngs_modulus / L;
}

void axisym_quad4_operators(const double rz[8], const LinearElasticSteel& steel, double* K,
                            double* mass, double* stress_row) {
    const double E = steel.youngs_modulus, nu = steel.poisson_ratio;
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    const double mu = E / (2 * (1 + nu));
    Eigen::Matrix4d D;
    D << lambda + 2 * mu, lambda, lambda, 0,
         lambda, lambda + 2 * mu, lambda, 0,
         lambda, lambda, lambda + 2 * mu, 0,
         0, 0, 0, mu;
    static constexpr double xi_n[4] = {-1, 1, 1, -1};
    static constexpr double eta_n[4] = {-1, -1, 1, 1};

    // Strain rows [e_r, e_z, e_theta, g_rz] at (xi, eta); returns r and det J.
    auto strain_matrix = [&](double xi, double eta, Eigen::Matrix<double, 4, 8>& B,
                             double& r, double& detJ, double N[4]) {
        double dN_dxi[4], dN_deta[4];
        for (int a = 0; a < 4; ++a) {
            N[a] = 0.25 * (1 + xi * xi_n[a]) * (1 + eta * eta_n[a]);
            dN_dxi[a] = 0.25 * xi_n[a] * (1 + eta * eta_n[a]);
            dN_deta[a] = 0.25 * eta_n[a] * (1 + xi * xi_n[a]);
        }
        Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
        r = 0.0;
        for (int a = 0; a < 4; ++a) {
            J(0, 0) += dN_dxi[a] * rz[2 * a];
            J(0, 1) += dN_dxi[a] * rz[2 * a + 1];
            J(1, 0) += dN_deta[a] * rz[2 * a];
            J(1, 1) += dN_deta[a] * rz[2 * a + 1];
            r += N[a] * rz[2 * a];
        }
        detJ = J.determinant();
        if (!(detJ > 0.0) || !(r > 0.0))
            throw std::invalid_argument("axisymmetric quad is inverted or touches the axis");
        const Eigen::Matrix2d Jinv = J.inverse();
        B.setZero();
        for (int a = 0; a < 4; ++a) {
            const double dN_dr = Jinv(0, 0) * dN_dxi[a] + Jinv(0, 1) * dN_deta[a];
            const double dN_dz = Jinv(1, 0) * dN_dxi[a] + Jinv(1, 1) * dN_deta[a];
            B(0, 2 * a) = dN_dr;
            B(1, 2 * a + 1) = dN_dz;
            B(2, 2 * a) = N[a] / r;
            B(3, 2 * a) = dN_dz;
            B(3, 2 * a + 1) = dN_dr;
        }
    };

    Eigen::Map<Eigen::Matrix<double, 8, 8, Eigen::RowMajor>> Ke(K);
    Ke.setZero();
    for (int a = 0; a < 4; ++a) mass[a] = 0.0;
    const double g = 1.0 / std::sqrt(3.0);
    Eigen::Matrix<double, 4, 8> B;
    double N[4], r, detJ;
    for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j) {
            strain_matrix(i ? g : -g, j ? g : -g, B, r, detJ, N);
            const double dV = full_ring(r) * detJ;  // the whole ring; Gauss weights are 1
            Ke.noalias() += B.transpose() * D * B * dV;
            // Row-sum lumping of the consistent mass: m_a = integral of rho N_a.
            for (int a = 0; a < 4; ++a) mass[a] += steel.density * N[a] * dV;
        }
    }
    strain_matrix(0.0, 0.0, B, r, detJ, N);
    const Eigen::Matrix<double, 1, 8> row = D.row(1) * B;
    for (int k = 0; k < 8; ++k) stress_row[k] = row(k);
}

double element_max_frequency(const double* K, const double* mass_per_dof, int ndof) {
    Eigen::MatrixXd A(ndof, ndof);
    for (int i = 0; i < ndof; ++i)
        for (int j = 0; j < ndof; ++j)
            A(i, j) = K[i * ndof + j] / std::sqrt(mass_per_dof[i] * mass_per_dof[j]);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A, Eigen::EigenvaluesOnly);
    return std::sqrt(std::max(0.0, eig.eigenvalues().maxCoeff()));
}

}  // namespace pilempm::fem
