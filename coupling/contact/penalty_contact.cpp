#include "coupling/contact/penalty_contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pilempm::coupling {

namespace {

struct Projection {
    double xi = 0.0;        // along a -> b, in [0, 1]
    double distance2 = 0.0;
};

Projection project(const double* x, const double* xa, const double* xb) {
    const double tx = xb[0] - xa[0], ty = xb[1] - xa[1];
    const double l2 = tx * tx + ty * ty;
    double xi = l2 > 0.0 ? ((x[0] - xa[0]) * tx + (x[1] - xa[1]) * ty) / l2 : 0.0;
    xi = std::clamp(xi, 0.0, 1.0);
    const double dx = x[0] - xa[0] - xi * tx, dy = x[1] - xa[1] - xi * ty;
    return {xi, dx * dx + dy * dy};
}

}  // namespace

void PenaltyContact::bin_segments(const ContactSurface& s, double margin) {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300}, longest = 0.0;
    for (int k = 0; k < s.num_segments(); ++k) {
        const double* xa = &s.x[2 * s.a[k]];
        const double* xb = &s.x[2 * s.b[k]];
        for (int d = 0; d < 2; ++d) {
            lo[d] = std::min({lo[d], xa[d], xb[d]});
            hi[d] = std::max({hi[d], xa[d], xb[d]});
        }
        longest = std::max(longest, std::hypot(xb[0] - xa[0], xb[1] - xa[1]));
    }
    bin_size_ = std::max({longest, 2.0 * margin, 1e-9});
    for (int d = 0; d < 2; ++d) {
        bin_origin_[d] = lo[d] - margin - bin_size_;
        bins_[d] = static_cast<int>((hi[d] + margin + bin_size_ - bin_origin_[d]) / bin_size_) + 1;
    }
    // Counting sort of (bin, segment) pairs: each segment in the bins its box, grown by the
    // margin, overlaps, so a point finds every segment within the margin in its own bin.
    const int total = bins_[0] * bins_[1];
    bin_start_.assign(total + 1, 0);
    auto for_bins = [&](int k, auto&& visit) {
        const double* xa = &s.x[2 * s.a[k]];
        const double* xb = &s.x[2 * s.b[k]];
        int b0[2], b1[2];
        for (int d = 0; d < 2; ++d) {
            b0[d] = static_cast<int>((std::min(xa[d], xb[d]) - margin - bin_origin_[d]) / bin_size_);
            b1[d] = static_cast<int>((std::max(xa[d], xb[d]) + margin - bin_origin_[d]) / bin_size_);
        }
        for (int i = b0[0]; i <= b1[0]; ++i)
            for (int j = b0[1]; j <= b1[1]; ++j) visit(i * bins_[1] + j);
    };
    for (int k = 0; k < s.num_segments(); ++k) for_bins(k, [&](int bin) { ++bin_start_[bin + 1]; });
    for (int b = 0; b < total; ++b) bin_start_[b + 1] += bin_start_[b];
    bin_items_.assign(bin_start_[total], 0);
    std::vector<int> fill(bin_start_.begin(), bin_start_.end() - 1);
    for (int k = 0; k < s.num_segments(); ++k) for_bins(k, [&](int bin) { bin_items_[fill[bin]++] = k; });
    starting_.assign(s.x.size() / 2, -1);
    ending_.assign(s.x.size() / 2, -1);
    for (int k = 0; k < s.num_segments(); ++k) starting_[s.a[k]] = k, ending_[s.b[k]] = k;
}

int PenaltyContact::nearest_segment(const ContactSurface& s, const double* x, double& xi) const {
    const int i = static_cast<int>(std::floor((x[0] - bin_origin_[0]) / bin_size_));
    const int j = static_cast<int>(std::floor((x[1] - bin_origin_[1]) / bin_size_));
    if (i < 0 || j < 0 || i >= bins_[0] || j >= bins_[1]) return -1;
    const int bin = i * bins_[1] + j;
    int best = -1;
    double best_d2 = 1e300;
    for (int q = bin_start_[bin]; q < bin_start_[bin + 1]; ++q) {
        const int k = bin_items_[q];
        const Projection pr = project(x, &s.x[2 * s.a[k]], &s.x[2 * s.b[k]]);
        if (pr.distance2 < best_d2) best_d2 = pr.distance2, best = k, xi = pr.xi;
    }
    return best;
}

