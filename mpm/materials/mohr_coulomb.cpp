// Mohr-Coulomb with non-associated flow and a tension cut-off: return mapping in principal
// stress space.
//
// Why principal space: with isotropic linear elasticity the trial stress and the returned
// stress share their eigenvectors, so the return is a 3-component problem and the tensor is
// rebuilt with the trial eigenvectors. Every yield plane is linear in the principal stresses
// and the material is perfectly plastic, so the return onto any face, edge or corner is the
// closed-form solution of an n x n linear system (n = number of active planes, 1..3) whose
// matrix a_i . D b_j is a material constant (inverted once in the constructor).
//
// Planes, for sorted trial principal stresses s1 >= s2 >= s3 (tension positive):
//   0  MC main plane    (1+sin phi) s1 - (1-sin phi) s3 = 2c cos phi
//   1  MC plane s2-s3   meets 0 on the triaxial-compression edge (s1 = s2)
//   2  MC plane s1-s2   meets 0 on the triaxial-extension edge (s2 = s3)
//   3,4,5 tension       s1 = t, s2 = t, s3 = t
// Plastic flow: MC planes along b = grad of the plane with psi in place of phi; tension
// planes associated (b = a).
//
// Region choice: the return onto an active set is valid when all its plastic multipliers
// are >= 0 and the returned stress satisfies every criterion (the permutation-invariant
// ones, so a return that crossed an edge and changed the principal order is rejected).
// The sets are tried from the simplest (a face) to corners, as in Clausen, Damkilde &
// Andersen's multi-surface returns, so the first valid one is the answer:
//   no cut-off (t at or above the apex, or Tresca with t = inf):
//     face 0, compression edge {0,1}, extension edge {0,2}, else the apex (phi > 0)
//   cut-off below the apex:
//     face 0, face s1 = t, the two MC edges, the MC / s1 = t corner line, the s1 = s2 = t
//     line, the three corner points where the MC edges and lines meet the cut-off, and the
//     tension apex s1 = s2 = s3 = t.
// Only rounding at region boundaries can leave no valid set; then the closest admissible
// candidate in the complementary-energy norm is taken, and a radial scaling about the
// hydrostatic axis is the last resort, admissible by construction, so the update never
// leaves the elastic domain and never produces NaN.
#include "mpm/materials/mohr_coulomb.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace pilempm::mpm {

namespace {

using Vec3 = std::array<double, 3>;  // principal stresses, most tensile first
constexpr double kInf = std::numeric_limits<double>::infinity();

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

double max_abs(const Vec3& v) { return std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])}); }

Eigen::Matrix3d to_matrix(const double* s) {
    Eigen::Matrix3d m;
    m << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
    return m;
}

// The principal-space normal (1 + sin x) e_i - (1 - sin x) e_j of the MC plane on (i, j).
Vec3 mc_normal(int i, int j, double sin_x) {
    Vec3 n{0.0, 0.0, 0.0};
    n[i] = 1.0 + sin_x;
    n[j] = -(1.0 - sin_x);
    return n;
}

}  // namespace

