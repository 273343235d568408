#pragma once
// A named table of columns of doubles: the form every time series and profile takes on
// its way to CSV, HDF5 and the plots.
#include <cstddef>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

namespace pilempm {

struct Table {
    std::string name;                       // e.g. "pile_head" -> pile_head.csv, /pile_head in HDF5
    std::vector<std::string> columns;       // with units and sign in the name
    std::vector<std::vector<double>> data;  // data[column][row]

    Table() = default;
    Table(std::string table_name, std::vector<std::string> column_names)
        : name(std::move(table_name)), columns(std::move(column_names)), data(columns.size()) {}

    void add_row(std::initializer_list<double> row) {
        if (row.size() != columns.size()) throw std::logic_error("row size differs from columns");
        std::size_t c = 0;
        for (double v : row) data[c++].push_back(v);
    }
    std::size_t rows() const { return data.empty() ? 0 : data.front().size(); }
    // The column named `column_name`; throws (naming the table) when it has none.
    const std::vector<double>& column(const std::string& column_name) const {
        for (std::size_t k = 0; k < columns.size(); ++k)
            if (columns[k] == column_name) return data[k];
        throw std::runtime_error("the " + name + " table has no column " + column_name);
    }
};

}  // namespace pilempm
