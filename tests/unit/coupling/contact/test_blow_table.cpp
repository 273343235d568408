// The drive's blow-by-blow record read off a history: a blow's state before it is the
// history's row before its first, its set the toe's travel, its peaks over its own rows; the
// blow count per interval counts each blow where it ends, cumulative at each interval's
// bottom. A synthetic history whose answers are known by construction.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "coupling/contact/blow_table.hpp"
#include "coupling/driver/history_extremes.hpp"

namespace pc = pilempm::coupling;

namespace {

// Stage 1 settles (toe at 5.0), blows in stages 2 and 4 (each sinks the toe 0.1 m over two
// rows), a pause in stage 3; columns as the pile recorder names them.
pilempm::Table drive_history() {
    pilempm::Table h("history", {"time_s", "stage", "pile_toe_elevation_m", "pile_head_settlement_m", "pile_head_force_N",
                                 "pile_head_velocity_m_s", "enthru_J", "pile_max_compression_Pa", "pile_max_tension_Pa",
                                 "outer_shaft_resistance_N", "inner_shaft_resistance_N", "base_resistance_N",
                                 "toe_pore_pressure_Pa", "plug_length_m", "absorbed_energy_J", "pile_energy_J",
                                 "kinetic_energy_J", "soil_mass_kg", "soil_volume_m3", "pore_water_volume_m3",
                                 "shaft_pore_pressure_upper_Pa", "shaft_pore_pressure_middle_Pa",
                                 "shaft_pore_pressure_lower_Pa"});
    // The ledger's columns: absorbed energy cumulative, the rest of the moment.
    h.add_row({0.0, 1, 5.0, 0.0, 0, 0, 0, 1e6, 0, 10, 5, 20, 0, 1.0, 0, 0, 0, 100, 10, 4, 1e3, 2e3, 3e3});
    h.add_row({0.01, 2, 4.95, 0.06, 3e6, 2.0, 900, 150e6, 0, 40, 20, 300, 5e4, 1.0, 50, 800, 30, 100, 10, 4, 4e3, -5e3, 6e3});
    h.add_row({0.02, 2, 4.90, 0.05, 1e6, -0.5, 1000, 80e6, 30e6, 30, 10, 100, -2e4, 1.05, 70, 20, 5, 100, 10.1, 4.1, -7e3, 8e3, 9e3});
    h.add_row({1.00, 3, 4.89, 0.06, 0, 0, 0, 1e6, 0, 10, 5, 20, 0, 1.05, 75, 10, 0, 100, 10.05, 4.05, 0, 0, 0});
    h.add_row({1.01, 4, 4.85, 0.11, 2e6, 1.0, 700, 120e6, 0, 50, 20, 200, 3e4, 1.05, 95, 600, 20, 100, 10.1, 4.1, 1e4, 2e4, -3e4});
    h.add_row({1.02, 4, 4.80, 0.10, 0, 0, 800, 60e6, 10e6, 20, 10, 50, 1e4, 1.1, 115, 15, 4, 100, 10.2, 4.2, -1e4, 5e3, 4e4});
    // The driver's step count (the extremes skip time, step and stage) and the shaft's total.
    std::vector<double> step, shaft;
    for (std::size_t i = 0; i < h.rows(); ++i)
        step.push_back(10.0 * i), shaft.push_back(h.column("outer_shaft_resistance_N")[i] + h.column("inner_shaft_resistance_N")[i]);
    h.columns.insert(h.columns.begin() + 1, "step");
    h.data.insert(h.data.begin() + 1, step);
    h.columns.push_back("shaft_resistance_N");
    h.data.push_back(shaft);
    return h;
}

// Every row stored: the stages' extremes are those of their rows.
pilempm::Table drive_extremes(const pilempm::Table& h) { return pc::extremes_of_history(h, 100); }

double at(const pilempm::Table& t, const std::string& name, std::size_t row) {
    for (std::size_t k = 0; k < t.columns.size(); ++k)
        if (t.columns[k] == name) return t.data[k][row];
    ADD_FAILURE() << "no column " << name;
    return 0.0;
}

}  // namespace

