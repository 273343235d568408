#pragma once
// Each stage's extremes of the history's columns: the largest and smallest value of every
// column over every row sampled in the stage, whether the history stored it or not. A
// decimated history (StageSpec::record_every) then still gives a blow's exact peaks.
// The table: "stage" (1-based, as the history's), then max_<column> for each column after
// the history's first three (time_s, step, stage), then min_<column>.
#include <string>
#include <vector>

#include "core/table.hpp"

namespace pilempm::coupling {

// An empty extremes table for a history with these columns.
Table empty_extremes(const std::vector<std::string>& history_columns);

// Folds a sampled history row into a stage's running extremes (empty: the stage's first).
void fold_extremes(const std::vector<double>& row, std::vector<double>& max, std::vector<double>& min);

// Appends a stage's row from its running extremes (NaN where it sampled no row).
void add_extremes_row(Table& extremes, int stage, const std::vector<double>& max, const std::vector<double>& min);

// The extremes of a history that stored every row it sampled, for the stages with a number
// below `before_stage` (1-based; the rest go to `running_max` / `running_min` when given):
// what a run keeps as it goes, for a history held whole (a blow table's input in tests).
Table extremes_of_history(const Table& history, int before_stage, std::vector<double>* running_max = nullptr,
                          std::vector<double>* running_min = nullptr);

}  // namespace pilempm::coupling
