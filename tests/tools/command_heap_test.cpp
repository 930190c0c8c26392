// The gesmi command's heap policy (tools/gesmi/command_heap.h): after the call, blocks up
// to 32 MiB come from the heap (the program break's mapping, "[heap]" in the kernel's
// /proc/self/smaps), which is not marked for transparent huge pages (flag "hg"); bigger
// blocks get a marked mapping of their own; and memory allocated, written and freed
// after it reads back what was written.

#include "tools/gesmi/command_heap.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>
#include <thread>
#include <vector>

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

// A 16 MiB block (a 10^6-step mission's pair of bounds) is carved from the heap, where
// glibc would give it a mapping of its own (faulted in again after every free), and the
// heap is left in small pages: on a virtual machine that gives its free huge pages back
// to its host, a huge page is fresh host memory at every fault (docs/performance.md,
// "The heap back in small pages").
TEST(CommandHeap, BlocksUpTo32MiBComeFromTheHeapInSmallPages) {
  if (sanitized()) GTEST_SKIP() << "ASan replaces malloc";
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables != nullptr && std::string(tunables).find("glibc.malloc.hugetlb") != std::string::npos)
    GTEST_SKIP() << "GLIBC_TUNABLES asks glibc for huge pages in its heap";
  cli::use_command_heap();
  std::vector<double> block(std::size_t{2} << 20, 1.5);
  std::vector<double> column(60'000, 2.5);  // a 60,000-step mission's column is 480 kB
  const std::vector<Mapping> all = mappings();
  for (const void* address : {static_cast<const void*>(block.data()), static_cast<const void*>(column.data())}) {
    const Mapping* m = mapping_of(all, address);
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->name, "[heap]") << "a block under 32 MiB is not in the heap";
    EXPECT_FALSE(m->huge_pages) << "the heap is marked for huge pages";
  }
  EXPECT_EQ(block.back() + column.back(), 4.0);
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
