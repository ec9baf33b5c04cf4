// SPDX-License-Identifier: Apache-2.0
#include "buffers.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#endif
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstdint>

namespace vrreg::detail {
namespace {

// Asks Linux for transparent huge pages on a buffer not yet touched (a hint: nothing changes
// where it is not honoured).
void advise_huge_pages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20U;
  if (bytes < 4 * kHugePage) return;
  const auto address = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = (address + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t end = (address + bytes) & ~(kHugePage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

void fault_in_parallel(void* data, std::size_t bytes) {
  constexpr std::size_t kPage = 4096;
  constexpr std::size_t kPagesPerTask = 256;
  if (bytes < 4 * kPagesPerTask * kPage) return;
  auto* const bytes_begin = static_cast<unsigned char*>(data);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, bytes, kPagesPerTask * kPage),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t b = r.begin(); b < r.end(); b += kPage) bytes_begin[b] = 0;
                    });
}

}  // namespace

void allocate_points(Points3& points, Eigen::Index n) {
  points.resize(3, n);
  advise_huge_pages(points.data(), static_cast<std::size_t>(3 * n) * sizeof(double));
}

void allocate_stencils(std::vector<Stencil>& stencils, Eigen::Index n) {
  const auto count = static_cast<std::size_t>(n);
  stencils.reserve(count);
  advise_huge_pages(stencils.data(), count * sizeof(Stencil));
  fault_in_parallel(stencils.data(), count * sizeof(Stencil));
  stencils.resize(count);
}

}  // namespace vrreg::detail
