// The at() contract shared by every sequence (sequence.h): registry names in the memo's order,
// determinism per seed, range [0,1) (never 1.0), thread-safe reads, and decorrelated seeds.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include "common.h"
#include "disklab/sequence/halton.h"
#include "disklab/sequence/random.h"
#include "disklab/sequence/sequence.h"
#include "disklab/sequence/sobol.h"
#include "disklab/sequence/tabulated.h"
#include "support/stats.h"

namespace disklab::sequence {
namespace {

const std::vector<std::string> kMemoOrder = {
    "random",        "best-candidate", "art",        "halton-rotated", "halton-scrambled",
    "sobol-rotated", "sobol-xor",      "sobol-owen", "pmj02",          "pmj02bn"};
// Every test below runs on what the registry lists (the first test holds it to the memo's list),
// so a new generator is held to the contract as soon as it is registered.
const std::vector<std::string> kRegistered = sequence_names();

// Registry instances of the tabulated sequences hold 2^16 points (the candidate searches make them
// slow to build), so the many-seed tests build them with a small capacity; the registry's own
// instances are tested for determinism and range below.
std::unique_ptr<Sequence> make_small(const std::string& name, uint64_t seed, uint32_t capacity) {
  return make_sequence(name, seed, capacity);
}

// Indices that exercise the table edges, digit carries and the end of the index range.
const uint32_t kProbeIndices[] = {0,           1,           2,           3,          255,
                                  256,         65535,       65536,       65537,      1u << 20,
                                  0x7fffffffu, 0x80000000u, 0xfffffffeu, 0xffffffffu};

TEST(Contract, RegistryListsTheMemoSequencesInOrder) {
  const std::vector<std::string> names = sequence_names();
  EXPECT_EQ(names, kMemoOrder);
  for (const std::string& n : names)
    EXPECT_EQ(make_sequence(n, 1)->name(), n);
  EXPECT_THROW(make_sequence("sobol", 1), std::invalid_argument);
  EXPECT_THROW(make_sequence("", 1), std::invalid_argument);
}

TEST(Contract, RegistryInstancesAreDeterministicAndInRange) {
  for (const std::string& name : kRegistered) {
    const auto a = make_sequence(name, 42), b = make_sequence(name, 42);
    const auto c = make_small(name, 43, 1u << 12);
    int same_as_other_seed = 0;
    auto check = [&](uint32_t i) {
      const Point2 p = a->at(i), q = b->at(i);
      EXPECT_EQ(p, q) << name << " index " << i << " differs between two instances of seed 42";
      EXPECT_TRUE(p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0)
          << name << " index " << i << " gives (" << p.x << ", " << p.y << ")";
      EXPECT_EQ(p, a->at(i)) << name << " index " << i << ": repeated call differs";
      if (p == c->at(i)) ++same_as_other_seed;
    };
    for (uint32_t i = 0; i < 4096; ++i)
      check(i);
    for (uint32_t i : kProbeIndices)
      check(i);
    EXPECT_LT(same_as_other_seed, 5) << name << ": seeds 42 and 43 give the same points";
  }
}

// The worst case for "never 1.0": the largest fixed-point values convert below 1.
TEST(Contract, LargestFixedPointValuesStayBelowOne) {
  EXPECT_LT(to_unit(0xffffffffu), 1.0);
  EXPECT_LT(halton3_to_unit(kHalton3Scale - 1), 1.0);
}

RC_GTEST_PROP(Contract, AnySeedAnyIndexInRange, (uint64_t seed, uint32_t index)) {
  // The analytic sequences at arbitrary seeds and indices (the tabulated ones share the same
  // fixed-point conversion, tested above with their table wrap-around).
  for (const char* name : {"random", "art", "halton-rotated", "halton-scrambled", "sobol-rotated",
                           "sobol-xor", "sobol-owen"}) {
    const Point2 p = make_sequence(name, seed)->at(index);
    RC_ASSERT(p.x >= 0.0);
    RC_ASSERT(p.x < 1.0);
    RC_ASSERT(p.y >= 0.0);
    RC_ASSERT(p.y < 1.0);
  }
}

TEST(Contract, MaxCountOnlyChangesTheTableSize) {
  // make_sequence(name, seed, max_count) gives the same points as make_sequence(name, seed).
  for (const std::string& name : kRegistered) {
    const auto full = make_sequence(name, 9), small = make_sequence(name, 9, 300);
    for (uint32_t i = 0; i < 300; ++i)
      ASSERT_EQ(full->at(i), small->at(i)) << name << " index " << i;
  }
}

TEST(Contract, TablePrefixDoesNotDependOnCapacity) {
  // The tables are generated point by point from one random stream, so a smaller capacity gives
  // the same first points: results at N points do not depend on the capacity chosen.
  const Pmj02 small(5, 1u << 10), large(5, 1u << 13);
  const BestCandidate bc_small(5, 1u << 10), bc_large(5, 1u << 13);
  for (uint32_t i = 0; i < (1u << 10); ++i) {
    ASSERT_EQ(small.at(i), large.at(i)) << "pmj02 index " << i;
    ASSERT_EQ(bc_small.at(i), bc_large.at(i)) << "best-candidate index " << i;
  }
}

TEST(Contract, ConcurrentReadsMatchSerialReads) {
  for (const std::string& name : kRegistered) {
    const auto seq = make_small(name, 7, 1u << 12);
    constexpr uint32_t kCount = 1u << 14;  // past the small table: wrap-around path too
    std::vector<Point2> serial(kCount), a(kCount), b(kCount);
    for (uint32_t i = 0; i < kCount; ++i)
      serial[i] = seq->at(i);
    std::thread t1([&] {
      for (uint32_t i = 0; i < kCount; ++i)
        a[i] = seq->at(i);
    });
    std::thread t2([&] {
      for (uint32_t i = kCount; i-- > 0;)
        b[i] = seq->at(i);
    });
    t1.join();
    t2.join();
    EXPECT_EQ(a, serial) << name;
    EXPECT_EQ(b, serial) << name;
  }
}

TEST(Contract, ConsecutiveSeedsAreDecorrelated) {
  // For consecutive seeds s = 0..S-1: (1) the first point is uniform over seeds (chi-square on
  // a 6 x 6 grid), and (2) the integration errors of N = 64 points on a smooth integrand are
  // uncorrelated between seed s and s+1 (lag-1 correlation; under independence it is
  // approximately normal with standard deviation 1/sqrt(S)). A seed used directly as an offset
  // or mask would fail both.
  constexpr int kSeeds = 720;
  constexpr uint32_t kN = 64;
  const double alpha = test::sidak_alpha(test::seq::kFamilyAlpha, 2 * kRegistered.size());
  const double z = test::normal_two_sided_quantile(alpha);
  auto f = [](Point2 p) { return std::exp(-(p.x * p.x + 2.0 * p.y * p.y)); };
  for (const std::string& name : kRegistered) {
    std::vector<double> observed(36, 0.0), expected(36, kSeeds / 36.0), estimate(kSeeds, 0.0);
    for (int s = 0; s < kSeeds; ++s) {
      const auto seq = make_small(name, static_cast<uint64_t>(s), kN);
      const Point2 p0 = seq->at(0);
      observed[static_cast<int>(p0.x * 6) * 6 + static_cast<int>(p0.y * 6)] += 1.0;
      double sum = 0.0;
      for (uint32_t i = 0; i < kN; ++i)
        sum += f(seq->at(i));
      estimate[s] = sum / kN;
    }
    const test::ChiSquareResult r = test::chi_square(observed, expected);
    EXPECT_GT(r.p_value, alpha) << name << ": first point over seeds: " << r.summary();
    const test::MeanEstimate m = test::mean_estimate(estimate);
    double num = 0.0, den = 0.0;
    for (int s = 0; s < kSeeds; ++s) {
      den += (estimate[s] - m.mean) * (estimate[s] - m.mean);
      if (s + 1 < kSeeds) num += (estimate[s] - m.mean) * (estimate[s + 1] - m.mean);
    }
    const double lag1 = num / den;
    EXPECT_LT(std::abs(lag1), z / std::sqrt(static_cast<double>(kSeeds)))
        << name << ": lag-1 correlation of estimates over consecutive seeds " << lag1;
  }
}

TEST(Contract, RandomMatchesSequentialPcg32) {
  // at(i) jumps the generator: it must equal the (2i, 2i+1)-th draws of a sequential stream.
  const RandomSequence seq(99);
  Pcg32 rng(99);
  for (uint32_t i = 0; i < 1000; ++i) {
    const double u = rng.next_double(), v = rng.next_double();
    ASSERT_EQ(seq.at(i), (Point2{u, v})) << "index " << i;
  }
}

// advance(k) is the jump the table-driven at(i) must agree with for indices a sequential
// stream cannot reach in a test: first prove advance(k) equals k draws (k < 2^17 covers the low
// bits of every jump), then compare at(i) with advance(2i) on the high bytes and at 2^32 - 1.
TEST(Contract, PcgAdvanceEqualsSequentialDraws) {
  for (const uint64_t k : {0ull, 1ull, 2ull, 255ull, 256ull, 65535ull, 65536ull, 131071ull}) {
    Pcg32 stepped(7), jumped(7);
    for (uint64_t j = 0; j < k; ++j)
      stepped.next_u32();
    jumped.advance(k);
    ASSERT_EQ(stepped.next_u32(), jumped.next_u32()) << "k=" << k;
  }
}

TEST(Contract, RandomAtLargeIndicesMatchesAdvance) {
  const RandomSequence seq(99);
  std::vector<uint32_t> indices = {0xFFFFFFFFu, 0x80000000u, 0x00FF0000u, 0xFF000000u, 0x01000000u};
  Pcg32 pick(5);
  for (int k = 0; k < 200; ++k)
    indices.push_back(pick.next_u32());
  for (const uint32_t i : indices) {
    Pcg32 rng(99);
    rng.advance(2 * static_cast<uint64_t>(i));
    const double u = rng.next_double(), v = rng.next_double();
    ASSERT_EQ(seq.at(i), (Point2{u, v})) << "index " << i;
  }
}

}  // namespace
}  // namespace disklab::sequence