void PenaltyContact::compute(mpm::Particles<2>& p, mpm::ShapeKind kind, const ContactSurface& s, double dt,
                             const std::vector<std::unique_ptr<mpm::ConstitutiveModel>>& materials) {
    const long n = static_cast<long>(p.size());
    tangential_.resize(n, 0.0);
    segment_.resize(n, -1);
    const bool first = !started_;
    started_ = true;
    if (settings_.ignore_initial_overlap) overlap_.resize(n, 0.0);
    nodal_force_.assign(s.x.size(), 0.0);
    segment_force_.assign(2 * s.a.size(), 0.0);
    totals_ = {};
    touches_.clear();
    near_.clear();
    std::fill(p.external_force.begin(), p.external_force.end(), 0.0);
    // The search margin: the largest half-extent of a point domain along an axis.
    double margin = 0.0, half[4];
    for (long i = 0; i < n; ++i) {
        mpm::half_domain_edges<2>(p, i, kind, half);
        margin = std::max({margin, std::abs(half[0]) + std::abs(half[2]), std::abs(half[1]) + std::abs(half[3])});
    }
    bin_segments(s, margin);
    const double mu = settings_.friction, ring = settings_.ring;
    // Off contact: no force, no tangential history, and (unless still in its initial
    // overlap) no overlap kept.
    auto release = [&](long i, bool overlapping = false) {
        tangential_[i] = 0.0;
        segment_[i] = -1;
        if (!overlap_.empty() && !overlapping) overlap_[i] = 0.0;
    };
    for (long i = 0; i < n; ++i) {
        const double* x = &p.x[2 * i];
        double xi = 0.0;
        int k = nearest_segment(s, x, xi);
        if (k < 0) {
            release(i);
            continue;
        }
        const double* xa = &s.x[2 * s.a[k]];
        const double* xb = &s.x[2 * s.b[k]];
        const double len = std::hypot(xb[0] - xa[0], xb[1] - xa[1]);
        double t[2] = {(xb[0] - xa[0]) / len, (xb[1] - xa[1]) / len};
        double nrm[2] = {t[1], -t[0]};
        const double xs[2] = {xa[0] + xi * (xb[0] - xa[0]), xa[1] + xi * (xb[1] - xa[1])};
        const double rel[2] = {x[0] - xs[0], x[1] - xs[1]};
        mpm::half_domain_edges<2>(p, i, kind, half);
        // k_n across the point's thickness along n, and the step the pair needs: every point
        // the search finds, so one about to touch has its step already.
        double compliance = 1.0 / p.mass[i];
        if (!s.inverse_mass.empty())
            compliance += ring * ((1.0 - xi) * (1.0 - xi) * s.inverse_mass[s.a[k]] + xi * xi * s.inverse_mass[s.b[k]]);
        const mpm::ConstitutiveModel& material = *materials[p.material[i]];
        const double modulus = std::max(material.p_wave_modulus(),
                                        material.p_wave_modulus_at(&p.stress[6 * i], p.state.data() + p.state_stride * i));
        auto thickness_along = [&](const double* dir) {
            return 2.0 * (std::abs(half[0] * dir[0] + half[1] * dir[1]) + std::abs(half[2] * dir[0] + half[3] * dir[1]));
        };
        // The domain's area (per radian in axisymmetry): the face a traction acts on is this
        // over the thickness across it.
        const double domain = 4.0 * std::abs(half[0] * half[3] - half[1] * half[2]) * (settings_.axisymmetric ? x[0] : 1.0);
        auto face = [&](const double* dir) { return domain / thickness_along(dir); };
        auto stiffness = [&](const double* dir) {
            const double thickness = thickness_along(dir);
            return settings_.penalty_factor * modulus * domain / (thickness * thickness);
        };
        const double margin = settings_.stability_margin;
        const double k_near = stiffness(nrm);
        totals_.stable_time_step = std::min(totals_.stable_time_step, margin / std::sqrt(k_near * compliance));
        // The grid's step counts the springs of the pairs that touch or could within a step
        // (a point moves far less than a tenth of its thickness in one).
        const NearPair pair{i, k_near, s.a[k], s.b[k], xi};
        const double reach_within = 0.1 * thickness_along(nrm);
        auto keep_if_near = [&](double apart) {
            if (apart < reach_within) near_.push_back(pair);
        };
        double gap, share = 1.0;
        if ((xi <= 0.0 || xi >= 1.0) && rel[0] * nrm[0] + rel[1] * nrm[1] > 0.0) {
            // Past the segment's end, outside: the corner node against the point's domain
            // (a parallelogram of half-edges e1, e2): node - x = a e1 + b e2, inside when
            // |a|, |b| < 1; the point leaves it along the edge nearer the node.
            const double det = half[0] * half[3] - half[1] * half[2];
            const double a = (-rel[0] * half[3] + rel[1] * half[2]) / det;
            const double b = (rel[0] * half[1] - rel[1] * half[0]) / det;
            if (std::abs(a) >= 1.0 || std::abs(b) >= 1.0) {
                keep_if_near(std::max((std::abs(a) - 1.0) * std::hypot(half[0], half[1]),
                                      (std::abs(b) - 1.0) * std::hypot(half[2], half[3])));
                release(i);
                continue;
            }
            const double l1 = std::hypot(half[0], half[1]), l2 = std::hypot(half[2], half[3]);
            const double depth1 = (1.0 - std::abs(a)) * l1, depth2 = (1.0 - std::abs(b)) * l2;
            const bool along_e1 = depth1 <= depth2;
            const double sign = -((along_e1 ? a : b) > 0.0 ? 1.0 : -1.0);
            nrm[0] = sign * (along_e1 ? half[0] / l1 : half[2] / l2);
            nrm[1] = sign * (along_e1 ? half[1] / l1 : half[3] / l2);
            gap = -(along_e1 ? depth1 : depth2);
            double face_length = len;
            // Both segments at the corner are as near; the force belongs to the one it pushes
            // off (a point under a closed toe's rim bears on the base, not the shaft), and its
            // tangent is the direction of slip.
            const int node = xi <= 0.0 ? s.a[k] : s.b[k];
            const int other = xi <= 0.0 ? ending_[node] : starting_[node];
            if (other >= 0) {
                const double* oa = &s.x[2 * s.a[other]];
                const double* ob = &s.x[2 * s.b[other]];
                const double olen = std::hypot(ob[0] - oa[0], ob[1] - oa[1]);
                const double ot[2] = {(ob[0] - oa[0]) / olen, (ob[1] - oa[1]) / olen};
                if (ot[1] * nrm[0] - ot[0] * nrm[1] > t[1] * nrm[0] - t[0] * nrm[1]) {
                    k = other;
                    xi = node == s.a[k] ? 0.0 : 1.0;
                    t[0] = ot[0], t[1] = ot[1];
                    face_length = olen;
                }
            }
            // A face contact's force is its gap times the whole face; a corner overlaps only
            // part of the point's face, so it takes that share: the face's length inside the
            // domain over the most of it that could be (the domain's chord along the face, or
            // the face itself where it is shorter, as a thin wall's tip). Full force here
            // pushed the soil beside a punch's rim away and held it.
            if (settings_.corner_overlap_share) {
                const double along = xi <= 0.0 ? 1.0 : -1.0;  // the face runs from the node this way
                const double fa = along * (t[0] * half[3] - t[1] * half[2]) / det;  // in (e1, e2)
                const double fb = along * (t[1] * half[0] - t[0] * half[1]) / det;
                double inside = 1e300, chord = 1e300;
                if (fa != 0.0) inside = std::min(inside, ((fa > 0.0 ? 1.0 : -1.0) - a) / fa), chord = std::min(chord, 2.0 / std::abs(fa));
                if (fb != 0.0) inside = std::min(inside, ((fb > 0.0 ? 1.0 : -1.0) - b) / fb), chord = std::min(chord, 2.0 / std::abs(fb));
                share = std::min(1.0, std::min(inside, face_length) / std::min(chord, face_length));
            }
        } else {
            const double d = rel[0] * nrm[0] + rel[1] * nrm[1];
            const double reach = std::abs(half[0] * nrm[0] + half[1] * nrm[1]) + std::abs(half[2] * nrm[0] + half[3] * nrm[1]);
            gap = d - reach;
            // Apart, or the point's centre is past the surface: inside the body, where a wall
            // thinner than the point can catch it at a corner; it is let go (pushing it out
            // from there would take a force of the penalty times its half-size) and counted.
            if (gap >= 0.0) {
                keep_if_near(gap);
                release(i);
                continue;
            }
            if (d < 0.0) {
                ++totals_.points_inside;
                release(i);
                continue;
            }
        }
        if (settings_.ignore_initial_overlap) {
            // The overlap at the start is the zero gap; it shrinks as the point moves out.
            if (first) overlap_[i] = std::min(0.0, gap);
            overlap_[i] = std::min(0.0, std::max(overlap_[i], gap));
            gap -= overlap_[i];
            if (gap >= 0.0) {
                keep_if_near(gap);
                release(i, true);
                continue;
            }
        }
        const double kn_full = stiffness(nrm);
        totals_.stable_time_step = std::min(totals_.stable_time_step, margin / std::sqrt(kn_full * compliance));
        near_.push_back(pair);
        near_.back().stiffness = std::max(k_near, kn_full);
        const double kn = share * kn_full;
        const double fn = -kn * gap;
        // Tangential: a spring on the slip since the last step, capped by Coulomb.
        const double* va = &s.v[2 * s.a[k]];
        const double* vb = &s.v[2 * s.b[k]];
        const double vrel = (p.v[2 * i] - (1.0 - xi) * va[0] - xi * vb[0]) * t[0] +
                            (p.v[2 * i + 1] - (1.0 - xi) * va[1] - xi * vb[1]) * t[1];
        const bool same_face = segment_[i] >= 0 && s.side[segment_[i]] == s.side[k];
        double ft = (same_face ? tangential_[i] : 0.0) - settings_.tangential_ratio * kn * vrel * dt;
        // Coulomb on the effective normal force: the point pushes with the mixture's stress
        // (the water's excess pressure p reaches the steel through it), the grains with
        // fn - p A, A the domain's face across n (Terzaghi; shaft friction under a rapid load grew
        // with the pore pressure it raised).
        const double pore = p.pore_pressure.empty() ? 0.0 : p.pore_pressure[i];
        const double cap = mu * std::max(0.0, fn - share * pore * face(nrm));
        if (std::abs(ft) > cap) ft = std::copysign(cap, ft);  // slip, else stick
        tangential_[i] = ft;
        segment_[i] = k;
        const double f[2] = {fn * nrm[0] + ft * t[0], fn * nrm[1] + ft * t[1]};
        for (int c = 0; c < 2; ++c) {
            p.external_force[2 * i + c] = f[c];
            nodal_force_[2 * s.a[k] + c] -= ring * (1.0 - xi) * f[c];
            nodal_force_[2 * s.b[k] + c] -= ring * xi * f[c];
            totals_.force_on_master[c] -= ring * f[c];
            totals_.force_by_side[static_cast<int>(s.side[k])][c] -= ring * f[c];
            segment_force_[2 * k + c] -= ring * f[c];
        }
        touches_.push_back({i, {nrm[0], nrm[1]}, {xs[0], xs[1]}});
        ++totals_.points_in_contact;
        totals_.max_penetration = std::max(totals_.max_penetration, -gap);
    }
}

