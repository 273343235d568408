#pragma once
// Penalty contact between material points (slave) and the segments of a master surface,
// independent of the grid: the gap is from the point's domain to the segment, the normal
// force -k_n g, the tangential force a penalty spring capped by Coulomb's mu f_n' (stick or
// slip, kept per point between steps), f_n' the effective normal force: f_n less the point's
// excess pore pressure over its face. The forces are equal and opposite: each point's on
// its external force, the master's on the segment's two nodes by the projection's weights
// (times `ring`: the master integrates the whole ring, the soil is per radian).
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "coupling/contact/contact_surface.hpp"
#include "mpm/grid/shape_functions.hpp"
#include "mpm/materials/constitutive_model.hpp"
#include "mpm/points/particles.hpp"

namespace pilempm::coupling {

struct ContactSettings {
    double friction = 0.0;  // mu = tan(delta)
    // The penalty per point from the soil's stiffness, k_n = penalty_factor M A_p / h_p^2
    // (M the point's P-wave modulus in its current state, never below its material's
    // reference one; A_p its domain's area, times r in axisymmetry; h_p the domain's
    // thickness across the contact): a contact traction sigma on the domain's face
    // penetrates g = sigma h_p / (penalty_factor M), g / h = sigma / (2 penalty_factor M)
    // with two points a cell. The domain, not the point's volume: a point carried from the
    // axis round a toe keeps the small volume of its first radius in a full-size uGIMP
    // domain, and on its volume it took the rim's load at five times that gap. A soil that stiffens under the
    // pile's toe stiffens its contact with it, so sigma / M stays near the soil's own strain.
    // Independent of the step, so the contact stores and gives back its energy; the step it
    // needs (omega dt <= stability_margin) is grid_stable_time_step() on the grid's masses,
    // totals().stable_time_step on the points' own (a run's first step).
    double penalty_factor = 4.0;
    // omega dt of the contact's stiffest pair: 2 cfl, the margin the soil's CFL leaves its
    // stiffest grid mode (central differences are stable to 2), so that the case's cfl
    // scales the whole step, the contact's part of it too (1 at the default cfl of 0.5).
    double stability_margin = 1.0;
    double tangential_ratio = 1.0;  // k_t / k_n
    double ring = 1.0;              // master force per point force: 2 pi axisymmetric, 1 plane strain
    bool axisymmetric = false;      // the soil per radian: a point's face is its domain's times r
    // A body wished in place: the overlaps found at the first step are taken as the points'
    // zero gap, and forgotten as each point moves out of its overlap.
    bool ignore_initial_overlap = false;
    // A point meeting a corner takes the share of the face the corner overlaps (a face
    // contact's force is its gap times the whole face), else the whole face's force. The
    // share is right for a punch's rim (verification 2); on a toe only two points wide it
    // leaves the toe bearing on one rim point, so jacking keeps the whole force for now.
    bool corner_overlap_share = false;
};

// A point pressed on the surface this step: the surface's unit normal into the soil there
// and the nearest point on it (the body is impermeable to the soil's pore water there).
struct ContactTouch {
    long point = 0;
    double normal[2] = {0, 0};
    double on_surface[2] = {0, 0};  // m
};

struct ContactTotals {
    std::array<double, 2> force_on_master{};  // N (master's measure: the whole ring)
    // The same by the side of the master it acts on (SurfaceSide: outer, inner, toe, head, other).
    std::array<std::array<double, 2>, 5> force_by_side{};
    double max_penetration = 0.0;             // m, the deepest point domain into a segment
    int points_in_contact = 0;
    int points_inside = 0;  // centres past the surface, let go (a wall thinner than a point)
    double stable_time_step = 1e300;  // s, over the points near the surface
};

class PenaltyContact {
public:
    explicit PenaltyContact(ContactSettings settings) : settings_(settings) {}