MohrCoulomb::MohrCoulomb(double E, double nu, double phi_deg, double psi_deg, double c, double t)
    : E_(E), nu_(nu) {
    if (!(E > 0.0) || !(nu > -1.0 && nu < 0.5))
        throw std::invalid_argument("mohr_coulomb: E > 0, -1 < nu < 0.5");
    if (!(phi_deg >= 0.0 && phi_deg < 90.0) || !(psi_deg >= 0.0 && psi_deg <= phi_deg))
        throw std::invalid_argument("mohr_coulomb: 0 <= dilation angle <= friction angle < 90");
    if (!(c >= 0.0) || std::isinf(c) || (phi_deg == 0.0 && !(c > 0.0)))
        throw std::invalid_argument("mohr_coulomb: finite cohesion >= 0, and > 0 when phi = 0");
    if (std::isnan(t) || t == -kInf)
        throw std::invalid_argument("mohr_coulomb: tension cut-off must be a number or +inf");
    lambda_ = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    mu_ = E / (2.0 * (1.0 + nu));
    const double to_rad = std::numbers::pi / 180.0;
    sin_phi_ = std::sin(phi_deg * to_rad);
    cos_phi_ = std::cos(phi_deg * to_rad);
    sin_psi_ = std::sin(psi_deg * to_rad);
    apex_ = sin_phi_ > 0.0 ? c * cos_phi_ / sin_phi_ : kInf;
    t_ = std::min(t, apex_);
    // At (or above) the apex the cut-off is implied by the cone and only adds degenerate
    // corners, so it is switched off.
    tension_ = t_ < apex_;

    const int pairs[3][2] = {{0, 2}, {1, 2}, {0, 1}};
    for (int m = 0; m < 3; ++m) {
        a_[m] = mc_normal(pairs[m][0], pairs[m][1], sin_phi_);
        k_[m] = 2.0 * c * cos_phi_;
        const Vec3 b = mc_normal(pairs[m][0], pairs[m][1], sin_psi_);
        const double tr = b[0] + b[1] + b[2];
        for (int i = 0; i < 3; ++i) Db_[m][i] = lambda_ * tr + 2.0 * mu_ * b[i];
    }
    for (int m = 3; m < kPlanes; ++m) {
        a_[m] = {0.0, 0.0, 0.0};
        a_[m][m - 3] = 1.0;
        k_[m] = t_;
        for (int i = 0; i < 3; ++i) Db_[m][i] = lambda_ + (i == m - 3 ? 2.0 * mu_ : 0.0);
    }
    build_active_sets();
}

void MohrCoulomb::build_active_sets() {
    // Faces first, then edges, then corners: a trial whose face return is valid never
    // reaches an edge, and so on (the order of Clausen et al.'s region tests).
    add_active_set({0});
    if (tension_) add_active_set({3});
    add_active_set({0, 1});  // triaxial compression edge, s1 = s2
    add_active_set({0, 2});  // triaxial extension edge, s2 = s3
    if (tension_) {
        add_active_set({0, 3});     // MC plane / s1 cut-off
        add_active_set({3, 4});     // s1 = s2 = t
        add_active_set({0, 2, 3});  // extension edge meets the s1 cut-off
        // The compression edge meets s1 = s2 = t where four planes (0, 1, 3, 4) are active;
        // its region is the cone of their four flow directions, covered by the 3-subsets.
        add_active_set({0, 3, 4});
        add_active_set({0, 1, 3});
        add_active_set({1, 3, 4});
        add_active_set({0, 1, 4});
        add_active_set({3, 4, 5});  // s1 = s2 = s3 = t
    }
    // Without the cut-off the apex (phi > 0) is the remainder: see principal_return.
}

void MohrCoulomb::add_active_set(std::initializer_list<int> planes) {
    ActiveSet set;
    set.n = static_cast<int>(planes.size());
    std::copy(planes.begin(), planes.end(), set.planes.begin());
    Eigen::Matrix3d A = Eigen::Matrix3d::Identity(), N = Eigen::Matrix3d::Identity();
    Eigen::Vector3d k = Eigen::Vector3d::Zero();
    for (int i = 0; i < set.n; ++i) {
        const int pi = set.planes[i];
        for (int j = 0; j < set.n; ++j) A(i, j) = dot(a_[pi], Db_[set.planes[j]]);
        for (int j = 0; j < 3; ++j) N(i, j) = a_[pi][j];
        k(i) = k_[pi];
    }
    const Eigen::Matrix3d Ainv = A.inverse();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) set.inverse[i][j] = Ainv(i, j);
    if (set.n == 3) {
        // The corner itself, solved once so that corner returns land on it exactly.
        const Eigen::Vector3d v = N.partialPivLu().solve(k);
        set.vertex = {v(0), v(1), v(2)};
    }
    sets_.push_back(set);
}

double MohrCoulomb::principal_yield(const Vec3& s) const {
    // Order-free form, so it also judges returns that changed the principal order.
    const double hi = std::max({s[0], s[1], s[2]}), lo = std::min({s[0], s[1], s[2]});
    const double f = (1.0 + sin_phi_) * hi - (1.0 - sin_phi_) * lo - k_[0];
    return tension_ ? std::max(f, hi - t_) : f;
}

