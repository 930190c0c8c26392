// The pictures are written atomically as valid PNG files, whose pixels Pillow (an
// independent decoder) reads as drawn.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "io/format_error.h"
#include "io/plot/canvas.h"
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

TEST(Plot, PixelsAreWrittenInTheirColoursRowByRow) {
  // Three primaries and a mixed colour in separate boxes on white, in a picture whose
  // rows are not a multiple of anything in particular (odd width and height).
  const std::string path = test::temp_folder("plot-pixels") + "/canvas.png";
  {
    io::Canvas canvas(203, 151);
    canvas.fill_rect(10, 10, 20, 20, io::Rgb{1, 0, 0});
    canvas.fill_rect(50, 10, 20, 20, io::Rgb{0, 1, 0});
    canvas.fill_rect(90, 10, 20, 20, io::Rgb{0, 0, 1});
    canvas.fill_rect(150, 120, 40, 25, io::Rgb{1, 1, 0});
    canvas.save_png(path);
  }
  // x, y, expected R, G, B (0-255) of the pixels Pillow reads.
  const std::string script = test::temp_folder("plot-pixels-check") + "/check.py";
  std::ofstream(script) << "import sys\nfrom PIL import Image\n"
                           "im = Image.open(sys.argv[1]).convert('RGB')\n"
                           "want = [(20, 20, (255, 0, 0)), (60, 20, (0, 255, 0)), (100, 20, (0, 0, 255)),\n"
                           "        (170, 140, (255, 255, 0)), (0, 0, (255, 255, 255)), (202, 150, (255, 255, 255)),\n"
                           "        (40, 100, (255, 255, 255))]\n"
                           "bad = [(x, y, im.getpixel((x, y)), c) for x, y, c in want if im.getpixel((x, y)) != c]\n"
                           "print(im.size, bad)\n"
                           "sys.exit(0 if im.size == (203, 151) and not bad else 1)\n";
  EXPECT_EQ(std::system(("/usr/bin/python3 " + script + " " + path).c_str()), 0);
}

TEST(Plot, ReportsAnUnwritableFolderAndLeavesNothing) {
  const Solved s;
  io::EnvelopePicture envelope;
  envelope.domains = &s.domains;
  EXPECT_THROW(io::write_envelope_png(envelope, "/nonexistent-folder/envelope.png"), io::FormatError);
}

}  // namespace
}  // namespace gesmi
