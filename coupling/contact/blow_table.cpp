#include "coupling/contact/blow_table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pilempm::coupling {

namespace {

const std::vector<double>& col(const Table& t, const std::string& name) { return t.column(name); }

}  // namespace

Table blow_table(const Table& history, const Table& extremes, const std::vector<BlowStage>& blows,
                 double ground_elevation) {
    Table out("blows", {"blow", "stage", "start_time_s", "duration_s", "toe_depth_before_m", "toe_depth_m", "set_m",
                        "max_head_displacement_m", "max_head_force_N", "max_head_velocity_m_s",
                        "enthru_J", "max_compression_Pa", "max_tension_Pa", "max_shaft_resistance_N",
                        "max_base_resistance_N", "max_toe_pore_pressure_Pa", "min_toe_pore_pressure_Pa",
                        "plug_length_m", "radiated_energy_J", "pile_energy_end_J", "soil_kinetic_energy_end_J",
                        "soil_mass_kg", "soil_volume_m3", "pore_water_volume_m3", "soil_mass_change",
                        "grain_volume_change",
                        "max_shaft_pore_pressure_upper_Pa", "min_shaft_pore_pressure_upper_Pa",
                        "max_shaft_pore_pressure_middle_Pa", "min_shaft_pore_pressure_middle_Pa",
                        "max_shaft_pore_pressure_lower_Pa", "min_shaft_pore_pressure_lower_Pa"});
    const auto& stage = col(history, "stage");
    const auto& time = col(history, "time_s");
    const auto& toe = col(history, "pile_toe_elevation_m");
    const auto& head = col(history, "pile_head_settlement_m");
    const auto& plug = col(history, "plug_length_m");
    const auto& absorbed = col(history, "absorbed_energy_J");
    const auto& pile_energy = col(history, "pile_energy_J");
    const auto& kinetic = col(history, "kinetic_energy_J");
    const auto& mass = col(history, "soil_mass_kg");
    const auto& volume = col(history, "soil_volume_m3");
    const auto& water = col(history, "pore_water_volume_m3");
    // Each stage's first and last row, in one pass (a drive of hundreds of blows has
    // hundreds of thousands of rows, and the table is rebuilt at every checkpoint).
    std::vector<std::size_t> first_row, last_row;
    for (std::size_t i = 0; i < stage.size(); ++i) {
        const auto st = static_cast<std::size_t>(std::max(0.0, stage[i]));
        if (st >= first_row.size()) first_row.resize(st + 1, stage.size()), last_row.resize(st + 1, 0);
        if (first_row[st] == stage.size()) first_row[st] = i;
        last_row[st] = i;
    }
    // Each stage's row of extremes.
    const auto& extremes_stage = col(extremes, "stage");
    std::vector<std::size_t> peak_row(first_row.size(), extremes_stage.size());
    for (std::size_t r = 0; r < extremes_stage.size(); ++r) {
        const auto st = static_cast<std::size_t>(std::max(0.0, extremes_stage[r]));
        if (st < peak_row.size()) peak_row[st] = r;
    }
    double last_blow_toe = 0.0;  // where the last blow left the toe
    bool after_a_blow = false;
    for (const BlowStage& b : blows) {
        const auto st = static_cast<std::size_t>(b.stage);
        if (st >= first_row.size() || first_row[st] == stage.size()) continue;  // not run (the drive ended before it)
        if (peak_row[st] == extremes_stage.size()) continue;  // under way (a checkpoint's tables: its finished blows)
        const std::size_t first = first_row[st], last = last_row[st];
        const std::size_t before = first > 0 ? first - 1 : first;
        auto peak = [&](const char* which, const std::string& column) { return col(extremes, which + column)[peak_row[st]]; };
        // The set counts from where the last blow left the toe, as a set is read in the
        // field: the pause's settlement goes to the blow after it, and the sets add up to
        // the drive's penetration.
        const double toe_before = after_a_blow ? last_blow_toe : toe[before];
        last_blow_toe = toe[last];
        after_a_blow = true;
        // The drift since the run began, formed here in double precision: the CSV's ten
        // digits of the volumes would hide changes below 1e-10 of them.
        const double mass_change = mass[last] / mass.front() - 1.0;
        const double grain_change = (volume[last] - water[last]) / (volume.front() - water.front()) - 1.0;
        const char* shaft[3] = {"shaft_pore_pressure_upper_Pa", "shaft_pore_pressure_middle_Pa",
                                "shaft_pore_pressure_lower_Pa"};
        out.add_row({static_cast<double>(b.blow), static_cast<double>(b.stage), time[before],
                     time[last] - time[before], ground_elevation - toe_before, ground_elevation - toe[last],
                     toe_before - toe[last], std::max(0.0, peak("max_", "pile_head_settlement_m") - head[before]),
                     std::max(0.0, peak("max_", "pile_head_force_N")),
                     std::max(0.0, peak("max_", "pile_head_velocity_m_s")), std::max(0.0, peak("max_", "enthru_J")),
                     std::max(0.0, peak("max_", "pile_max_compression_Pa")),
                     std::max(0.0, peak("max_", "pile_max_tension_Pa")),
                     std::max(0.0, peak("max_", "shaft_resistance_N")), std::max(0.0, peak("max_", "base_resistance_N")),
                     peak("max_", "toe_pore_pressure_Pa"), peak("min_", "toe_pore_pressure_Pa"), plug[last],
                     absorbed[last] - absorbed[before], pile_energy[last], kinetic[last], mass[last], volume[last],
                     water[last], mass_change, grain_change, peak("max_", shaft[0]), peak("min_", shaft[0]),
                     peak("max_", shaft[1]), peak("min_", shaft[1]), peak("max_", shaft[2]), peak("min_", shaft[2])});
    }
    return out;
}

Table blow_count_table(const Table& blows, double interval) {
    if (!(interval > 0.0)) throw std::invalid_argument("blow_count_table: the depth interval must be positive");
    Table out("blow_count", {"depth_top_m", "depth_bottom_m", "blows", "blows_per_m", "cumulative_blows"});
    const auto& before = col(blows, "toe_depth_before_m");
    const auto& after = col(blows, "toe_depth_m");
    if (after.empty()) return out;
    const double start = before.front();
    const double deepest = *std::max_element(after.begin(), after.end());
    const int intervals = std::max(1, static_cast<int>(std::ceil((deepest - start) / interval - 1e-9)));
    std::vector<double> count(intervals, 0.0);
    for (double d : after) {
        const int k = std::clamp(static_cast<int>(std::floor((d - start) / interval)), 0, intervals - 1);
        count[k] += 1.0;
    }
    double cumulative = 0.0;
    for (int k = 0; k < intervals; ++k) {
        cumulative += count[k];
        out.add_row({start + k * interval, start + (k + 1) * interval, count[k], count[k] / interval, cumulative});
    }
    return out;
}

}  // namespace pilempm::coupling