// Return of the sorted trial onto one active set: multipliers from the constant inverse,
// then one step of iterative refinement so that the result lies on its planes to rounding
// of the result, not of the (possibly huge) trial. Returns the criterion at the result
// (<= 0 up to rounding: admissible) and writes the smallest multiplier to min_multiplier.
double MohrCoulomb::return_to_set(const ActiveSet& set, const Vec3& trial, Vec3& out,
                                  double& min_multiplier) const {
    // Multipliers that bring the active planes' values at `s` to zero.
    auto multipliers = [&](const Vec3& s) {
        Vec3 f{}, dl{};
        for (int i = 0; i < set.n; ++i) f[i] = dot(a_[set.planes[i]], s) - k_[set.planes[i]];
        for (int i = 0; i < set.n; ++i)
            for (int j = 0; j < set.n; ++j) dl[i] += set.inverse[i][j] * f[j];
        return dl;
    };
    auto apply = [&](const Vec3& dl) {
        for (int j = 0; j < set.n; ++j)
            for (int i = 0; i < 3; ++i) out[i] -= dl[j] * Db_[set.planes[j]][i];
    };
    const Vec3 dl = multipliers(trial);
    min_multiplier = *std::min_element(dl.begin(), dl.begin() + set.n);
    if (set.n == 3) {
        out = set.vertex;  // exact, whatever the size of the trial
    } else {
        out = trial;
        apply(dl);
        apply(multipliers(out));
    }
    return principal_yield(out);
}

// Complementary energy (s_trial - s) . C (s_trial - s): the distance the return minimises
// for associated flow, used to pick among fallback candidates.
double MohrCoulomb::energy_distance(const Vec3& trial, const Vec3& out) const {
    const Vec3 ds{trial[0] - out[0], trial[1] - out[1], trial[2] - out[2]};
    return dot(ds, plastic_strain(ds));
}

// The principal plastic strain C (s_trial - s) of a stress drop ds at fixed total strain.
std::array<double, 3> MohrCoulomb::plastic_strain(const Vec3& ds) const {
    const double tr = ds[0] + ds[1] + ds[2];
    Vec3 e;
    for (int i = 0; i < 3; ++i) e[i] = ((1.0 + nu_) * ds[i] - nu_ * tr) / E_;
    return e;
}

void MohrCoulomb::principal_return(const Vec3& trial, Vec3& out) const {
    const double stress_scale = k_[0] + (tension_ ? std::abs(t_) : 0.0);
    const double multiplier_tol = 1e-12 * (max_abs(trial) + stress_scale) / mu_;
    auto feasible_tol = [&](const Vec3& s) {
        return 1e-12 * (max_abs(s) + stress_scale) + 1e-15 * max_abs(trial);
    };
    Vec3 candidate;
    double min_multiplier = 0.0;
    for (const ActiveSet& set : sets_) {
        const double f = return_to_set(set, trial, candidate, min_multiplier);
        if (min_multiplier >= -multiplier_tol && f <= feasible_tol(candidate)) {
            out = candidate;
            return;
        }
    }
    // Beyond the faces and edges of the cone lies the apex region (the standard choice,
    // e.g. de Souza Neto et al. ch. 8). Testing it as a set would need the flow directions
    // of all six MC planes (hydrostatic trials), and with psi = 0 those are deviatoric and
    // cannot return a hydrostatic trial at all, so the apex is taken as the remainder. The
    // return map stays continuous: face and edge returns reach the apex on its boundary.
    if (!tension_ && sin_phi_ > 0.0) {
        out = {apex_, apex_, apex_};
        return;
    }
    // With the cut-off the sets cover principal space; only rounding on a region boundary
    // gets here, and the closest admissible candidate is then the natural pick.
    double best = kInf;
    for (const ActiveSet& set : sets_) {
        const double f = return_to_set(set, trial, candidate, min_multiplier);
        const double w = energy_distance(trial, candidate);
        if (f <= feasible_tol(candidate) && w < best) {
            best = w;
            out = candidate;
        }
    }
    if (best == kInf) radial_fallback(trial, out);
}

// Last resort, feasible by construction: move the mean stress down to the apex or cut-off
// if it is beyond, then scale the deviator about it until every criterion holds.
void MohrCoulomb::radial_fallback(const Vec3& trial, Vec3& out) const {
    const double p = std::min((trial[0] + trial[1] + trial[2]) / 3.0, std::min(apex_, t_));
    const Vec3 d{trial[0] - p, trial[1] - p, trial[2] - p};
    const double hi = std::max({d[0], d[1], d[2]}), lo = std::min({d[0], d[1], d[2]});
    double alpha = 1.0;
    const double g = (1.0 + sin_phi_) * hi - (1.0 - sin_phi_) * lo;  // >= 0 as hi >= lo
    const double room = std::max(0.0, k_[0] - 2.0 * sin_phi_ * p);
    if (g > room) alpha = room / g;
    if (tension_ && hi > 0.0 && p + alpha * hi > t_) alpha = std::max(0.0, (t_ - p) / hi);
    for (int i = 0; i < 3; ++i) out[i] = p + alpha * d[i];
}

