#pragma once
// A small reader for gesmi's CSV files (docs/formats.md): a header line of column
// names, then rows of fields separated by commas (or, for logger exports read through
// a column map, semicolons, tabs or runs of blanks). No quoting; spaces around a field
// and a final '\r' (CRLF files) are ignored; blank lines are skipped. Every error is
// one FormatError "FILE:LINE: field: reason".
//
//   CsvReader csv(in, "marks.csv");
//   csv.read_header({"time", "mine", "range", "side"});
//   while (csv.next()) double t = csv.number(0);

#include <cstddef>
#include <initializer_list>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gesmi::io {

enum class Delimiter { comma, semicolon, tab, whitespace };

/// ",", ";", "tab" (or a tab), "whitespace" (or " "): the delimiter; nullopt otherwise.
std::optional<Delimiter> parse_delimiter(std::string_view text);
/// The delimiter a header line uses: ';' if it has one, else a tab, else ',', else blanks.
Delimiter detect_delimiter(std::string_view header);

class CsvReader {
 public:
  CsvReader(std::istream& in, std::string name, Delimiter delimiter = Delimiter::comma);

  /// Reads the header: it must start with `required`, in that order; the columns
  /// after them must be among `optional`, each at most once. Returns the header's
  /// column names.
  const std::vector<std::string>& read_header(std::initializer_list<std::string_view> required,
                                              std::initializer_list<std::string_view> optional = {});

  /// Reads a header of any names, each at most once (a logger export read through a
  /// column map); its delimiter is `declared`, or else detected from the line.
  const std::vector<std::string>& read_any_header(std::optional<Delimiter> declared);

  /// Moves to the next non-blank row; false at the end of the file. A row with
  /// fewer or more fields than the header is an error naming the first missing
  /// column (or the extra field).
  bool next();

  std::size_t line() const { return line_; }
  const std::string& name() const { return name_; }
  /// Column of `column_name` in the header, or -1.
  int column(std::string_view column_name) const;

  /// The field of the current row (spaces trimmed).
  std::string_view text(std::size_t column) const { return fields_[column]; }
  /// The field as a finite number; errors name the column ("missing value",
  /// "expected a number, found 'x'", "is NaN", "is infinite").
  double number(std::size_t column) const;
  /// The field as a number that may be NaN or infinite.
  double any_number(std::size_t column) const;

  /// Throws "FILE:LINE: <column name>: reason".
  [[noreturn]] void fail(std::size_t column, const std::string& reason) const;
  /// Throws "FILE:LINE: what".
  [[noreturn]] void fail_line(const std::string& what) const;

 private:
  std::istream& in_;
  std::string name_;
  Delimiter delimiter_;
  std::vector<std::string> columns_;
  std::string line_text_;
  std::vector<std::string_view> fields_;
  std::size_t line_ = 0;

  void read_header_line(const std::string& expected);
};

/// Fails at the current row of `csv` unless time > previous (strictly increasing).
void expect_increasing_time(const CsvReader& csv, std::size_t column, double time, double previous, std::size_t previous_line);

}  // namespace gesmi::io
