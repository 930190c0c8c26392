#pragma once
// A linear program's feasible set, {z : row_lower <= A z <= row_upper, column_lower <= z
// <= column_upper}, with A stored by rows (compressed sparse rows). Bounds may be
// infinite; an equality row has equal bounds.

#include <cstddef>
#include <vector>

namespace gesmi {

struct LinearProgram {
  std::size_t columns = 0;
  /// Row i holds the entries row_start[i] to row_start[i + 1] - 1 of `column` and `value`.
  std::vector<std::size_t> row_start{0};
  std::vector<std::size_t> column;
  std::vector<double> value;
  std::vector<double> row_lower, row_upper;
  std::vector<double> column_lower, column_upper;

  std::size_t rows() const { return row_lower.size(); }
  /// Appends the row lower <= sum of coefficients[k] z[columns[k]] <= upper.
  void add_row(const std::vector<std::size_t>& columns_of_row, const std::vector<double>& coefficients, double lower,
               double upper) {
    column.insert(column.end(), columns_of_row.begin(), columns_of_row.end());
    value.insert(value.end(), coefficients.begin(), coefficients.end());
    row_start.push_back(column.size());
    row_lower.push_back(lower);
    row_upper.push_back(upper);
  }
};

}  // namespace gesmi
