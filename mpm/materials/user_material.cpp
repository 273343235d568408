#include "mpm/materials/user_material.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace pilempm::mpm {

namespace {

// pilempm's Voigt order is xx yy zz xy yz zx; Abaqus's is 11 22 33 12 13 23.
constexpr int kToAbaqus[6] = {0, 1, 2, 3, 5, 4};  // abaqus[kToAbaqus[i]] = ours[i]

void to_abaqus(const double* ours, double* abq) {
    for (int i = 0; i < 6; ++i) abq[kToAbaqus[i]] = ours[i];
}
void from_abaqus(const double* abq, double* ours) {
    for (int i = 0; i < 6; ++i) ours[i] = abq[kToAbaqus[i]];
}

constexpr int kMaxHalvings = 10;

}  // namespace

UserMaterial::UserMaterial(const UserMaterialParameters& p) : par_(p), nstatv_(p.state_variables) {
    if (nstatv_ < 0) throw std::invalid_argument("umat: state_variables >= 0");
    if (static_cast<int>(p.initial_state.size()) > nstatv_)
        throw std::invalid_argument("umat: more initial state values than state_variables");
    if (!(p.p_wave_modulus > 0.0) || !(p.shear_modulus > 0.0))
        throw std::invalid_argument("umat: p_wave_modulus and shear_modulus > 0");
    handle_ = dlopen(p.library.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) throw std::runtime_error("umat: cannot load " + p.library + ": " + dlerror());
    const std::vector<std::string> symbols = p.symbol.empty() ? std::vector<std::string>{"umat_", "umat", "UMAT"}
                                                               : std::vector<std::string>{p.symbol};
    for (const auto& s : symbols)
        if (void* f = dlsym(handle_, s.c_str())) {
            umat_ = reinterpret_cast<Function>(f);
            break;
        }
    if (!umat_) {
        dlclose(handle_);
        throw std::runtime_error("umat: " + p.library + " has no symbol " +
                                 (p.symbol.empty() ? std::string("umat_, umat or UMAT") : p.symbol));
    }
    for (int k = 0; k < nstatv_; ++k) names_.push_back("statev_" + std::to_string(k + 1));
    for (const char* c : {"11", "22", "33", "12", "13", "23"}) names_.push_back(std::string("umat_strain_") + c);
}

UserMaterial::~UserMaterial() {
    if (handle_) dlclose(handle_);
}

void UserMaterial::initialise_state(const double* /*stress*/, double* state) const {
    std::fill(state, state + num_state(), 0.0);
    std::copy(par_.initial_state.begin(), par_.initial_state.end(), state);
}

bool UserMaterial::call(int point, const double* dstran, double* stress, double* statev, double* stran) const {
    double ddsdde[36] = {}, sse = 0, spd = 0, scd = 0, rpl = 0, ddsddt[6] = {}, drplde[6] = {}, drpldt = 0;
    double time[2] = {time_, time_}, dtime = dt_, temp = 0, dtemp = 0, predef[1] = {0}, dpred[1] = {0};
    double coords[3] = {0, 0, 0}, pnewdt = 1.0, celent = 1.0;
    double eye[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, f0[9], f1[9];
    std::copy(eye, eye + 9, f0);
    std::copy(eye, eye + 9, f1);
    char cmname[80];
    std::memset(cmname, ' ', sizeof cmname);
    std::memcpy(cmname, par_.name.data(), std::min<std::size_t>(par_.name.size(), sizeof cmname));
    int ndi = 3, nshr = 3, ntens = 6, nstatv = nstatv_, nprops = static_cast<int>(par_.properties.size());
    int noel = point + 1, npt = 1, layer = 1, kspt = 1, kstep = 1, kinc = 1;
    double dstran_copy[6];
    std::copy(dstran, dstran + 6, dstran_copy);
    double* props = const_cast<double*>(par_.properties.data());  // read-only by the UMAT contract
    auto invoke = [&] {
        umat_(stress, statev, ddsdde, &sse, &spd, &scd, &rpl, ddsddt, drplde, &drpldt, stran, dstran_copy, time, &dtime,
              &temp, &dtemp, predef, dpred, cmname, &ndi, &nshr, &ntens, &nstatv, props, &nprops, coords, eye, &pnewdt,
              &celent, f0, f1, &noel, &npt, &layer, &kspt, &kstep, &kinc, sizeof cmname);
    };
    if (par_.thread_safe) {
        invoke();
    } else {
        std::lock_guard<std::mutex> lock(serial_);
        invoke();
    }
    return pnewdt >= 1.0;
}

// Tries the whole increment, then halves, quarters, ... while the UMAT asks for less.
void UserMaterial::update_point(int point, const double* dstrain, double* stress, double* state) const {
    thread_local std::vector<double> statev;
    double d[6], s_abq[6], stran[6];
    to_abaqus(dstrain, d);
    for (int level = 0, pieces = 1; level <= kMaxHalvings; ++level, pieces *= 2) {
        to_abaqus(stress, s_abq);
        statev.assign(state, state + nstatv_);
        std::copy(state + nstatv_, state + nstatv_ + 6, stran);
        double piece[6];
        for (int i = 0; i < 6; ++i) piece[i] = d[i] / pieces;
        bool accepted = true;
        for (int k = 0; k < pieces && accepted; ++k) {
            accepted = call(point, piece, s_abq, statev.data(), stran);
            for (int i = 0; i < 6 && accepted; ++i) stran[i] += piece[i];
        }
        if (!accepted) continue;
        from_abaqus(s_abq, stress);
        std::copy(statev.begin(), statev.end(), state);
        std::copy(stran, stran + 6, state + nstatv_);
        return;
    }
    throw std::runtime_error("umat: the UMAT refused the increment of point " + std::to_string(point) + " even in " +
                             std::to_string(1 << kMaxHalvings) + " pieces (PNEWDT < 1)");
}

void UserMaterial::update(int count, const int* points, const double* de, double* stress, double* state,
                          int stride) const {
    for (int k = 0; k < count; ++k) {
        const int idx = points[k];
        update_point(idx, de + 6 * idx, stress + 6 * idx, state + static_cast<std::size_t>(stride) * idx);
    }
}

}  // namespace pilempm::mpm
