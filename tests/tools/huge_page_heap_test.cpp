// The gesmi command's heap policy (tools/gesmi/huge_page_heap.h): after the call the
// heap's range is marked for transparent huge pages (the kernel's own account in
// /proc/self/smaps, flag "hg"), later blocks are carved from that range, and memory
// allocated, written and freed after it reads back what was written.

#include "tools/gesmi/huge_page_heap.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace gesmi::test {
namespace {

struct Mapping {
  std::uintptr_t begin = 0, end = 0;
  bool huge_pages = false;  // VmFlags has "hg": madvise(MADV_HUGEPAGE) was applied
};

// The process's mappings as the kernel lists them.
std::vector<Mapping> mappings() {
  std::vector<Mapping> all;
  std::ifstream smaps("/proc/self/smaps");
  for (std::string line; std::getline(smaps, line);) {
    if (line.rfind("VmFlags:", 0) == 0) {
      if (!all.empty()) all.back().huge_pages = line.find(" hg") != std::string::npos;
      continue;
    }
    const std::size_t dash = line.find('-');
    const std::size_t space = line.find(' ');
    if (dash == std::string::npos || space == std::string::npos || dash > space) continue;
    char* stop = nullptr;
    const auto begin = std::strtoull(line.c_str(), &stop, 16);
    if (stop != line.c_str() + dash) continue;  // not a mapping's header line
    all.push_back({begin, std::strtoull(line.c_str() + dash + 1, nullptr, 16), false});
  }
  return all;
}

const Mapping* mapping_of(const std::vector<Mapping>& all, const void* address) {
  const auto a = reinterpret_cast<std::uintptr_t>(address);
  for (const Mapping& m : all)
    if (a >= m.begin && a < m.end) return &m;
  return nullptr;
}

bool marked(const void* address) {
  const std::vector<Mapping> all = mappings();
  const Mapping* m = mapping_of(all, address);
  return m != nullptr && m->huge_pages;
}

bool mapped(const void* address) { return mapping_of(mappings(), address) != nullptr; }

bool sanitized() {
#if defined(__SANITIZE_ADDRESS__)
  return true;  // ASan's allocator does not take memory from the program break
#else
  return false;
#endif
}

// glibc told to fill blocks: the policy leaves the heap alone (huge_page_heap.cpp).
bool perturbed() {
  const char* perturb = std::getenv("MALLOC_PERTURB_");
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  return (perturb != nullptr && std::atoi(perturb) != 0) ||
         (tunables != nullptr && std::string(tunables).find("glibc.malloc.perturb") != std::string::npos);
}

TEST(HugePageHeap, MarksTheHeapAndLaterBlocksComeFromIt) {
  if (sanitized()) GTEST_SKIP() << "ASan replaces malloc";
  if (perturbed()) GTEST_SKIP() << "glibc perturbs blocks: the heap is left alone";
  if (!std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled"))
    GTEST_SKIP() << "this kernel has no transparent huge pages";
  cli::use_huge_page_heap();
  // A block of an array's size (a 60,000-step mission's column is 480 kB).
  std::vector<double> column(60'000, 1.5);
  EXPECT_TRUE(marked(column.data())) << "the block is not in a range marked for huge pages";
  EXPECT_TRUE(marked(static_cast<char*>(sbrk(0)) - 1)) << "the heap's end is not marked";
}

// Whether the page at `address` is in memory (/proc/self/pagemap, bit 63; readable by
// the process itself), or nullopt where the kernel does not say.
std::optional<bool> present(std::uintptr_t address) {
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const int fd = open("/proc/self/pagemap", O_RDONLY);
  if (fd < 0) return std::nullopt;
  std::uint64_t entry = 0;
  const ssize_t got = pread(fd, &entry, sizeof(entry), static_cast<off_t>(address / page * sizeof(entry)));
  close(fd);
  if (got != static_cast<ssize_t>(sizeof(entry))) return std::nullopt;
  return (entry >> 63 & 1) != 0;
}

// The kernel gives a huge page only to an aligned 2 MiB that nothing has touched: the
// call must leave the heap's first such range after it untouched (growing the heap
// writes glibc's chunk headers; written inside that range, they left the heap's most
// used 2 MiB in small pages). Checked in a fresh process (the death test's "threadsafe"
// style runs this test alone in a new one): a heap the other tests have used, freed and
// grown again is another matter.
TEST(HugePageHeap, TheHeapsFirstHugePageIsLeftUntouched) {
  if (sanitized()) GTEST_SKIP() << "ASan replaces malloc";
  if (perturbed()) GTEST_SKIP() << "glibc perturbs blocks: the heap is left alone";
  if (!std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled"))
    GTEST_SKIP() << "this kernel has no transparent huge pages";
  if (!present(reinterpret_cast<std::uintptr_t>(&sanitized)))
    GTEST_SKIP() << "the kernel does not say which pages are in memory";
  const std::string style = GTEST_FLAG_GET(death_test_style);
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        cli::use_huge_page_heap();
        constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
        // Larger than anything freed before: carved from the heap's new top, not its bins.
        void* block = std::malloc(std::size_t{4} << 20);
        const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(block) + kHugePage - 1) & ~(kHugePage - 1);
        const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
        int touched = 0;
        for (std::uintptr_t a = first; a < first + kHugePage; a += page) touched += present(a).value_or(true) ? 1 : 0;
        std::fprintf(stderr, "%d pages of the heap's first huge page were in memory before any block was written\n",
                     touched);
        std::_Exit(block != nullptr && touched == 0 ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
  GTEST_FLAG_SET(death_test_style, style);
}

// Blocks beyond the heap's 32 MiB get a marked mapping of their own, returned when freed.
TEST(HugePageHeap, BigBlocksHaveTheirOwnMarkedMapping) {
  if (sanitized()) GTEST_SKIP() << "ASan replaces operator new";
  if (!std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled"))
    GTEST_SKIP() << "this kernel has no transparent huge pages";
  cli::use_huge_page_heap();
  const void* address = nullptr;
  {
    std::vector<double> big(5'000'000, 2.5);  // 40 MB: a 10^7-step mission's column is 80 MB
    address = big.data();
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(address) % (std::uintptr_t{2} << 20), 0u) << "not on a huge page";
    EXPECT_TRUE(marked(address)) << "the big block is not in a range marked for huge pages";
    EXPECT_EQ(big.back(), 2.5);
  }
  EXPECT_FALSE(mapped(address)) << "the big block's mapping outlived the block";
}

// A size no mapping can hold is refused as the standard says (std::bad_alloc), not
// rounded into a small mapping; memory from before the call is freed as malloc's.
TEST(HugePageHeap, RefusesImpossibleSizesAndFreesEarlierMemory) {
  if (sanitized()) GTEST_SKIP() << "ASan's operator new is in charge, and aborts on such sizes by design";
  auto* earlier = new std::vector<double>(5'000'000, 1.0);  // 40 MB from malloc: the policy is not on yet
  cli::use_huge_page_heap();
  for (const std::size_t bytes : {SIZE_MAX, SIZE_MAX - (std::size_t{1} << 20), SIZE_MAX / 2})
    EXPECT_THROW((void)::operator new(bytes), std::bad_alloc) << bytes;
  EXPECT_EQ(earlier->back(), 1.0);
  delete earlier;
}

// Several threads allocating and freeing big and small blocks at once.
TEST(HugePageHeap, BigBlocksFromSeveralThreads) {
  cli::use_huge_page_heap();
  std::vector<std::thread> threads;
  std::atomic<int> wrong{0};
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&wrong, t] {
      for (int round = 0; round < 20; ++round) {
        std::vector<std::uint32_t> big(std::size_t{9} << 20, static_cast<std::uint32_t>(t * 100 + round));  // 36 MiB
        std::vector<std::uint32_t> small(1000, 7u);
        if (big[big.size() / 2] != static_cast<std::uint32_t>(t * 100 + round) || small.back() != 7u) ++wrong;
      }
    });
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(wrong.load(), 0);
}

TEST(HugePageHeap, MemoryAfterItHoldsWhatIsWritten) {
  cli::use_huge_page_heap();
  // Blocks below, at and beyond the 32 MiB heap limit, written, freed and allocated again.
  for (int round = 0; round < 2; ++round) {
    std::vector<std::vector<std::uint64_t>> blocks;
    for (const std::size_t bytes : {std::size_t{4096}, std::size_t{1} << 20, std::size_t{32} << 20, std::size_t{48} << 20})
      blocks.emplace_back(bytes / sizeof(std::uint64_t));
    for (std::size_t b = 0; b < blocks.size(); ++b)
      for (std::size_t i = 0; i < blocks[b].size(); ++i) blocks[b][i] = (b << 40) ^ i ^ static_cast<std::uint64_t>(round);
    for (std::size_t b = 0; b < blocks.size(); ++b)
      for (std::size_t i = 0; i < blocks[b].size(); i += 997)
        ASSERT_EQ(blocks[b][i], (b << 40) ^ i ^ static_cast<std::uint64_t>(round)) << "block " << b << " word " << i;
  }
}

}  // namespace
}  // namespace gesmi::test
