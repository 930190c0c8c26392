// Why: the cost of a small page's fault differs tenfold between the virtual machines
// this project has run on (about 1 µs where the host maps the guest's memory in
// hardware, about 10 µs under a paravirtual MMU whose page tables are shadowed), and
// it decides whether the heap is cheaper in small or huge pages (docs/performance.md,
// "The heap's page size from the cost of a fault").

#include "tools/gesmi/page_fault_cost.h"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <ctime>
#include <limits>

namespace gesmi::cli {
namespace {

constexpr int kPagesPerRound = 8;

// One round: a fresh mapping in small pages, each page written once; per page.
double one_round(std::size_t page) {
  const std::size_t bytes = page * kPagesPerRound;
  void* mapping = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapping == MAP_FAILED) return std::numeric_limits<double>::quiet_NaN();
  madvise(mapping, bytes, MADV_NOHUGEPAGE);  // (under THP "always" the range could get one)
  volatile unsigned char* bytes_of = static_cast<unsigned char*>(mapping);
  const double before = thread_cpu_microseconds();
  for (std::size_t offset = 0; offset < bytes; offset += page) bytes_of[offset] = 1;
  const double after = thread_cpu_microseconds();
  munmap(mapping, bytes);
  return (after - before) / kPagesPerRound;
}

}  // namespace

double thread_cpu_microseconds() {
  timespec t{};
  if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t) != 0) return std::numeric_limits<double>::quiet_NaN();
  return static_cast<double>(t.tv_sec) * 1e6 + static_cast<double>(t.tv_nsec) / 1e3;
}

double small_page_fault_microseconds() {
  const long page = sysconf(_SC_PAGESIZE);
  if (page <= 0) return std::numeric_limits<double>::quiet_NaN();
  // The smaller of two: an interrupt during one round only raises that round.
  const double first = one_round(static_cast<std::size_t>(page));
  const double second = one_round(static_cast<std::size_t>(page));
  if (std::isnan(first) || std::isnan(second)) return std::isnan(first) ? second : first;
  return std::min(first, second);
}

}  // namespace gesmi::cli
