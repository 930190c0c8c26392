#include "io/imports/csv_reader.h"

#include <algorithm>

#include "io/text/csv_number.h"
#include "io/format_error.h"
#include "io/text/message_text.h"

namespace gesmi::io {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

void split(std::string_view line, Delimiter delimiter, std::vector<std::string_view>& fields) {
  fields.clear();
  if (delimiter == Delimiter::whitespace) {
    line = trim(line);
    std::size_t start = 0;
    while (start < line.size()) {
      std::size_t end = line.find_first_of(" \t", start);
      if (end == std::string_view::npos) end = line.size();
      fields.push_back(line.substr(start, end - start));
      start = line.find_first_not_of(" \t", end);
      if (start == std::string_view::npos) break;
    }
    if (fields.empty()) fields.push_back({});
    return;
  }
  const char separator = delimiter == Delimiter::semicolon ? ';' : delimiter == Delimiter::tab ? '\t' : ',';
  std::size_t start = 0;
  while (true) {
    const std::size_t at = line.find(separator, start);
    fields.push_back(trim(line.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start)));
    if (at == std::string_view::npos) return;
    start = at + 1;
  }
}

std::string joined(std::initializer_list<std::string_view> names) {
  std::string out;
  for (const std::string_view n : names) out += (out.empty() ? "" : ",") + std::string(n);
  return out;
}

}  // namespace

std::optional<Delimiter> parse_delimiter(std::string_view text) {
  if (text == ",") return Delimiter::comma;
  if (text == ";") return Delimiter::semicolon;
  if (text == "\t" || text == "tab") return Delimiter::tab;
  if (text == " " || text == "whitespace") return Delimiter::whitespace;
  return std::nullopt;
}

Delimiter detect_delimiter(std::string_view header) {
  if (header.find(';') != std::string_view::npos) return Delimiter::semicolon;
  if (header.find('\t') != std::string_view::npos) return Delimiter::tab;
  if (header.find(',') != std::string_view::npos) return Delimiter::comma;
  return Delimiter::whitespace;
}

CsvReader::CsvReader(std::istream& in, std::string name, Delimiter delimiter)
    : in_(in), name_(std::move(name)), delimiter_(delimiter) {}

void CsvReader::fail_line(const std::string& what) const {
  throw FormatError(name_ + ":" + std::to_string(line_) + ": " + what);
}

void CsvReader::fail(std::size_t column, const std::string& reason) const {
  fail_line((column < columns_.size() ? columns_[column] : "column " + std::to_string(column + 1)) + ": " + reason);
}

const std::vector<std::string>& CsvReader::read_header(std::initializer_list<std::string_view> required,
                                                       std::initializer_list<std::string_view> optional) {
  const std::string expected = joined(required);
  read_header_line("expected the header '" + expected + "'");
  split(line_text_, delimiter_, fields_);
  bool ok = fields_.size() >= required.size() && std::equal(required.begin(), required.end(), fields_.begin());
  for (std::size_t i = required.size(); ok && i < fields_.size(); ++i) {
    const bool known = std::find(optional.begin(), optional.end(), fields_[i]) != optional.end();
    const bool repeated = std::find(fields_.begin() + static_cast<std::ptrdiff_t>(required.size()),
                                    fields_.begin() + static_cast<std::ptrdiff_t>(i), fields_[i]) !=
                          fields_.begin() + static_cast<std::ptrdiff_t>(i);
    ok = known && !repeated;
  }
  if (!ok) {
    std::string wanted = "expected '" + expected + "'";
    if (optional.size() > 0) wanted += " then optional columns among " + joined(optional);
    fail_line("header: " + wanted + ", found " + quoted_input(trim(line_text_)));
  }
  columns_.assign(fields_.begin(), fields_.end());
  return columns_;
}

void CsvReader::read_header_line(const std::string& expected) {
  while (std::getline(in_, line_text_)) {
    ++line_;
    if (!trim(line_text_).empty()) break;
  }
  if (line_ == 0 || trim(line_text_).empty()) {
    line_ = std::max<std::size_t>(line_, 1);
    fail_line("header: the file is empty (" + expected + ")");
  }
  // A UTF-8 byte order mark (spreadsheet exports) is not part of the first name.
  if (line_ == 1 && line_text_.rfind("\xEF\xBB\xBF", 0) == 0) line_text_.erase(0, 3);
}

const std::vector<std::string>& CsvReader::read_any_header(std::optional<Delimiter> declared) {
  read_header_line("expected a header line of column names");
  delimiter_ = declared ? *declared : detect_delimiter(trim(line_text_));
  split(line_text_, delimiter_, fields_);
  for (std::size_t i = 0; i < fields_.size(); ++i) {
    if (fields_[i].empty()) fail_line("header: column " + std::to_string(i + 1) + " has no name");
    if (std::find(fields_.begin(), fields_.begin() + static_cast<std::ptrdiff_t>(i), fields_[i]) !=
        fields_.begin() + static_cast<std::ptrdiff_t>(i))
      fail_line("header: column " + quoted_input(fields_[i]) + " appears twice");
  }
  columns_.assign(fields_.begin(), fields_.end());
  return columns_;
}

bool CsvReader::next() {
  while (std::getline(in_, line_text_)) {
    ++line_;
    if (trim(line_text_).empty()) continue;
    split(line_text_, delimiter_, fields_);
    if (fields_.size() < columns_.size())
      fail(fields_.size(), "missing column (expected " + std::to_string(columns_.size()) + " fields, found " +
                               std::to_string(fields_.size()) + ")");
    if (fields_.size() > columns_.size())
      fail_line("expected " + std::to_string(columns_.size()) + " fields, found " + std::to_string(fields_.size()) +
                " (extra field " + quoted_input(fields_[columns_.size()]) + ")");
    return true;
  }
  if (in_.bad()) fail_line("read error");
  return false;
}

int CsvReader::column(std::string_view column_name) const {
  const auto found = std::find(columns_.begin(), columns_.end(), column_name);
  return found == columns_.end() ? -1 : static_cast<int>(found - columns_.begin());
}

double CsvReader::any_number(std::size_t column) const {
  const std::string_view field = fields_[column];
  if (field.empty()) fail(column, "missing value");
  const std::optional<double> value = parse_number(field);
  if (!value) fail(column, "expected a number, found " + quoted_input(field));
  return *value;
}

double CsvReader::number(std::size_t column) const {
  const double value = any_number(column);
  if (const std::string_view why = non_finite_reason(value); !why.empty()) fail(column, std::string(why));
  return value;
}

void expect_increasing_time(const CsvReader& csv, std::size_t column, double time, double previous,
                            std::size_t previous_line) {
  if (!(time > previous))
    csv.fail(column, format_number(time) + " s does not increase (" + format_number(previous) + " s on line " +
                         std::to_string(previous_line) + ")");
}

}  // namespace gesmi::io