double PenaltyContact::grid_stable_time_step(const std::vector<double>& node_mass,
                                             const std::vector<mpm::Stencil<2>>& stencils, const ContactSurface& s) {
    if (near_.empty()) return 1e300;
    node_springs_.resize(node_mass.size(), 0.0);
    master_springs_.resize(s.x.size() / 2, 0.0);
    const bool master = !s.inverse_mass.empty();
    for (const NearPair& q : near_) {
        const mpm::Stencil<2>& st = stencils[q.point];
        for (int e = 0; e < st.count; ++e) node_springs_[st.e[e].node] += q.stiffness * st.e[e].N;
        master_springs_[q.a] += q.stiffness * (1.0 - q.xi);
        master_springs_[q.b] += q.stiffness * q.xi;
    }
    // Element by element: pair p's share of node i's mass is k_p N_ip / S_i, so its own
    // frequency on its shares, sum_i N_ip S_i / m_i (+ the pile's nodes alike), bounds the
    // whole system's.
    double omega2 = 0.0;
    for (const NearPair& q : near_) {
        const mpm::Stencil<2>& st = stencils[q.point];
        double w2 = 0.0;
        for (int e = 0; e < st.count; ++e)
            if (st.e[e].N > 0.0) w2 += st.e[e].N * node_springs_[st.e[e].node] / node_mass[st.e[e].node];
        if (master)
            w2 += settings_.ring * ((1.0 - q.xi) * master_springs_[q.a] * s.inverse_mass[q.a] +
                                    q.xi * master_springs_[q.b] * s.inverse_mass[q.b]);
        omega2 = std::max(omega2, w2);
    }
    for (const NearPair& q : near_) {
        const mpm::Stencil<2>& st = stencils[q.point];
        for (int e = 0; e < st.count; ++e) node_springs_[st.e[e].node] = 0.0;
        master_springs_[q.a] = master_springs_[q.b] = 0.0;
    }
    return omega2 > 0.0 ? settings_.stability_margin / std::sqrt(omega2) : 1e300;
}