TEST(BlowTable, EachBlowsSetAndPeaksComeFromItsOwnRows) {
    const auto history = drive_history();
    const auto blows = pc::blow_table(history, drive_extremes(history), {{2, 1}, {4, 2}, {6, 3}}, 6.0);
    ASSERT_EQ(blows.rows(), 2u);  // blow 3 never ran
    EXPECT_DOUBLE_EQ(at(blows, "start_time_s", 1), 1.0);
    EXPECT_NEAR(at(blows, "duration_s", 1), 0.02, 1e-15);
    EXPECT_DOUBLE_EQ(at(blows, "toe_depth_before_m", 0), 1.0);
    EXPECT_NEAR(at(blows, "set_m", 0), 0.1, 1e-12);
    EXPECT_NEAR(at(blows, "toe_depth_m", 1), 1.2, 1e-12);
    // The pause settled the toe 0.01 m: the next blow's set takes it (from 4.90, not 4.89).
    EXPECT_NEAR(at(blows, "toe_depth_before_m", 1), 1.1, 1e-12);
    EXPECT_NEAR(at(blows, "set_m", 1), 0.1, 1e-12);
    EXPECT_NEAR(at(blows, "max_head_displacement_m", 1), 0.05, 1e-12);  // 0.11 against 0.06 before it
    EXPECT_DOUBLE_EQ(at(blows, "max_head_force_N", 0), 3e6);
    EXPECT_DOUBLE_EQ(at(blows, "enthru_J", 0), 1000.0);
    EXPECT_DOUBLE_EQ(at(blows, "max_compression_Pa", 0), 150e6);
    EXPECT_DOUBLE_EQ(at(blows, "max_tension_Pa", 1), 10e6);
    EXPECT_DOUBLE_EQ(at(blows, "max_shaft_resistance_N", 1), 70.0);
    EXPECT_DOUBLE_EQ(at(blows, "max_base_resistance_N", 0), 300.0);
    EXPECT_DOUBLE_EQ(at(blows, "min_toe_pore_pressure_Pa", 0), -2e4);
    EXPECT_DOUBLE_EQ(at(blows, "plug_length_m", 1), 1.1);
    // The ledger: energy radiated in the blow (from the row before it), the rest at its end.
    EXPECT_DOUBLE_EQ(at(blows, "radiated_energy_J", 0), 70.0);
    EXPECT_DOUBLE_EQ(at(blows, "radiated_energy_J", 1), 40.0);  // 115 against 75 before it
    EXPECT_DOUBLE_EQ(at(blows, "pile_energy_end_J", 0), 20.0);
    EXPECT_DOUBLE_EQ(at(blows, "soil_kinetic_energy_end_J", 1), 4.0);
    EXPECT_DOUBLE_EQ(at(blows, "soil_mass_kg", 1), 100.0);
    EXPECT_DOUBLE_EQ(at(blows, "soil_volume_m3", 0), 10.1);
    EXPECT_DOUBLE_EQ(at(blows, "pore_water_volume_m3", 1), 4.2);
    // Drift since the history's first row: the grains' volume (soil - water) 6 -> 6 (none).
    EXPECT_DOUBLE_EQ(at(blows, "soil_mass_change", 1), 0.0);
    EXPECT_NEAR(at(blows, "grain_volume_change", 1), 0.0, 1e-15);
    // The shaft's pore pressure per third, largest and smallest over the blow's own rows.
    EXPECT_DOUBLE_EQ(at(blows, "max_shaft_pore_pressure_upper_Pa", 0), 4e3);
    EXPECT_DOUBLE_EQ(at(blows, "min_shaft_pore_pressure_upper_Pa", 0), -7e3);
    EXPECT_DOUBLE_EQ(at(blows, "max_shaft_pore_pressure_middle_Pa", 0), 8e3);
    EXPECT_DOUBLE_EQ(at(blows, "min_shaft_pore_pressure_middle_Pa", 1), 5e3);
    EXPECT_DOUBLE_EQ(at(blows, "max_shaft_pore_pressure_lower_Pa", 1), 4e4);
    EXPECT_DOUBLE_EQ(at(blows, "min_shaft_pore_pressure_lower_Pa", 1), -3e4);
}

