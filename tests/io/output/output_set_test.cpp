// io::OutputSet: files appear together at commit, or not at all; a new folder appears
// whole at commit; siblings of an earlier run that this run did not write go; a failed
// outer set takes back what the sets inside it committed.

#include "io/output/output_set.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "io/output/atomic_output.h"
#include "io/format_error.h"
#include "tests/support/run_command.h"

namespace gesmi::io {
namespace {

namespace fs = std::filesystem;

std::size_t files_in(const std::string& folder) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

TEST(OutputSet, FilesAppearOnlyAtCommit) {
  const std::string folder = test::temp_folder("output-set");
  OutputSet set;
  write_text_file(folder + "/a.txt", "a");
  write_text_file(folder + "/b.txt", "b");
  EXPECT_FALSE(fs::exists(folder + "/a.txt"));
  EXPECT_EQ(files_in(folder), 2u);  // the two temporaries
  set.commit();
  EXPECT_TRUE(fs::exists(folder + "/a.txt"));
  EXPECT_TRUE(fs::exists(folder + "/b.txt"));
  EXPECT_EQ(files_in(folder), 2u);
  EXPECT_EQ(set.written(), (std::vector<std::string>{folder + "/a.txt", folder + "/b.txt"}));
}

TEST(OutputSet, WithoutCommitNothingIsLeftAndEarlierFilesStay) {
  const std::string folder = test::temp_folder("output-set");
  std::ofstream(folder + "/a.txt") << "earlier";
  {
    OutputSet set;
    write_text_file(folder + "/a.txt", "new");
    write_text_file(folder + "/b.txt", "new");
  }
  EXPECT_EQ(files_in(folder), 1u);
  std::ifstream in(folder + "/a.txt");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "earlier");
}

TEST(OutputSet, SiblingsOfAnEarlierRunThatThisRunDidNotWriteAreRemoved) {
  const std::string folder = test::temp_folder("output-set");
  std::ofstream(folder + "/r.geojson") << "stale";
  std::ofstream(folder + "/r.mines.csv") << "stale";
  std::ofstream(folder + "/notes.txt") << "the user's";
  OutputSet set;
  set.owns(folder + "/r.geojson");
  set.owns(folder + "/r.mines.csv");
  write_text_file(folder + "/r.h5", "result");
  write_text_file(folder + "/r.mines.csv", "fresh");
  set.commit();
  EXPECT_FALSE(fs::exists(folder + "/r.geojson"));
  EXPECT_TRUE(fs::exists(folder + "/r.mines.csv"));
  EXPECT_TRUE(fs::exists(folder + "/notes.txt"));
}

TEST(OutputSet, AFailedOuterSetTakesBackWhatInnerSetsCommitted) {
  const std::string parent = test::temp_folder("output-set");
  const std::string folder = parent + "/demo";
  {
    OutputSet outer;
    outer.prepare_folder(folder, /*in_place=*/true);
    {
      OutputSet inner;
      write_text_file(folder + "/mission.h5", "m");
      inner.commit();
    }
    EXPECT_TRUE(fs::exists(folder + "/mission.h5"));  // readable by the next step
  }
  EXPECT_FALSE(fs::exists(folder));  // created by the set, empty again, removed
}

TEST(OutputSet, AMissingFolderIsFilledUnderATemporaryNameAndAppearsWholeAtCommit) {
  const std::string parent = test::temp_folder("output-set");
  const std::string folder = parent + "/out";
  OutputSet set;
  set.prepare_folder(folder + "/");
  const std::string staging = folder + ".tmp-" + std::to_string(::getpid());
  EXPECT_EQ(set.staged_path(folder + "/a.txt"), staging + "/a.txt");
  write_text_file(folder + "/a.txt", "a");
  write_text_file(folder + "/b.txt", "b");
  EXPECT_FALSE(fs::exists(folder));
  EXPECT_EQ(files_in(staging), 2u);  // the two temporaries
  set.commit();
  EXPECT_EQ(files_in(folder), 2u);
  EXPECT_EQ(files_in(parent), 1u);
  EXPECT_EQ(set.written(), (std::vector<std::string>{folder + "/a.txt", folder + "/b.txt"}));
}

TEST(OutputSet, AStagedFolderWithoutCommitLeavesNothing) {
  const std::string parent = test::temp_folder("output-set");
  {
    OutputSet set;
    set.prepare_folder(parent + "/out");
    write_text_file(parent + "/out/a.txt", "a");
    {
      OutputSet inner;
      write_text_file(parent + "/out/b.txt", "b");
      inner.commit();
    }
    EXPECT_FALSE(fs::exists(parent + "/out"));
  }
  EXPECT_EQ(files_in(parent), 0u);
}

TEST(OutputSet, AnExistingFolderIsWrittenInPlaceAndStagingFoldersOfDeadRunsGo) {
  const std::string parent = test::temp_folder("output-set");
  const pid_t dead = fork();
  if (dead == 0) _exit(0);
  ASSERT_GT(dead, 0);
  ASSERT_EQ(::waitpid(dead, nullptr, 0), dead);
  const std::string stale = parent + "/out.tmp-" + std::to_string(dead);
  fs::create_directory(stale);
  std::ofstream(stale + "/a.txt") << "half";
  const std::string other = parent + "/other.tmp-" + std::to_string(dead);  // another target's
  fs::create_directory(other);
  {
    OutputSet set;
    set.prepare_folder(parent + "/out");
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(other));
    write_text_file(parent + "/out/a.txt", "a");
    set.commit();
  }
  OutputSet again;
  again.prepare_folder(parent + "/out");
  EXPECT_FALSE(again.stages(parent + "/out"));  // it exists: written in place
  EXPECT_EQ(again.staged_path(parent + "/out/a.txt"), parent + "/out/a.txt");
}

TEST(OutputSet, ChecksRefuseInputsAndNonRegularFiles) {
  const std::string folder = test::temp_folder("output-set");
  std::ofstream(folder + "/in.h5") << "input";
  fs::create_symlink(folder + "/in.h5", folder + "/link.h5");
  OutputSet set({folder + "/in.h5"});
  EXPECT_THROW(set.check(folder + "/link.h5"), FormatError);
  EXPECT_THROW(set.check("/dev/null"), FormatError);
  EXPECT_THROW(set.check(folder), FormatError);
  EXPECT_THROW(set.check(folder + "/missing/out.h5"), FormatError);
  EXPECT_NO_THROW(set.check(folder + "/out.h5"));
}

}  // namespace
}  // namespace gesmi::io
