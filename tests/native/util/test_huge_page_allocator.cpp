// The planners' large scratch vectors (native/src/util/huge_page_allocator.hpp):
// blocks of 2 MiB and more are mapped on their own, aligned for huge pages;
// growing, shrinking and copying across that size keep every element.
#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

#include "util/huge_page_allocator.hpp"

namespace footfall {
namespace {

TEST(HugePageAllocator, KeepsEveryElementAcrossTheMappedSize) {
  LargeVector<std::uint64_t> values;
  constexpr std::size_t kLarge = 3 * huge_pages::kSize / sizeof(std::uint64_t);
  // Grows by doublings from the heap into mapped blocks, each a copy of the last.
  for (std::size_t i = 0; i < kLarge; ++i) values.push_back(i * 7);
  ASSERT_GE(values.capacity() * sizeof(std::uint64_t), huge_pages::kSize);
  if (huge_pages::kMapped) {
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(values.data()) % huge_pages::kSize, 0u);
  }
  for (std::size_t i = 0; i < kLarge; i += 4099) ASSERT_EQ(values[i], i * 7) << i;
  EXPECT_EQ(values.back(), (kLarge - 1) * 7);

  // A copy made small again comes back from the heap, its elements intact.
  values.resize(1000);
  values.shrink_to_fit();
  EXPECT_EQ(std::accumulate(values.begin(), values.end(), std::uint64_t{0}), 7u * 999 * 1000 / 2);
  const LargeVector<std::uint64_t> copy(values.begin(), values.end());
  EXPECT_EQ(copy, values);
}

TEST(HugePageAllocator, MappedBlocksAreZeroedAndWritable) {
  // Value-initialised like any vector's, in a block that is not a whole
  // number of huge pages.
  LargeVector<double> zeros(huge_pages::kSize / sizeof(double) + 12345);
  for (const double z : zeros) ASSERT_EQ(z, 0.0);
  zeros.back() = 1.5;
  EXPECT_EQ(zeros.back(), 1.5);
}

}  // namespace
}  // namespace footfall
