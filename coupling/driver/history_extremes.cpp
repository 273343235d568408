#include "coupling/driver/history_extremes.hpp"

#include <algorithm>
#include <limits>

namespace pilempm::coupling {

namespace {
constexpr std::size_t kLeading = 3;  // time_s, step, stage: no extremes
}

Table empty_extremes(const std::vector<std::string>& history_columns) {
    std::vector<std::string> columns = {"stage"};
    for (const char* prefix : {"max_", "min_"})
        for (std::size_t k = kLeading; k < history_columns.size(); ++k) columns.push_back(prefix + history_columns[k]);
    return Table("stage_extremes", std::move(columns));
}

void fold_extremes(const std::vector<double>& row, std::vector<double>& max, std::vector<double>& min) {
    if (max.empty()) {
        max = row;
        min = row;
        return;
    }
    for (std::size_t k = 0; k < row.size(); ++k) {
        max[k] = std::max(max[k], row[k]);
        min[k] = std::min(min[k], row[k]);
    }
}

void add_extremes_row(Table& extremes, int stage, const std::vector<double>& max, const std::vector<double>& min) {
    const std::size_t n = (extremes.columns.size() - 1) / 2;
    extremes.data[0].push_back(static_cast<double>(stage));
    for (std::size_t k = 0; k < n; ++k) {
        const bool sampled = kLeading + k < max.size();
        extremes.data[1 + k].push_back(sampled ? max[kLeading + k] : std::numeric_limits<double>::quiet_NaN());
        extremes.data[1 + n + k].push_back(sampled ? min[kLeading + k] : std::numeric_limits<double>::quiet_NaN());
    }
}

Table extremes_of_history(const Table& history, int before_stage, std::vector<double>* running_max,
                          std::vector<double>* running_min) {
    Table out = empty_extremes(history.columns);
    const auto& stage = history.column("stage");
    std::vector<double> row(history.columns.size()), max, min;
    for (std::size_t i = 0; i < history.rows(); ++i) {
        for (std::size_t k = 0; k < row.size(); ++k) row[k] = history.data[k][i];
        fold_extremes(row, max, min);
        const bool last_of_stage = i + 1 == history.rows() || stage[i + 1] != stage[i];
        if (!last_of_stage) continue;
        if (stage[i] < before_stage) {
            add_extremes_row(out, static_cast<int>(stage[i]), max, min);
        } else {
            if (running_max) *running_max = max;
            if (running_min) *running_min = min;
        }
        max.clear();
        min.clear();
    }
    return out;
}

}  // namespace pilempm::coupling
