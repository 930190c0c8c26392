// NMEA 0183 fixes (io/imports/import_nmea.h) on the textbook sentences (whose
// checksums come from the NMEA documentation, not from this parser), dates across
// midnight, and every refusal.
#include "io/imports/import_nmea.h"

#include <gtest/gtest.h>

#include "tests/support/timegm_oracle.h"

#include <sstream>

#include "io/exports/export_logger.h"
#include "io/format_error.h"

namespace gesmi::io {
namespace {

// The classic example pair: 12:35:19 UTC on 23 March 1994 at 48°07.038' N 11°31.000' E.
constexpr const char* kRmc = "$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W*6A";
constexpr const char* kGga = "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47";

using test::timegm_seconds;

NmeaFixes fixes_of(const std::string& text, std::optional<std::int64_t> date = std::nullopt) {
  std::istringstream in(text);
  return read_nmea(in, "gps.nmea", date);
}

std::string nmea_error(const std::string& text, std::optional<std::int64_t> date = std::nullopt) {
  try {
    fixes_of(text, date);
  } catch (const FormatError& e) {
    return e.what();
  }
  return "";
}

TEST(Nmea, TheTextbookPairGivesItsFix) {
  const NmeaFixes f = fixes_of(std::string(kRmc) + "\r\n" + kGga + "\r\n");
  ASSERT_EQ(f.time.size(), 1u);
  EXPECT_EQ(f.time[0].seconds, timegm_seconds(1994, 3, 23, 12, 35, 19));
  EXPECT_EQ(f.time[0].fraction, 0.0);
  EXPECT_DOUBLE_EQ(f.latitude[0], 48.0 + 7.038 / 60.0);
  EXPECT_DOUBLE_EQ(f.longitude[0], 11.0 + 31.0 / 60.0);
  EXPECT_EQ(f.line[0], 2u);
  EXPECT_EQ(f.rmc, 1u);
  EXPECT_EQ(f.bad_checksum, 0u);
}

TEST(Nmea, BadChecksumsAreSkippedAndCounted) {
  std::string gga = kGga;
  gga.back() = '8';  // *48
  std::string altered = kGga;
  altered[10] = '6';  // a digit of the time changed, checksum kept
  const NmeaFixes f =
      fixes_of(std::string(kRmc) + "\n" + gga + "\n" + altered + "\n" + "$GPGGA,123519,4807.038,N\n" + kGga + "\n");
  EXPECT_EQ(f.bad_checksum, 3u);
  ASSERT_EQ(f.time.size(), 1u);
  EXPECT_EQ(f.line[0], 5u);
}

TEST(Nmea, NoFixQualityOtherSentencesAndSouthWest) {
  const std::string no_fix = nmea_sentence("GPGGA,123520,,,,,0,00,,,M,,M,,");
  const std::string dead_reckoning = nmea_sentence("GPGGA,123520.5,4807.038,N,01131.000,E,6,00,,,M,,M,,");
  const std::string south_west = nmea_sentence("GNGGA,123521.25,3345.5000,S,07030.0000,W,2,10,0.8,1.0,M,0.0,M,,");
  const std::string other = nmea_sentence("GPVTG,054.7,T,034.4,M,005.5,N,010.2,K");
  const NmeaFixes f = fixes_of("\xEF\xBB\xBF" + std::string(kRmc) + "\n" + no_fix + "\n" + dead_reckoning + "\n" +
                               other + "\n" + south_west + "\n");
  EXPECT_EQ(f.no_fix, 2u);
  EXPECT_EQ(f.other, 1u);
  ASSERT_EQ(f.time.size(), 1u);
  EXPECT_EQ(f.time[0].seconds, timegm_seconds(1994, 3, 23, 12, 35, 21));
  EXPECT_EQ(f.time[0].fraction, 0.25);
  EXPECT_DOUBLE_EQ(f.latitude[0], -(33.0 + 45.5 / 60.0));
  EXPECT_DOUBLE_EQ(f.longitude[0], -(70.0 + 30.0 / 60.0));
}

TEST(Nmea, DatesCrossMidnightBothWays) {
  // RMC at 23:59:59 on 31 Dec 2025, then a GGA at 00:00:01: 1 Jan 2026.
  const std::string rmc = nmea_sentence("GPRMC,235959,A,4807.038,N,01131.000,E,0.0,0.0,311225,,,A");
  const std::string after = nmea_sentence("GPGGA,000001,4807.038,N,01131.000,E,1,08,0.9,0.0,M,0.0,M,,");
  const std::string before = nmea_sentence("GPGGA,235958,4807.038,N,01131.000,E,1,08,0.9,0.0,M,0.0,M,,");
  NmeaFixes f = fixes_of(before + "\n" + rmc + "\n" + after + "\n");
  ASSERT_EQ(f.time.size(), 2u);
  EXPECT_EQ(f.time[0].seconds, timegm_seconds(2025, 12, 31, 23, 59, 58));  // dated by the first RMC after it
  EXPECT_EQ(f.time[1].seconds, timegm_seconds(2026, 1, 1, 0, 0, 1));
  // Without RMC, --date dates the first fix and the time of day falling back is midnight.
  f = fixes_of(before + "\n" + after + "\n", timegm_seconds(2025, 12, 31, 0, 0, 0) / 86400);
  ASSERT_EQ(f.time.size(), 2u);
  EXPECT_EQ(f.time[0].seconds, timegm_seconds(2025, 12, 31, 23, 59, 58));
  EXPECT_EQ(f.time[1].seconds, timegm_seconds(2026, 1, 1, 0, 0, 1));
}

TEST(Nmea, DetectedFromTheFirstSentenceEvenAfterAByteOrderMark) {
  std::istringstream bom("\xEF\xBB\xBF" + std::string(kRmc) + "\n"), blank_first("\n  \n" + std::string(kGga)),
      csv("time,longitude,latitude\n0,1,2\n");
  EXPECT_TRUE(looks_like_nmea(bom));
  EXPECT_TRUE(looks_like_nmea(blank_first));
  EXPECT_FALSE(looks_like_nmea(csv));
}

TEST(Nmea, RefusalsNameTheLineAndTheField) {
  EXPECT_NE(nmea_error(std::string(kGga) + "\n").find("--date"), std::string::npos);
  EXPECT_NE(nmea_error("hello\n").find("gps.nmea:1: not an NMEA sentence"), std::string::npos);
  const auto field_error = [](const std::string& body) {
    return nmea_error(std::string(kRmc) + "\n" + nmea_sentence(body) + "\n");
  };
  EXPECT_NE(field_error("GPGGA,12351,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,").find("gps.nmea:2: GPGGA field 1"),
            std::string::npos);
  EXPECT_NE(field_error("GPGGA,123519,4867.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,").find("field 2: minutes"),
            std::string::npos);
  EXPECT_NE(field_error("GPGGA,123519,9107.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,").find("field 2"), std::string::npos);
  EXPECT_NE(field_error("GPGGA,123519,4807.038,X,01131.000,E,1,08,0.9,545.4,M,46.9,M,,").find("field 3"), std::string::npos);
  EXPECT_NE(field_error("GPGGA,123519,4807.038,N,1131.000,E,1,08,0.9,545.4,M,46.9,M,,").find("field 4"), std::string::npos);
  EXPECT_NE(field_error("GPGGA,123519,4807.038,N,01131.000,E,x,08").find("field 6"), std::string::npos);
  EXPECT_NE(field_error("GPGGA,123519,4807.038,N,01131.000,E,9,08").find("field 6"), std::string::npos);
  EXPECT_NE(field_error("GPGGA,123519,4807.038,N,01131.000,E").find("field 6: missing"), std::string::npos);
  EXPECT_NE(field_error("GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,300294,003.1,W").find("field 9: the date"),
            std::string::npos);
  EXPECT_NE(field_error("GPGGA,246060,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,").find("does not exist"),
            std::string::npos);
}

}  // namespace
}  // namespace gesmi::io
