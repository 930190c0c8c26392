// Why: at 10^7 steps a command's arrays are 80-240 MB each. glibc maps every block above
// 32 MiB on its own in 4 KiB pages, and touching 3.5 GB that way took `gesmi kalman` 16 s
// of system time. glibc can mark those mappings for huge pages itself, but only when the
// environment says so before main (glibc.malloc.hugetlb); so the C++ allocation
// functions are replaced here, for big blocks only. The replacement is the standard's
// (replaceable global allocation functions); malloc, and so C libraries, are untouched.

#include "tools/gesmi/huge_page_blocks.h"

#include <sys/mman.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <new>

// Under ASan, whose own operator new stays in charge, none of this is compiled.
#if !defined(__SANITIZE_ADDRESS__)

namespace gesmi::cli {
namespace {

constexpr std::size_t kAlignment = std::size_t{2} << 20;  // a huge page: mappings start on one

struct Mapping {
  void* start = nullptr;
  std::size_t bytes = 0;
};

// The live big blocks. A fixed table: when it is full, blocks come from malloc.
struct BigBlocks {
  std::mutex lock;
  std::array<Mapping, 256> table{};
  // Every big block lies in [lowest, highest): a pointer outside is not one, without the lock.
  std::atomic<std::uintptr_t> lowest{UINTPTR_MAX}, highest{0};
  std::atomic<bool> enabled{false};
};

constinit BigBlocks the_big_blocks;  // constant-initialised: usable before main and after exit

BigBlocks& big_blocks() { return the_big_blocks; }

void* map_big_block(std::size_t bytes) {
  if (bytes > SIZE_MAX - 2 * kAlignment) return nullptr;  // no such mapping; malloc then refuses it too
  BigBlocks& b = big_blocks();
  const std::size_t length = (bytes + kAlignment - 1) / kAlignment * kAlignment;
  // Over-map by one huge page and trim, so that the block starts on a huge page.
  void* raw = mmap(nullptr, length + kAlignment, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) return nullptr;
  const auto raw_start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t start = (raw_start + kAlignment - 1) & ~(kAlignment - 1);
  if (start > raw_start) munmap(raw, start - raw_start);
  if (const std::uintptr_t tail = raw_start + length + kAlignment - (start + length); tail > 0)
    munmap(reinterpret_cast<void*>(start + length), tail);
  void* block = reinterpret_cast<void*>(start);
  // Advice only (refused, the block is still good memory), and only on the whole huge
  // pages the block fills: a partly used last one would count 2 MiB resident.
  if (const std::size_t whole = bytes / kAlignment * kAlignment; whole > 0) madvise(block, whole, MADV_HUGEPAGE);
  const std::lock_guard<std::mutex> guard(b.lock);
  for (Mapping& m : b.table) {
    if (m.start != nullptr) continue;
    m = {block, length};
    if (start < b.lowest.load(std::memory_order_relaxed)) b.lowest.store(start, std::memory_order_relaxed);
    if (start + length > b.highest.load(std::memory_order_relaxed)) b.highest.store(start + length, std::memory_order_relaxed);
    return block;
  }
  munmap(block, length);  // the table is full
  return nullptr;
}

// Unmaps `p` if it is a big block; false when it is not one.
bool unmap_big_block(void* p) {
  BigBlocks& b = big_blocks();
  const auto address = reinterpret_cast<std::uintptr_t>(p);
  if (address < b.lowest.load(std::memory_order_relaxed) || address >= b.highest.load(std::memory_order_relaxed))
    return false;
  const std::lock_guard<std::mutex> guard(b.lock);
  for (Mapping& m : b.table) {
    if (m.start != p) continue;
    munmap(m.start, m.bytes);
    m = {};
    return true;
  }
  return false;
}

}  // namespace

void use_huge_page_blocks() { big_blocks().enabled.store(true, std::memory_order_release); }

}  // namespace gesmi::cli

void* operator new(std::size_t bytes) {
  using namespace gesmi::cli;
  if (bytes >= kHugePageBlock && big_blocks().enabled.load(std::memory_order_acquire))
    if (void* block = map_big_block(bytes)) return block;
  for (;;) {
    if (void* block = std::malloc(bytes == 0 ? 1 : bytes)) return block;
    std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
}

void operator delete(void* p) noexcept {
  if (p == nullptr || gesmi::cli::unmap_big_block(p)) return;
  std::free(p);
}

void operator delete(void* p, std::size_t) noexcept { operator delete(p); }

#else

void gesmi::cli::use_huge_page_blocks() {}

#endif