std::vector<std::pair<std::string, std::vector<double>>> PenaltyContact::outputs() const {
    std::vector<double> totals = {totals_.force_on_master[0], totals_.force_on_master[1]};
    for (const auto& side : totals_.force_by_side) totals.insert(totals.end(), side.begin(), side.end());
    totals.insert(totals.end(), {totals_.max_penetration, static_cast<double>(totals_.points_in_contact),
                                 static_cast<double>(totals_.points_inside), totals_.stable_time_step});
    std::vector<double> touches;
    touches.reserve(5 * touches_.size());
    for (const ContactTouch& t : touches_)
        touches.insert(touches.end(), {static_cast<double>(t.point), t.normal[0], t.normal[1], t.on_surface[0],
                                       t.on_surface[1]});
    return {{"contact_nodal_force", nodal_force_},
            {"contact_segment_force", segment_force_},
            {"contact_totals", totals},
            {"contact_touches", touches}};
}

void PenaltyContact::restore_outputs(const std::vector<double>& nodal_force, const std::vector<double>& segment_force,
                                     const std::vector<double>& totals, const std::vector<double>& touches) {
    if (totals.size() != 16 || touches.size() % 5 != 0)
        throw std::runtime_error("the checkpoint's contact totals or touches are malformed");
    nodal_force_ = nodal_force;
    segment_force_ = segment_force;
    totals_.force_on_master = {totals[0], totals[1]};
    for (std::size_t k = 0; k < totals_.force_by_side.size(); ++k)
        totals_.force_by_side[k] = {totals[2 + 2 * k], totals[3 + 2 * k]};
    totals_.max_penetration = totals[12];
    totals_.points_in_contact = static_cast<int>(totals[13]);
    totals_.points_inside = static_cast<int>(totals[14]);
    totals_.stable_time_step = totals[15];
    touches_.clear();
    for (std::size_t k = 0; k < touches.size(); k += 5)
        touches_.push_back({static_cast<long>(touches[k]), {touches[k + 1], touches[k + 2]},
                            {touches[k + 3], touches[k + 4]}});
}

}  // namespace pilempm::coupling