// Equivalent plastic strain increment sqrt(2/3 de_p : de_p) of the full plastic strain
// (volumetric part included, so tension and apex flow count). de_p = C (s_trial - s) is
// independent of how the multipliers split at corners with more than three active planes.
double MohrCoulomb::plastic_strain_increment(const Vec3& trial, const Vec3& out) const {
    const Vec3 de = plastic_strain({trial[0] - out[0], trial[1] - out[1], trial[2] - out[2]});
    return std::sqrt(2.0 / 3.0 * dot(de, de));
}

void MohrCoulomb::initialise_state(const double*, double* state) const { state[0] = 0.0; }

double MohrCoulomb::yield_function(const double* stress) const {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(to_matrix(stress), Eigen::EigenvaluesOnly);
    const Eigen::Vector3d ev = es.eigenvalues();
    return principal_yield({ev(2), ev(1), ev(0)});
}

// Stresses well inside the domain (by a margin far above the error of the closed-form
// eigenvalues) are accepted without the iterative eigensolver.
bool MohrCoulomb::clearly_elastic(const Eigen::Matrix3d& m) const {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
    es.computeDirect(m, Eigen::EigenvaluesOnly);
    const Eigen::Vector3d ev = es.eigenvalues();
    const Vec3 s{ev(2), ev(1), ev(0)};
    if (!std::isfinite(s[0]) || !std::isfinite(s[2])) return false;
    return principal_yield(s) < -1e-6 * (max_abs(s) + k_[0]);
}

void MohrCoulomb::update(int count, const int* points, const double* de, double* stress,
                         double* state, int stride) const {
    for (int k = 0; k < count; ++k) {
        const int p = points[k];
        const double* e = de + 6 * p;
        double* s = stress + 6 * p;
        // Elastic predictor, written exactly as LinearElastic so the elastic range agrees
        // with it to the last bit.
        double trial[6];
        const double tr = lambda_ * (e[0] + e[1] + e[2]);
        trial[0] = s[0] + (tr + 2.0 * mu_ * e[0]);
        trial[1] = s[1] + (tr + 2.0 * mu_ * e[1]);
        trial[2] = s[2] + (tr + 2.0 * mu_ * e[2]);
        trial[3] = s[3] + mu_ * e[3];
        trial[4] = s[4] + mu_ * e[4];
        trial[5] = s[5] + mu_ * e[5];
        const Eigen::Matrix3d m = to_matrix(trial);
        if (!clearly_elastic(m)) {
            double eps_p = 0.0;
            plastic_corrector(m, trial, eps_p);
            state[static_cast<std::size_t>(stride) * p] += eps_p;
        }
        std::copy(trial, trial + 6, s);
    }
}

// Spectral decomposition, principal return, rebuild with the trial eigenvectors. Leaves
// `voigt` untouched when the accurate eigenvalues show the trial is admissible.
void MohrCoulomb::plastic_corrector(const Eigen::Matrix3d& m, double* voigt, double& eps_p) const {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(m);
    const Eigen::Vector3d ev = es.eigenvalues();  // ascending
    const Vec3 trial{ev(2), ev(1), ev(0)};         // s1 >= s2 >= s3
    if (principal_yield(trial) <= 0.0) return;
    Vec3 out;
    principal_return(trial, out);
    eps_p = plastic_strain_increment(trial, out);
    const Eigen::Matrix3d& V = es.eigenvectors();
    Eigen::Matrix3d r = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 3; ++i) r += out[i] * V.col(2 - i) * V.col(2 - i).transpose();
    voigt[0] = r(0, 0);
    voigt[1] = r(1, 1);
    voigt[2] = r(2, 2);
    voigt[3] = r(0, 1);
    voigt[4] = r(1, 2);
    voigt[5] = r(0, 2);
}

}  // namespace pilempm::mpm
