// The gesmi command's heap policy (tools/gesmi/command_heap.h): after the call, blocks up
// to 32 MiB come from the heap (the program break's mapping, "[heap]" in the kernel's
// /proc/self/smaps), in small pages or marked for transparent huge pages (flag "hg") as
// asked, or as the measured cost of a small page's fault says; bigger blocks get a
// marked mapping of their own; and memory allocated, written and freed after it reads
// back what was written. The page-size cases run each in a fresh process (a heap the
// other tests have grown and marked is another matter).

#include "tools/gesmi/command_heap.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <new>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "tools/gesmi/page_fault_cost.h"

namespace gesmi::test {
namespace {

struct Mapping {
  std::uintptr_t begin = 0, end = 0;
  std::string name;         // the file or "[heap]", "[stack]" ...; empty for anonymous memory
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
    // The header's sixth field, if any, is the name.
    std::size_t at = space;
    for (int field = 1; field < 5 && at != std::string::npos; ++field) at = line.find(' ', line.find_first_not_of(' ', at));
    const std::size_t name = at == std::string::npos ? std::string::npos : line.find_first_not_of(' ', at);
    all.push_back({begin, std::strtoull(line.c_str() + dash + 1, nullptr, 16),
                   name == std::string::npos ? std::string() : line.substr(name), false});
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

// glibc told to fill blocks, or to put its heap in huge pages itself: the heap's pages
// are then not the policy's to choose.
bool glibc_decides() {
  const char* perturb = std::getenv("MALLOC_PERTURB_");
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const std::string t = tunables != nullptr ? tunables : "";
  return (perturb != nullptr && std::atoi(perturb) != 0) || t.find("glibc.malloc.perturb") != std::string::npos ||
         t.find("glibc.malloc.hugetlb") != std::string::npos;
}

bool transparent_huge_pages() { return std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled"); }

// Runs `check` in a fresh process (the death test's "threadsafe" style); it returns what
// went wrong, empty when nothing did, which the test then shows.
void in_fresh_process(const std::function<std::string()>& check) {
  const std::string style = GTEST_FLAG_GET(death_test_style);
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        const std::string wrong = check();
        if (!wrong.empty()) std::fprintf(stderr, "%s\n", wrong.c_str());
        std::_Exit(wrong.empty() ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
  GTEST_FLAG_SET(death_test_style, style);
}

// Where a block and the heap's end are: in the heap, and marked or not.
std::string heap_blocks_are(bool huge) {
  std::vector<double> block(std::size_t{2} << 20, 1.5);  // 16 MiB: a 10^6-step mission's pair of bounds
  std::vector<double> column(60'000, 2.5);               // a 60,000-step mission's column is 480 kB
  const std::vector<Mapping> all = mappings();
  for (const void* address : {static_cast<const void*>(block.data()), static_cast<const void*>(column.data()),
                              static_cast<const void*>(static_cast<char*>(sbrk(0)) - 1)}) {
    const Mapping* m = mapping_of(all, address);
    if (m == nullptr) return "a block is in no mapping";
    if (m->name != "[heap]") return "a block under 32 MiB is not in the heap but in '" + m->name + "'";
    if (m->huge_pages != huge) return huge ? "a heap block is not marked for huge pages" : "the heap is marked for huge pages";
  }
  return block.back() + column.back() == 4.0 ? "" : "the blocks do not hold what was written";
}

// A 16 MiB block is carved from the heap, where glibc would give it a mapping of its own
// (faulted in again after every free), and left in small pages when asked: on a virtual
// machine that gives its free huge pages back to its host, a huge page is fresh host
// memory at every fault (docs/performance.md, "The heap back in small pages").
TEST(CommandHeap, BlocksUpTo32MiBComeFromTheHeapInSmallPagesWhenAsked) {
  if (sanitized()) GTEST_SKIP() << "ASan replaces malloc";
  if (glibc_decides()) GTEST_SKIP() << "the environment tells glibc how to use its heap";
  in_fresh_process([] {
    if (cli::use_command_heap(cli::HeapPages::small) != cli::HeapPages::small) return std::string("not small pages");
    return heap_blocks_are(false);
  });
}

// Asked for huge pages, the heap's blocks are in a marked range, its end included.
TEST(CommandHeap, BlocksUpTo32MiBComeFromTheHeapInHugePagesWhenAsked) {
  if (sanitized()) GTEST_SKIP() << "ASan replaces malloc";
  if (glibc_decides()) GTEST_SKIP() << "the environment tells glibc how to use its heap";
  if (!transparent_huge_pages()) GTEST_SKIP() << "this kernel has no transparent huge pages";
  in_fresh_process([] {
    if (cli::use_command_heap(cli::HeapPages::huge) != cli::HeapPages::huge) return std::string("not huge pages");
    return heap_blocks_are(true);
  });
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
// marking must leave the heap's first such range after it untouched (growing the heap
// writes glibc's chunk headers; written inside that range, they left the heap's most
// used 2 MiB in small pages).
TEST(CommandHeap, TheHeapsFirstHugePageIsLeftUntouched) {
  if (sanitized()) GTEST_SKIP() << "ASan replaces malloc";
  if (glibc_decides()) GTEST_SKIP() << "the environment tells glibc how to use its heap";
  if (!transparent_huge_pages()) GTEST_SKIP() << "this kernel has no transparent huge pages";
  if (!present(reinterpret_cast<std::uintptr_t>(&sanitized)))
    GTEST_SKIP() << "the kernel does not say which pages are in memory";
  in_fresh_process([] {
    if (cli::use_command_heap(cli::HeapPages::huge) != cli::HeapPages::huge) return std::string("not huge pages");
    constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
    // Larger than anything freed before: carved from the heap's new top, not its bins.
    void* block = std::malloc(std::size_t{4} << 20);
    const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(block) + kHugePage - 1) & ~(kHugePage - 1);
    const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    int touched = 0;
    for (std::uintptr_t a = first; a < first + kHugePage; a += page) touched += present(a).value_or(true) ? 1 : 0;
    if (block == nullptr || touched != 0)
      return std::to_string(touched) + " pages of the heap's first huge page were in memory before any block was written";
    return std::string();
  });
}

// By default the heap's pages follow the measured cost of a small page's fault; the
// choice shows in the heap's marks.
TEST(CommandHeap, ByDefaultThePagesFollowTheCostOfAFault) {
  if (sanitized()) GTEST_SKIP() << "ASan replaces malloc";
  if (glibc_decides()) GTEST_SKIP() << "the environment tells glibc how to use its heap";
  if (!transparent_huge_pages()) GTEST_SKIP() << "this kernel has no transparent huge pages";
  in_fresh_process([] {
    const cli::HeapPages pages = cli::use_command_heap();
    if (pages == cli::HeapPages::by_fault_cost) return std::string("no choice made");
    return heap_blocks_are(pages == cli::HeapPages::huge);
  });
}

double process_cpu_microseconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e6 + static_cast<double>(t.tv_nsec) / 1e3;
}

// The probe's figure against an independent one: 512 fresh small pages written once,
// timed by the process's clock; the median of 5 rounds. A probe that counted one page
// for many, or many for one, would be off by far more than the factor allowed.
TEST(CommandHeap, TheFaultProbeAgreesWithALongerMeasurement) {
  const double probe = cli::small_page_fault_microseconds();
  ASSERT_TRUE(std::isfinite(probe));
  EXPECT_GT(probe, 0.0);
  const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  constexpr std::size_t kPages = 512;
  std::vector<double> rounds;
  for (int round = 0; round < 5; ++round) {
    void* mapping = mmap(nullptr, page * kPages, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    ASSERT_NE(mapping, MAP_FAILED);
    madvise(mapping, page * kPages, MADV_NOHUGEPAGE);
    volatile char* bytes = static_cast<char*>(mapping);
    const double before = process_cpu_microseconds();
    for (std::size_t p = 0; p < kPages; ++p) bytes[p * page] = 1;
    rounds.push_back((process_cpu_microseconds() - before) / kPages);
    munmap(mapping, page * kPages);
  }
  std::sort(rounds.begin(), rounds.end());
  const double reference = rounds[rounds.size() / 2];
  EXPECT_LT(probe, 8.0 * reference) << "probe " << probe << " us, reference " << reference << " us a page";
  EXPECT_GT(probe, reference / 8.0) << "probe " << probe << " us, reference " << reference << " us a page";
}

// Blocks beyond the heap's 32 MiB get a marked mapping of their own, returned when freed.
TEST(CommandHeap, BigBlocksHaveTheirOwnMarkedMapping) {
  if (sanitized()) GTEST_SKIP() << "ASan replaces operator new";
  if (!std::filesystem::exists("/sys/kernel/mm/transparent_hugepage/enabled"))
    GTEST_SKIP() << "this kernel has no transparent huge pages";
  cli::use_command_heap();
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
TEST(CommandHeap, RefusesImpossibleSizesAndFreesEarlierMemory) {
  if (sanitized()) GTEST_SKIP() << "ASan's operator new is in charge, and aborts on such sizes by design";
  auto* earlier = new std::vector<double>(5'000'000, 1.0);  // 40 MB from malloc: the policy is not on yet
  cli::use_command_heap();
  for (const std::size_t bytes : {SIZE_MAX, SIZE_MAX - (std::size_t{1} << 20), SIZE_MAX / 2})
    EXPECT_THROW((void)::operator new(bytes), std::bad_alloc) << bytes;
  EXPECT_EQ(earlier->back(), 1.0);
  delete earlier;
}

// Several threads allocating and freeing big and small blocks at once.
TEST(CommandHeap, BigBlocksFromSeveralThreads) {
  cli::use_command_heap();
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

TEST(CommandHeap, MemoryAfterItHoldsWhatIsWritten) {
  cli::use_command_heap();
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