// A history that stored a blow's rows sparsely: its peaks are its extremes over every step,
// not the stored rows' (here the head force peaked at 5 MN between two stored rows), and a
// blow not finished yet (no extremes) is left out.
TEST(BlowTable, APeakBetweenStoredRowsComesFromTheStagesExtremes) {
    const auto history = drive_history();
    auto extremes = drive_extremes(history);
    for (std::size_t r = 0; r < extremes.rows(); ++r)
        if (extremes.data[0][r] == 2.0)
            for (std::size_t k = 0; k < extremes.columns.size(); ++k)
                if (extremes.columns[k] == "max_pile_head_force_N") extremes.data[k][r] = 5e6;
    auto blows = pc::blow_table(history, extremes, {{2, 1}, {4, 2}}, 6.0);
    ASSERT_EQ(blows.rows(), 2u);
    EXPECT_DOUBLE_EQ(at(blows, "max_head_force_N", 0), 5e6);
    EXPECT_DOUBLE_EQ(at(blows, "max_head_force_N", 1), 2e6);
    blows = pc::blow_table(history, pc::extremes_of_history(history, 4), {{2, 1}, {4, 2}}, 6.0);
    EXPECT_EQ(blows.rows(), 1u);
}

// The extremes of a history by stage; those of the stage under way apart.
TEST(HistoryExtremes, EachStageRowHoldsItsRowsLargestAndSmallest) {
    const auto history = drive_history();
    std::vector<double> max, min;
    const auto e = pc::extremes_of_history(history, 4, &max, &min);
    ASSERT_EQ(e.rows(), 3u);
    EXPECT_DOUBLE_EQ(at(e, "stage", 1), 2.0);
    EXPECT_DOUBLE_EQ(at(e, "max_pile_head_velocity_m_s", 1), 2.0);
    EXPECT_DOUBLE_EQ(at(e, "min_pile_head_velocity_m_s", 1), -0.5);
    EXPECT_DOUBLE_EQ(at(e, "max_shaft_resistance_N", 1), 60.0);
    EXPECT_DOUBLE_EQ(at(e, "min_plug_length_m", 2), 1.05);
    ASSERT_EQ(max.size(), history.columns.size());  // stage 4's two rows, every column
    EXPECT_DOUBLE_EQ(max[2], 4.0);
    EXPECT_DOUBLE_EQ(min[history.columns.size() - 1], 30.0);
}

TEST(BlowTable, TheBlowCountCountsEachBlowWhereItEnds) {
    pilempm::Table blows("blows", {"toe_depth_before_m", "toe_depth_m"});
    // From 1.0 m: four blows of 0.1 m, then six of 0.04 m: 1.1 1.2 | 1.3 1.4 1.44 1.48 | 1.52 ... 1.64.
    double d = 1.0;
    for (int k = 0; k < 10; ++k) {
        const double set = k < 4 ? 0.1 : 0.04;
        blows.add_row({d, d + set});
        d += set;
    }
    const auto count = pc::blow_count_table(blows, 0.25);
    ASSERT_EQ(count.rows(), 3u);  // 1.0-1.25, 1.25-1.5, 1.5-1.75
    EXPECT_DOUBLE_EQ(at(count, "blows", 0), 2.0);  // 1.1, 1.2
    EXPECT_DOUBLE_EQ(at(count, "blows", 1), 4.0);
    EXPECT_DOUBLE_EQ(at(count, "blows", 2), 4.0);
    EXPECT_DOUBLE_EQ(at(count, "depth_bottom_m", 2), 1.75);
    EXPECT_DOUBLE_EQ(at(count, "blows_per_m", 0), 8.0);
    EXPECT_DOUBLE_EQ(at(count, "cumulative_blows", 2), 10.0);
    EXPECT_THROW(pc::blow_count_table(blows, 0.0), std::invalid_argument);
}
