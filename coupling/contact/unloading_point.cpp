#include "coupling/contact/unloading_point.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pilempm::coupling {

namespace {

const std::vector<double>& col(const Table& t, const std::string& name) { return t.column(name); }

// dv/dt by central differences over `window` (s) at least, v read linearly between rows
// (one-sided at the record's ends): the pile's ringing averaged out over its wave period.
std::vector<double> acceleration(const std::vector<double>& t, const std::vector<double>& v, double window) {
    const std::size_t n = t.size();
    auto v_at = [&](double time) {
        if (time <= t.front()) return v.front();
        if (time >= t.back()) return v.back();
        const std::size_t k = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), time) - t.begin());
        const double w = (time - t[k - 1]) / (t[k] - t[k - 1]);
        return v[k - 1] + w * (v[k] - v[k - 1]);
    };
    std::vector<double> a(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const double before = i > 0 ? t[i - 1] : t[i], after = i + 1 < n ? t[i + 1] : t[i];
        const double lo = std::max(t.front(), std::min(before, t[i] - 0.5 * window));
        const double hi = std::min(t.back(), std::max(after, t[i] + 0.5 * window));
        a[i] = hi > lo ? (v_at(hi) - v_at(lo)) / (hi - lo) : 0.0;
    }
    return a;
}

}  // namespace

UnloadingPointResult unloading_point(const RapidLoadRecord& r, double mass, double window) {
    const std::size_t n = r.time.size();
    if (n < 3 || r.force.size() != n || r.settlement.size() != n || r.velocity.size() != n)
        throw std::invalid_argument("unloading point: a record of at least 3 rows, every column as long as the time");
    const std::vector<double> a = acceleration(r.time, r.velocity, window);
    std::vector<double> soil(n);
    for (std::size_t i = 0; i < n; ++i) soil[i] = r.force[i] - mass * a[i];
    const std::size_t peak = static_cast<std::size_t>(std::max_element(r.force.begin(), r.force.end()) - r.force.begin());
    if (!(r.force[peak] > 0.0)) throw std::invalid_argument("unloading point: the record has no load (its force is never down)");
    // The unloading point: the first row from the peak load on where the pile stops (v <= 0),
    // v = 0 found linearly between it and the row before.
    std::size_t u = peak;
    while (u < n && r.velocity[u] > 0.0) ++u;
    if (u == n) throw std::invalid_argument("unloading point: the pile is still moving down at the record's end");
    if (u == 0) throw std::invalid_argument("unloading point: the pile never moved down");
    const double w = r.velocity[u - 1] / (r.velocity[u - 1] - r.velocity[u]);  // 0 at u - 1, 1 at u
    auto at = [&](const std::vector<double>& x) { return x[u - 1] + w * (x[u] - x[u - 1]); };
    UnloadingPointResult out;
    out.unloading_time = at(r.time);
    out.max_settlement = at(r.settlement);
    out.static_resistance = at(soil);
    out.peak_force = r.force[peak];
    // C by least squares over the peak load to the unloading point, the static resistance
    // held at F_u: sum (F_soil - F_u) v / sum v^2 (rows of small v weigh little).
    double num = 0.0, den = 0.0;
    for (std::size_t i = peak; i < u; ++i) {
        num += (soil[i] - out.static_resistance) * r.velocity[i];
        den += r.velocity[i] * r.velocity[i];
    }
    out.damping = den > 0.0 ? num / den : 0.0;
    for (std::size_t i = 0; i < u; ++i) out.peak_velocity = std::max(out.peak_velocity, r.velocity[i]);
    out.curve = Table("unloading_point", {"time_s", "settlement_m", "velocity_m_s", "acceleration_m_s2", "load_N",
                                          "soil_force_N", "static_force_N"});
    for (std::size_t i = 0; i < u; ++i)
        out.curve.add_row({r.time[i], r.settlement[i], r.velocity[i], a[i], r.force[i], soil[i],
                           soil[i] - out.damping * r.velocity[i]});
    return out;
}

RapidLoadRecord rapid_load_record(const Table& history, int stage) {
    const auto& st = col(history, "stage");
    const auto& t = col(history, "time_s");
    const auto& f = col(history, "pile_head_force_N");
    const auto& s = col(history, "pile_head_settlement_m");
    const auto& v = col(history, "pile_head_velocity_m_s");
    RapidLoadRecord r;
    double start = 0.0;  // the settlement before the stage's first row
    bool first = true;
    for (std::size_t i = 0; i < st.size(); ++i) {
        if (st[i] != stage) continue;
        if (first) start = i > 0 ? s[i - 1] : 0.0, first = false;
        r.time.push_back(t[i]);
        r.force.push_back(f[i]);
        r.settlement.push_back(s[i] - start);
        r.velocity.push_back(v[i]);
    }
    return r;
}

}  // namespace pilempm::coupling
