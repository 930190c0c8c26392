// docs/formats.md agrees with the code: the sensor model key table is exactly the
// one generated from the list in solver/mission/sensor_model.cpp (sensor_model_fields) (on a mismatch the test
// prints the table to paste between the markers), and the CSV headers the readers
// expect are the ones documented.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io/text/csv_number.h"
#include "io/imports/import_nav_csv.h"
#include "tests/support/paths.h"

namespace gesmi::io {
namespace {

std::string formats_doc() {
  std::ifstream in(test::source_dir() + "/docs/formats.md");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Markdown table cells cannot hold a bare '|'.
std::string cell(std::string_view text) {
  std::string out;
  for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string model_key_table() {
  const SensorModel defaults;
  std::string table = "| key | unit | default | meaning |\n| --- | --- | --- | --- |\n";
  for (const SensorModelField& f : sensor_model_fields())
    table += "| `" + std::string(f.key) + "` | " + std::string(f.unit) + " | " + format_number(defaults.*f.member) +
              " | " + cell(f.meaning) + " |\n";
  for (const SensorModelChoice& c : sensor_model_choices()) {
    std::string names;
    for (const std::string_view n : c.names) names += (names.empty() ? "" : ", ") + ("`" + std::string(n) + "`");
    table += "| `" + std::string(c.key) + "` | – | " + std::string(c.get(defaults)) + " | " + cell(c.meaning) + ": " + names +
             " (a string attribute in HDF5) |\n";
  }
  return table;
}

TEST(FormatsDoc, ModelKeyTableIsGeneratedFromTheFieldList) {
  const std::string doc = formats_doc();
  const std::string begin = "<!-- model-keys:begin (generated: tests/io/files/import_formats_doc_test.cpp) -->\n";
  const std::string end = "<!-- model-keys:end -->";
  const std::size_t from = doc.find(begin), to = doc.find(end);
  ASSERT_NE(from, std::string::npos) << "docs/formats.md lacks the marker " << begin;
  ASSERT_NE(to, std::string::npos);
  const std::string table = doc.substr(from + begin.size(), to - from - begin.size());
  EXPECT_EQ(table, model_key_table()) << "paste this between the markers of docs/formats.md:\n" << model_key_table();
  for (const SensorModelField& f : sensor_model_fields())
    EXPECT_NE(doc.find("`" + std::string(f.key) + "`"), std::string::npos) << f.key;
}

TEST(FormatsDoc, CsvHeadersAreTheOnesTheReadersExpect) {
  const std::string doc = formats_doc();
  for (const char* header : {"time,roll,pitch,heading,vx,vy,vz,altitude,depth", "time,longitude,latitude",
                             "north_halfwidth,east_halfwidth", "time,mine,range,side", "time,north,east,down",
                             "mine,north,east,down",
                             "mine,marks,north_lo,north_hi,east_lo,east_hi,down_lo,down_hi,latitude_lo,latitude_hi,longitude_lo,"
                             "longitude_hi,status",
                             "time,utc,north_lo,north_hi,east_lo,east_hi,down_lo,down_hi,latitude_lo,latitude_hi,longitude_lo,"
                             "longitude_hi,status"})
    EXPECT_NE(doc.find(header), std::string::npos) << header;
  for (const NavHalfWidthColumn& c : nav_half_width_columns())
    EXPECT_NE(doc.find("`" + std::string(c.name) + "`"), std::string::npos) << c.name;
}

}  // namespace
}  // namespace gesmi::io