    // From the points at t_n and the surface's current geometry: overwrites the points'
    // external force (zero off contact) and fills nodal_force() (2 per surface node).
    // materials: the points' constitutive models (their stiffness sets the penalty); dt: the
    // step the forces act over.
    void compute(mpm::Particles<2>& p, mpm::ShapeKind kind, const ContactSurface& surface, double dt,
                 const std::vector<std::unique_ptr<mpm::ConstitutiveModel>>& materials);

    // The step the contact allows on the grid the soil's last step scattered to (node_mass per
    // grid entry, the points' stencils of that step), for the pairs the last compute() found:
    // the springs on each node summed and the node's mass split among them in proportion,
    // so that omega^2 <= max over pairs of sum_i N_ip S_i / m_i (S_i = sum_q k_q N_iq), the
    // pile's side likewise (a rigorous bound on the coupled system's highest frequency). A
    // light point among heavy ones no longer sets the step by its own mass; the points alone
    // bound it by max k / m_p (totals().stable_time_step), which this never exceeds.
    double grid_stable_time_step(const std::vector<double>& node_mass, const std::vector<mpm::Stencil<2>>& stencils,
                                 const ContactSurface& surface);

    const ContactSettings& settings() const { return settings_; }
    const std::vector<double>& nodal_force() const { return nodal_force_; }
    // The force on each segment (2 per segment, the master's measure), for traction profiles.
    const std::vector<double>& segment_force() const { return segment_force_; }
    const ContactTotals& totals() const { return totals_; }
    const std::vector<ContactTouch>& touches() const { return touches_; }
    // Per point: the tangential force it carries (N, along its segment's a -> b) and its
    // segment (-1 off contact), for restart.
    const std::vector<double>& tangential_force() const { return tangential_; }
    const std::vector<int>& segment() const { return segment_; }
    // The initial overlap each point still has (m, <= 0), when ignored.
    const std::vector<double>& overlap() const { return overlap_; }
    bool started() const { return started_; }
    // A checkpoint's history back: tangential forces, segments and overlaps per point.
    void restore(std::vector<double> tangential, std::vector<int> segment, std::vector<double> overlap, bool started) {
        tangential_ = std::move(tangential);
        segment_ = std::move(segment);
        overlap_ = std::move(overlap);
        started_ = started;
    }
    // The last step's outputs (forces, totals, touches) as flat arrays and back: a run
    // stopped in a pause, where no step computes them, resumes with them as they were.
    std::vector<std::pair<std::string, std::vector<double>>> outputs() const;
    void restore_outputs(const std::vector<double>& nodal_force, const std::vector<double>& segment_force,
                         const std::vector<double>& totals, const std::vector<double>& touches);

private:
    void bin_segments(const ContactSurface& s, double margin);
    int nearest_segment(const ContactSurface& s, const double* x, double& xi) const;

    ContactSettings settings_;
    std::vector<double> nodal_force_, segment_force_, tangential_;
    std::vector<int> segment_;
    std::vector<double> overlap_;  // per point, when initial overlaps are ignored
    bool started_ = false;         // the first step (and its overlaps) taken
    ContactTotals totals_;
    std::vector<ContactTouch> touches_;
    // Segments binned on a uniform grid over the surface's box, grown by the search margin.
    double bin_origin_[2] = {0.0, 0.0}, bin_size_ = 1.0;
    int bins_[2] = {0, 0};
    std::vector<int> bin_start_, bin_items_;
    // Per node, the segment that starts there and the one that ends there (-1: none): the
    // two that share a corner.
    std::vector<int> starting_, ending_;
    // The pairs the search found (touching or about to) with their stiffest spring, for the
    // grid's step; scratch sums of springs per grid entry and per surface node.
    struct NearPair {
        long point;
        double stiffness;  // N/m per radian (per metre in plane strain)
        int a, b;          // the segment's nodes
        double xi;
    };
    std::vector<NearPair> near_;
    std::vector<double> node_springs_, master_springs_;
};

}  // namespace pilempm::coupling
