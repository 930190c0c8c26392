// The pictures are written atomically as valid PNG files.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/format_error.h"
#include "io/plot/plot_envelope.h"
#include "io/plot/plot_waterfall.h"
#include "solver/solve/solve_mission.h"
#include "tests/support/run_command.h"
#include "tests/support/tiny_mission.h"

namespace gesmi {
namespace {

bool is_png(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char sig[8] = {};
  in.read(sig, 8);
  return in && std::string(sig, 8) == std::string("\x89PNG\r\n\x1a\n", 8);
}

struct Solved {
  test::TinyMission tiny = test::make_tiny_mission(8, test::TinyErrors::uniform);
  TubeDomains domains = solve_mission(tiny.mission).domains;
};

TEST(Plot, WritesTheEnvelopeAndTheWaterfallAsPng) {
  const Solved s;
  const std::string folder = test::temp_folder("plot");
  io::EnvelopePicture envelope;
  envelope.domains = &s.domains;
  envelope.mission = &s.tiny.mission;
  for (const PositionFix& f : s.tiny.fixes) envelope.fix_boxes.push_back(f.box);
  envelope.title = "tiny mission";
  io::write_envelope_png(envelope, folder + "/envelope.png");
  EXPECT_TRUE(is_png(folder + "/envelope.png"));

  const Waterfall w = compute_waterfall(s.tiny.mission, s.tiny.mission.model, s.domains);
  io::WaterfallPicture picture;
  picture.waterfall = &w;
  picture.time = s.tiny.mission.time;
  for (std::size_t j = 0; j < s.tiny.mission.mark_count(); ++j)
    picture.marks.push_back({s.tiny.mission.mark_time[j], s.tiny.mission.mark_range[j], s.tiny.mission.mark_mine[j]});
  io::write_waterfall_png(picture, folder + "/waterfall.png");
  EXPECT_TRUE(is_png(folder + "/waterfall.png"));
  // Only the two pictures: no temporary file left behind.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()), 2);
}

TEST(Plot, ReportsAnUnwritableFolderAndLeavesNothing) {
  const Solved s;
  io::EnvelopePicture envelope;
  envelope.domains = &s.domains;
  EXPECT_THROW(io::write_envelope_png(envelope, "/nonexistent-folder/envelope.png"), io::FormatError);
}

}  // namespace
}  // namespace gesmi
