#pragma once
// A cut through the grid's velocity fields (Nairn's CRAMP, for a thin wall rather than a
// crack): a point's contribution to a node whose straight line from the point crosses the
// cut goes `offset` fields up. Material either side of a wall thinner than a cell then
// never shares a field at the nodes between, so neither side feels the other through the
// grid; away from the cut (below a pile's toe) the material stays on one field. Geometry
// only: whatever wall it is (the FE pile's mid-surface) is the caller's business.
#include <vector>

#include "mpm/grid/grid.hpp"
#include "mpm/grid/shape_functions.hpp"

namespace pilempm::mpm {

struct FieldCut {
    // A polyline in the (x or r, y) plane, its vertices in increasing y (a wall's mid-line
    // from its toe to its head), 2 per vertex.
    std::vector<double> vertices;
    int offset = 1;  // fields added to a crossing entry (2 with water fields: pairs)
    // Its lowest `contact_segments` segments are a slip line through one material rather
    // than a wall between two: there the sides meet at the nodes both reach, in frictional
    // contact (mpm/grid/field_contact.hpp); the rest are walls.
    int contact_segments = 0;
    double friction = 0.0;  // Coulomb coefficient across the slip line (tan of its friction angle)
    bool has_contact() const { return contact_segments > 0; }

    // The polyline's x range once bound(): a line from a to b that stays on one side of
    // it cannot cross, the test most points take (the soil away from a pile's wall).
    double x_low = -1e300, x_high = 1e300;
    void bound();  // call after setting the vertices

    int num_vertices() const { return static_cast<int>(vertices.size() / 2); }
    // Whether the line from a to b crosses the polyline. A point on the polyline counts as
    // being on its +x side, so a node on the cut still belongs to exactly one side.
    bool crosses(const double* a, const double* b) const;
    // The unit normal at p of the polyline's segment nearest p, pointing away from p's side
    // (from the field p's own side moves with to the one across); returns that segment.
    int normal_away_from(const double* p, double* n) const;
};

// Moves each stencil entry of the point at x across every cut its line to the node crosses.
// half: the point's half-edge vectors (row k = vector k, as evaluate_shape took them).
void apply_field_cuts(const Grid<2>& grid, const std::vector<FieldCut>& cuts, const double* x, const double* half,
                      Stencil<2>& s);

}  // namespace pilempm::mpm
