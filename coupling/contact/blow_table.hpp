#pragma once
// A drive's record blow by blow, read off the run's history (with the pile recorder's
// columns) and each stage's extremes of it (history_extremes.hpp: over every step, stored in
// the history or not): the set, the head's peaks (PDA style: F, Z v, the largest
// displacement, ENTHRU), the steel's largest compression and tension, the soil's resistance
// split into shaft and base, the pore pressure under the toe and the plug; and the blow count
// per depth interval against depth, as a drivability sheet gives it. Built from what a
// checkpoint holds, so a resumed run writes the same tables.
#include <vector>

#include "core/table.hpp"

namespace pilempm::coupling {

struct BlowStage {
    int stage = 0;  // the history's stage number (1-based)
    int blow = 0;   // its blow number within the drive (1-based)
};

// One row per blow that ran. ground_elevation: the seabed (m, the soil's frame), depths are
// below it. The state before a blow is the history's last row before its first; its toe
// depth before, the depth the last blow left it at (the set takes the pause's settlement).
// Its peaks are its stage's extremes.
Table blow_table(const Table& history, const Table& extremes, const std::vector<BlowStage>& blows,
                 double ground_elevation);

// From blow_table's rows: per interval of toe depth (m, from the depth of the first blow's
// start), the blows that ended in it and the blows per metre; and the cumulative blows at
// its bottom. Blows count where they end; an interval no blow ended in has 0.
Table blow_count_table(const Table& blows, double interval = 0.25);

}  // namespace pilempm::coupling
