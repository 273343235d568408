// A point that meets a closed toe at its rim touches two segments at once (the base and the
// shaft end at the same node, equally near). The force belongs to the face it pushes off:
// a point under the rim bears on the base (toe), one beside it on the shaft (outer),
// whichever of the two segments the search met first. With corner_overlap_share its force
// is the share of the face the corner overlaps (a face contact's is its gap times the
// whole face).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "coupling/contact/penalty_contact.hpp"
#include "mpm/materials/constitutive_model.hpp"

using namespace pilempm;
using namespace pilempm::coupling;

namespace {

constexpr double kHalf = 0.05, kOverlap = 1e-3;  // m: the point's half-size, its overlap

// The rectangle [0, w] x [0, 1] (a pile with its toe at y = 0), counter-clockwise, its
// segments listed forwards or backwards.
ContactSurface square(bool reversed, double w = 1.0) {
    ContactSurface s;
    s.x = {0.0, 0.0, w, 0.0, w, 1.0, 0.0, 1.0};
    s.v.assign(8, 0.0);
    const int a[4] = {0, 1, 2, 3}, b[4] = {1, 2, 3, 0};
    const SurfaceSide side[4] = {SurfaceSide::Toe, SurfaceSide::Outer, SurfaceSide::Head, SurfaceSide::Inner};
    for (int j = 0; j < 4; ++j) {
        const int k = reversed ? 3 - j : j;
        s.add_segment(a[k], b[k], side[k]);
    }
    return s;
}

// One point at x by the corner (1, 0): the contact's totals and the point's force.
ContactTotals touch(const double* x, bool reversed, double force[2], double width = 1.0, bool share = false) {
    std::vector<std::unique_ptr<mpm::ConstitutiveModel>> materials;
    materials.push_back(std::make_unique<mpm::LinearElastic>(20e6, 0.3));
    mpm::Particles<2> points;
    const double lengths[2] = {2 * kHalf, 2 * kHalf};
    points.add(x, 1.0, 4 * kHalf * kHalf, lengths, 0);
    points.resize_state(materials[0]->num_state());
    ContactSettings settings;
    settings.corner_overlap_share = share;
    PenaltyContact contact(settings);
    contact.compute(points, mpm::ShapeKind::GIMP, square(reversed, width), 1e-6, materials);
    force[0] = points.external_force[0];
    force[1] = points.external_force[1];
    EXPECT_EQ(contact.totals().points_in_contact, 1);
    return contact.totals();
}

// The point at x, whichever order the segments come in: pushed along `axis` (0: r, 1: z)
// with `sign`, the whole force charged to `charged` and none to `spared`.
void expect_charged(const double* x, int axis, double sign, SurfaceSide charged, SurfaceSide spared) {
    const int on = static_cast<int>(charged), off = static_cast<int>(spared);
    for (bool reversed : {false, true}) {
        double f[2];
        const ContactTotals t = touch(x, reversed, f);
        EXPECT_GT(sign * f[axis], 0.0) << "the push's direction, segments reversed: " << reversed;
        EXPECT_EQ(f[1 - axis], 0.0);
        EXPECT_LT(sign * t.force_by_side[on][axis], 0.0) << "the side it bears on, segments reversed: " << reversed;
        EXPECT_EQ(t.force_by_side[off][0], 0.0);
        EXPECT_EQ(t.force_by_side[off][1], 0.0);
    }
}

}  // namespace

TEST(ContactCorner, APointUnderTheRimBearsOnTheBase) {
    const double x[2] = {1.0 + 0.2 * kHalf, -kHalf + kOverlap};  // below, a little outside
    expect_charged(x, 1, -1.0, SurfaceSide::Toe, SurfaceSide::Outer);
}

TEST(ContactCorner, APointBesideTheRimPushesOnTheShaft) {
    const double x[2] = {1.0 + kHalf - kOverlap, -0.2 * kHalf};  // outside, a little below
    expect_charged(x, 0, 1.0, SurfaceSide::Outer, SurfaceSide::Toe);
}

TEST(ContactCorner, ACornerTakesTheShareOfTheFaceItOverlaps) {
    // Under the base's middle the whole of the point's top bears; under the rim, 0.8 kHalf of
    // its 2 kHalf, at the same depth: 0.4 of the face's force, and no push sideways.
    double face[2], corner[2];
    const double middle[2] = {0.5, -kHalf + kOverlap}, rim[2] = {1.0 + 0.2 * kHalf, -kHalf + kOverlap};
    touch(middle, false, face, 1.0, true);
    touch(rim, false, corner, 1.0, true);
    EXPECT_LT(face[1], 0.0);  // pushed down, off the base
    EXPECT_NEAR(corner[1], 0.4 * face[1], 1e-12 * std::abs(face[1]));
    EXPECT_EQ(corner[0], 0.0);
}

TEST(ContactCorner, AThinWallsTipBearsAsAWholeFaceOnceThePointCoversIt) {
    // A wall 0.4 kHalf thick (an open pile's tip, thinner than the point): a point whose top
    // covers the whole tip bears as fully as one centred under it; one covering half, half.
    const double width = 0.4 * kHalf;
    double centred[2], covering[2], half[2];
    const double under[2] = {0.5 * width, -kHalf + kOverlap};
    const double beside[2] = {width + 0.5 * kHalf, -kHalf + kOverlap};    // covers the whole tip
    const double halfway[2] = {width + kHalf - 0.2 * kHalf, -kHalf + kOverlap};  // covers 0.2 kHalf of 0.4
    touch(under, false, centred, width, true);
    touch(beside, false, covering, width, true);
    touch(halfway, false, half, width, true);
    double whole[2];  // without the share (corner_contact: full) the corner bears as the face
    touch(halfway, false, whole, width, false);
    EXPECT_NEAR(whole[1], centred[1], 1e-12 * std::abs(centred[1]));
    EXPECT_NEAR(covering[1], centred[1], 1e-12 * std::abs(centred[1]));
    EXPECT_LT(centred[1], 0.0);
    EXPECT_NEAR(half[1], 0.5 * centred[1], 1e-12 * std::abs(centred[1]));
}
