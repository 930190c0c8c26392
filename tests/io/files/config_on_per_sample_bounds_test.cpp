// A --config key on a mission that bounds some sensors per sample (io/files/
// mission_file.h, change_model): applied where nothing per sample depends on it, refused
// with the true reason where something does — the log's own half-widths replace the
// model's bound, or the import filled samples from that key, which only a new import redoes.

#include <gtest/gtest.h>

#include <string>

#include "io/files/mission_file.h"
#include "io/format_error.h"
#include "io/geodesy.h"
#include "tests/support/tiny_mission.h"

namespace gesmi::io {
namespace {

// The tiny mission with its fixes in latitude and longitude, as a file gives them.
Mission tiny() {
  Mission m = test::make_tiny_mission(1, test::TinyErrors::uniform).mission;
  m.origin = {48.2, -4.4};
  set_geodetic_gps(m);
  return m;
}

std::string refusal(Mission m, const SensorModel& model) {
  try {
    change_model(m, model, "bounds.yaml");
  } catch (const FormatError& e) {
    return e.what();
  }
  return "";
}

// A mission whose attitude bounds are the log's own, per sample (a GESMI text log's).
Mission with_logged_attitude_bounds() {
  Mission m = tiny();
  for (auto* h : {&m.half_widths.roll, &m.half_widths.pitch, &m.half_widths.heading}) h->assign(m.size(), 1e-3);
  return m;
}

TEST(ConfigOnPerSampleBounds, ARateTheLogsOwnBoundsDoNotDependOnIsApplied) {
  Mission m = with_logged_attitude_bounds();
  SensorModel model = m.model;
  model.max_attitude_rate = 0.08;
  EXPECT_NO_THROW(change_model(m, model, "bounds.yaml"));
  EXPECT_EQ(m.model.max_attitude_rate, 0.08);
}

TEST(ConfigOnPerSampleBounds, ABoundTheLogGivesPerSampleIsRefusedAsSuch) {
  SensorModel model = with_logged_attitude_bounds().model;
  model.roll = 1e-3;
  const std::string why = refusal(with_logged_attitude_bounds(), model);
  EXPECT_NE(why.find("bounds.yaml: roll: the log gives roll its own bound per sample"), std::string::npos) << why;
}

TEST(ConfigOnPerSampleBounds, AKeyTheImportFilledSamplesWithIsRefusedNamingThem) {
  Mission m = tiny();
  m.half_widths.depth.assign(m.size(), 2.0);
  m.half_widths.fill[7] = ChannelFill{"max_depth_rate", 0, 7, 2, 0.0, 1.0};
  for (auto* h : {&m.half_widths.vx, &m.half_widths.vy, &m.half_widths.vz}) h->assign(m.size(), 0.01);
  for (std::size_t c : {3u, 4u, 5u}) m.half_widths.fill[c] = ChannelFill{"surface_max_speed", 3, 0, 0, 0.0, 1.0};
  for (const char* key : {"max_depth_rate", "surface_max_speed", "dvl_relative", "depth_absolute"}) {
    SensorModel model = m.model;
    if (std::string(key) == "max_depth_rate") model.max_depth_rate = 0.3;
    if (std::string(key) == "surface_max_speed") model.surface_max_speed = 8.0;
    if (std::string(key) == "dvl_relative") model.dvl_relative = 0.01;
    if (std::string(key) == "depth_absolute") model.depth_absolute = 2.0;
    const std::string why = refusal(m, model);
    EXPECT_NE(why.find(std::string("bounds.yaml: ") + key + ": the import filled"), std::string::npos) << why;
    EXPECT_NE(why.find("import the log again with --config"), std::string::npos) << why;
  }
  // A rate key of a channel the import did not fill is applied.
  SensorModel model = m.model;
  model.max_attitude_rate = 0.08;
  EXPECT_EQ(refusal(m, model), "");
}

TEST(ConfigOnPerSampleBounds, AMissionFileThatDidNotRecordItsFillsRefusesAsBefore) {
  Mission m = with_logged_attitude_bounds();
  m.half_widths.fill_recorded = false;  // a file of format 3 or older
  SensorModel model = m.model;
  model.max_attitude_rate = 0.08;
  const std::string why = refusal(m, model);
  EXPECT_NE(why.find("max_attitude_rate: this mission bounds roll per sample"), std::string::npos) << why;
}

}  // namespace
}  // namespace gesmi::io
