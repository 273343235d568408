#pragma once
// Pieces the solver's passes share across its translation units (mpm_solver.cpp, the
// pore water's mpm_solver_pore_water.cpp): not for use outside the solver.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "mpm/solver/mpm_solver.hpp"

namespace pilempm::mpm {

// Below this many points a step is too short to pay for waking threads.
constexpr long kParallelPoints = 4000;

// Coulomb wall on node velocity v (D values): if v moves into the wall, the normal part is
// stopped and the tangential part loses at most friction x that normal change.
template <int D>
inline void apply_wall(int wall, double friction, double* v) {
    const int axis = wall / 2;
    const bool min_side = wall % 2 == 0;  // the wall lies below (x_axis = min): v_axis >= 0
    const double vn = v[axis];
    if (min_side ? vn >= 0.0 : vn <= 0.0) return;  // separating: free
    v[axis] = 0.0;
    double vt2 = 0.0;
    for (int d = 0; d < D; ++d)
        if (d != axis) vt2 += v[d] * v[d];
    const double vt = std::sqrt(vt2), cap = friction * std::abs(vn);
    const double keep = vt > cap ? 1.0 - cap / vt : 0.0;  // slip, or stick
    for (int d = 0; d < D; ++d)
        if (d != axis) v[d] *= keep;
}


// Asks for the stencil of a point a few ahead: the passes after the scatter find the
// stencils in memory, not in cache, and would otherwise wait on each.
template <int D>
inline void prefetch_stencil(const std::vector<Stencil<D>>& stencils, long i) {
    constexpr long kAhead = 4;
    constexpr std::size_t kBytes = sizeof(typename Stencil<D>::Entry) * (D == 2 ? 9 : 27) + 64;  // a uGIMP stencil
    if (i + kAhead >= static_cast<long>(stencils.size())) return;
    const char* at = reinterpret_cast<const char*>(&stencils[i + kAhead]);
    for (std::size_t b = 0; b < kBytes; b += 64) __builtin_prefetch(at + b);
}

// Each chunk of points accumulates into its own buffer of `values` per stored node (all
// fields), over the slots its points reach only; then the buffers are summed into `out`:
// scatter without atomics, deterministic for a fixed thread count.
template <int D>
template <class Accumulate>
void MpmSolver<D>::scatter(int values, Accumulate&& accumulate, std::vector<double>& out) {
    const int chunks = static_cast<int>(chunk_blocks_.size() / 2);
    const std::size_t per_slot = static_cast<std::size_t>(values) * Grid<D>::kBlockNodes;
    const std::size_t size = per_slot * m_.grid.active_blocks();
    thread_buffer_.resize(chunks);
#pragma omp parallel for schedule(static, 1) num_threads(chunks)
    for (int chunk = 0; chunk < chunks; ++chunk) {
        auto& buf = thread_buffer_[chunk];
        const int first = chunk_blocks_[2 * chunk], last = chunk_blocks_[2 * chunk + 1];
        if (first < 0) {
            buf.clear();
            continue;
        }
        buf.assign(per_slot * (last - first + 1), 0.0);
        // Entry k of the grid is buf[k - first slot's first entry].
        double* base = buf.data() - per_slot * first;
        for (long i = chunk_begin(chunk, chunks); i < chunk_begin(chunk + 1, chunks); ++i) accumulate(i, base);
    }
    if (chunks == 1 && chunk_blocks_[0] == 0 && thread_buffer_[0].size() == size) {
        out.swap(thread_buffer_[0]);  // one chunk over every block: its sums are the result
        return;
    }
    // The sum split by entries over the same threads: each entry still adds the chunks'
    // buffers in chunk order, so the result is the serial sum's to the bit.
    out.resize(size);
#pragma omp parallel num_threads(chunks)
    {
        const std::size_t threads = static_cast<std::size_t>(omp_get_num_threads());
        const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
        const std::size_t lo = size * t / threads, hi = size * (t + 1) / threads;
        std::fill(out.begin() + lo, out.begin() + hi, 0.0);
        for (int chunk = 0; chunk < chunks; ++chunk) {
            const auto& buf = thread_buffer_[chunk];
            if (buf.empty()) continue;
            const std::size_t from = per_slot * chunk_blocks_[2 * chunk];
            const std::size_t a = std::max(lo, from), b = std::min(hi, from + buf.size());
            for (std::size_t k = a; k < b; ++k) out[k] += buf[k - from];
        }
    }
}

// The velocity a point carries to node k of its stencil: its own, plus with APIC its
// affine field C (x_node - x_point).
template <int D>
inline void MpmSolver<D>::velocity_toward_node(const Stencil<D>& s, int k, const double* v, const double* C,
                                        double* out) const {
    for (int d = 0; d < D; ++d) out[d] = v[d];
    if (!m_.apic) return;
    const double* xn = &m_.grid.position[D * s.e[k].node];
    double dx[D];
    for (int d = 0; d < D; ++d) dx[d] = xn[d] - s.x[d];
    for (int d = 0; d < D; ++d)
        for (int e = 0; e < D; ++e) out[d] += C[D * d + e] * dx[e];
}

}  // namespace pilempm::mpm
