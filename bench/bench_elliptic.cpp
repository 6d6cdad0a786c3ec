// Cost of our elliptic integrals (lib/include/disklab/math/elliptic.h) against Boost.Math, same
// run (issue 4, "Benchmark"): F, Pi, R_F, R_J vs ellint_1, ellint_3, ellint_rf, ellint_rj, each
// Boost function with both policies:
//  - boost-double:  policy<promote_double<false>>, computes in double: the honest baseline;
//  - boost-default: Boost's default policy, which promotes double to long double internally.
//
// Ratios, not absolute times. Every benchmark interleaves, pass by pass over the same input set,
// the implementation under test with boost-double; the two are timed separately and their
// quotient reported as `ratio_to_boost_double` (machine load hits both alike and cancels).
// The reported time and items/s are the implementation's own.
//
// Inputs: a fixed pseudo-random set (PCG32, seed 1) of kInputs (n, phi, m) triples covering the
// domain of docs/design.md: m in [0, 1) (a quarter of them within 1e-3 of 1, where the duplication
// needs more steps), phi in [0, pi/2], n in three bands of equal size: (0, 1), [-1, 0) and
// log-uniform in [-1e6, -1) (the parallel map's n = -b_t^2 for far, grazing lights). Sets:
//  - mixed: all three bands interleaved (branch patterns of a real caller);
//  - n>0, -1<=n<0, n<-1: one band each (Pi only: its n < 0 path has an extra atan).
// Pi/mixed/own is ellint_pi<double> as a caller gets it: on a CPU with AVX2 and FMA its
// double-double kernel (lib/src/math/elliptic_pi_dd_kernel.inc; the AVX-512VL copy where the CPU
// has it), else the long-double path; Pi/mixed/own-portable always times the long-double path
// (ellint_pi_portable), Pi/mixed/own-avx2 ellint_pi<double> with the kernel's AVX2+FMA copy in
// use (what CPUs without AVX-512VL run; registered where this CPU runs it). The summary says which
// one "own" ran. Pi/mixed/own-double-loop times our Pi with its duplication loop in double (see
// pi_double_loop): what the 2-ulp accuracy costs in speed.
// Boost takes the modulus k = sqrt(m); k is computed once, outside the timed loops.
// R_F and R_J get the arguments Pi hands them: (c^2, 1 - m s^2, 1) and p = 1 - n s^2 (n > 0) or
// 1 - N s^2 with N = (m - n)/(1 - n) (n < 0).
//
// F/mixed/own is ellint_f<double> as a caller gets it: F's double-double kernel (same file and
// copy as Pi's) where the CPU runs it; F/mixed/own-portable always times the long-double path.
// F/mixed/own-double times the kernel's duplication path (its third path, below) for every input,
// in plain double with libm's sincos (see f_double_alg): the algorithm the kernel's first two
// paths replace, without the error terms that make it faithful. The summary prints how far both
// plain-double variants land from the library's values on the mixed set. Where F's time goes:
// F/mixed/own-chained feeds each result into the next input (one evaluation's latency against
// Boost's, not the throughput of independent calls), and F/small, F/complement, F/steps0-1 and
// F/steps2+ time F on inputs drawn like the mixed set's but kept by the kernel's path: phi <=
// kFSmallPhi (phi (1 + eps), no sin or cos), the complement near pi/2 (K(m) - F(psi|m)), and the
// duplication path with at most one step or with two and more.
//
// The summary after the table repeats the median ratios and checks the issues' targets:
// own Pi <= 0.4x the time of boost::math::ellint_3 with promote_double<false> (issue 4), and
// own F <= 0.5x the time of boost::math::ellint_1 with promote_double<false> (issue 16).
//
// Run: build/<preset>/bin/bench_elliptic --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bench_common.h"
#include "disklab/math/elliptic.h"
#include "disklab/sequence/random.h"
#include "math/elliptic_pi_dd.h"  // lib/src: the Pi kernel's private hooks

namespace {
namespace dm = disklab::math;
using Clock = std::chrono::steady_clock;
using boost_double_policy =
    boost::math::policies::policy<boost::math::policies::promote_double<false>>;

constexpr int kInputs = 4096;           // per set: ~0.2-2 ms per pass, many passes per benchmark
constexpr double kTargetPiRatio = 0.4;  // issue 4's target, own Pi / boost-double ellint_3
constexpr double kTargetFRatio = 0.5;   // issue 16's target, own F / boost-double ellint_1

struct Input {
  double n, phi, m, k;  // Legendre arguments; k = sqrt(m) for Boost
  double x, y, z, p;    // the Carlson arguments Pi evaluates
};

// kFSmall .. kFSteps2: F's inputs drawn like the mixed set's (phi, m), kept by the kernel's path
// (f_kernel_path).
enum class Band {
  kMixed,
  kPositive,
  kNegativeSmall,
  kNegativeLarge,
  kFSmall,
  kFComplement,
  kFSteps01,
  kFSteps2
};

int f_kernel_path(double phi, double m);

std::vector<Input> make_inputs(Band band) {
  disklab::sequence::Pcg32 rng(1, static_cast<uint64_t>(band) + 11);
  const bool by_path = band >= Band::kFSmall;
  const int path = static_cast<int>(band) - static_cast<int>(Band::kFSmall);
  std::vector<Input> in(kInputs);
  for (int i = 0, drawn = 0; i < kInputs; ++drawn) {
    Input& r = in[i];
    // m: three quarters uniform in [0, 1), one quarter 1 - 10^-(3..12) (near the singular end).
    r.m =
        (drawn % 4 == 3) ? 1.0 - std::pow(10.0, -3.0 - 9.0 * rng.next_double()) : rng.next_double();
    r.k = std::sqrt(r.m);
    r.phi = rng.next_double() * (std::numbers::pi / 2);
    const int b = band == Band::kMixed || by_path ? i % 3 : static_cast<int>(band) - 1;
    const double u = rng.next_double();
    if (b == 0)
      r.n = u;  // (0, 1) (u = 0 has probability 2^-32)
    else if (b == 1)
      r.n = -1.0 + u;  // [-1, 0)
    else
      r.n = -std::pow(10.0, 6.0 * u);  // [-1e6, -1), log-uniform
    const double s = std::sin(r.phi), c = std::cos(r.phi);
    r.x = c * c;
    r.y = 1.0 - r.m * s * s;
    r.z = 1.0;
    r.p = r.n > 0 ? 1.0 - r.n * s * s : 1.0 - (r.m - r.n) / (1.0 - r.n) * s * s;
    if (!(r.p > 0)) r.p = 1e-300;  // never: n < 1 and N < 1 keep p > 0
    if (!by_path || f_kernel_path(r.phi, r.m) == path) ++i;
  }
  return in;
}

const std::vector<Input>& inputs(Band band) {
  static const std::array<std::vector<Input>, 8> sets{
      make_inputs(Band::kMixed),         make_inputs(Band::kPositive),
      make_inputs(Band::kNegativeSmall), make_inputs(Band::kNegativeLarge),
      make_inputs(Band::kFSmall),        make_inputs(Band::kFComplement),
      make_inputs(Band::kFSteps01),      make_inputs(Band::kFSteps2)};
  return sets[static_cast<int>(band)];
}

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// The functions compared, one per (integral, implementation).
enum class Fn { kF, kPi, kRF, kRJ };
enum class Impl {
  kOwn,
  kBoostDouble,
  kBoostDefault,
  kOwnDoubleLoop,
  kOwnPortable,
  kOwnAvx2,
  kOwnDoubleAlg
};

// Pi as elliptic_legendre.h computes it, but with the duplication loop in double instead of long
// double: the speed side of the accuracy trade-off (not a library function: in double the loop's
// rounding, mostly that of the square roots, the lambda_k and the d_k, reaches 4 ulp on the
// 50-digit tables (21 of 2130 Pi rows above 2 ulp), above the 2-ulp promise).
double pi_double_loop(double n, double phi, double m) {
  namespace d = dm::detail;
  const auto a = d::legendre_args<double, double>(phi, m, 1.0 - m);
  if (a.s == 0) return phi;
  const double s3 = a.s * a.s * a.s, one_minus_n = 1.0 - n;
  const double N = (m - n) / one_minus_n;
  double rf, rj;
  if (n >= 0 || !(N > 0)) {
    d::rf_rj_legendre<double>(a.c, a.c2, a.delta2, d::one_minus_n_s2(n, one_minus_n, a), rf, rj);
    return a.s * rf + n / 3 * s3 * rj;
  }
  const double one_minus_N = (1.0 - m) / one_minus_n;
  d::rf_rj_legendre<double>(a.c, a.c2, a.delta2, a.c2 + one_minus_N * a.s * a.s, rf, rj);
  const double w = -n / one_minus_n, sw = std::sqrt(w), smn = std::sqrt(m - n);
  return a.s * rf / one_minus_n + w * one_minus_N / 3 * s3 * rj +
         (sw / smn) * std::atan(sw * smn * a.s * a.c / std::sqrt(a.delta2));
}

// One duplication step on the roots, r_i <- sqrt((r_i + r_j)(r_i + r_k)), without the halving.
__attribute__((target("avx2,fma"), always_inline)) inline void f_double_step(double& r0, double& r1,
                                                                             double& r2) {
  const double s01 = r0 + r1, s12 = r1 + r2, s02 = r0 + r2;
  r0 = std::sqrt(s01 * s02);
  r1 = std::sqrt(s01 * s12);
  r2 = std::sqrt(s02 * s12);
}

// F by the kernel's duplication path (elliptic_pi_dd_kernel.inc, f_dd beyond its first two paths:
// duplication on the roots c, Delta, 1 of R_F's arguments while their spread exceeds the
// kernel's kFKernelSpread, then the degree-17 series) for every input, with every quantity a
// plain double and libm's sincos: the algorithm without the double-double error terms that make
// it faithful, and without the first two paths. Compiled for the kernel's AVX2 + FMA; the series
// is the kernel's own (one call more than the kernel pays). Registered where the kernel runs. Not
// a library function: it is not faithful (the summary prints its distance from ellint_f).
__attribute__((target("avx2,fma"))) double f_double_alg(double phi, double m) {
  if (phi < 0x1p-26) return phi;
  double s, c;
  ::sincos(phi, &s, &c);
  double r0 = c, r1 = std::sqrt(std::fma(c, c, (1.0 - m) * s * s)), r2 = 1.0, scale = 1.0;
  while (3 * (r2 - r0) > dm::detail::kFKernelSpread * (r0 + r1 + r2)) {
    f_double_step(r0, r1, r2);
    scale *= 2.0;
  }
  const double inv_mu = 3.0 / (r0 + r1 + r2);
  const double d0 = std::fma(r0, inv_mu, -1.0), d1 = std::fma(r1, inv_mu, -1.0), d01 = d0 + d1;
  const double p01 = d0 * d1;
  const double g = dm::detail::f_dd_series(dm::detail::pi_dd_kernel(), p01 - d01 * d01, -p01 * d01);
  return s * inv_mu * (1.0 + g) * scale;
}

// The kernel's path for F(phi|m), phi in (0, pi/2], m in [0, 1] (f_dd in
// elliptic_pi_dd_kernel.inc): 0 small amplitude (phi <= kFSmallPhi), 1 the complement near pi/2
// (chi = pi/2 - phi with chi^2 <= kFComplementRegion (1 - m), 1 - m >= 1/16), else the
// duplication path with 0 or 1 step (2) or more (3), its steps counted by the kernel's rule in
// plain double (which may differ from the kernel's count where the spread lies within a few
// roundings of kFKernelSpread). For sorting inputs into the timed classes only.
int f_kernel_path(double phi, double m) {
  namespace d = dm::detail;
  if (phi <= d::kFSmallPhi) return 0;
  const double chi = std::numbers::pi / 2 - phi, x = 1.0 - m;
  if (x >= 0x1p-4 && chi * chi <= d::kFComplementRegion * x) return 1;
  const double s = std::sin(phi), c = std::cos(phi);
  double r0 = c, r1 = std::sqrt(c * c + x * s * s), r2 = 1.0;
  int k = 0;
  for (; 3 * (r2 - r0) > d::kFKernelSpread * (r0 + r1 + r2); ++k) {
    const double s01 = r0 + r1, s12 = r1 + r2, s02 = r0 + r2;
    r0 = std::sqrt(s01 * s02);
    r1 = std::sqrt(s01 * s12);
    r2 = std::sqrt(s02 * s12);
  }
  return k <= 1 ? 2 : 3;
}

template <Fn fn, Impl impl>
inline double eval(const Input& r) {
  if constexpr (fn == Fn::kF) {
    if constexpr (impl == Impl::kOwn) return dm::ellint_f(r.phi, r.m);
    if constexpr (impl == Impl::kBoostDouble)
      return boost::math::ellint_1(r.k, r.phi, boost_double_policy());
    if constexpr (impl == Impl::kBoostDefault) return boost::math::ellint_1(r.k, r.phi);
    if constexpr (impl == Impl::kOwnPortable)
      return dm::detail::ellint_f_core(r.phi, r.m, 1.0 - r.m);
    if constexpr (impl == Impl::kOwnDoubleAlg) return f_double_alg(r.phi, r.m);
  } else if constexpr (fn == Fn::kPi) {
    if constexpr (impl == Impl::kOwn) return dm::ellint_pi(r.n, r.phi, r.m);
    if constexpr (impl == Impl::kBoostDouble)
      return boost::math::ellint_3(r.k, r.n, r.phi, boost_double_policy());
    if constexpr (impl == Impl::kBoostDefault) return boost::math::ellint_3(r.k, r.n, r.phi);
    if constexpr (impl == Impl::kOwnDoubleLoop) return pi_double_loop(r.n, r.phi, r.m);
    if constexpr (impl == Impl::kOwnPortable)
      return dm::detail::ellint_pi_portable(r.n, 1.0 - r.n, r.phi, r.m, 1.0 - r.m);
    if constexpr (impl == Impl::kOwnAvx2) return dm::ellint_pi(r.n, r.phi, r.m);
  } else if constexpr (fn == Fn::kRF) {
    if constexpr (impl == Impl::kOwn) return dm::carlson_rf(r.x, r.y, r.z);
    if constexpr (impl == Impl::kBoostDouble)
      return boost::math::ellint_rf(r.x, r.y, r.z, boost_double_policy());
    if constexpr (impl == Impl::kBoostDefault) return boost::math::ellint_rf(r.x, r.y, r.z);
  } else {
    if constexpr (impl == Impl::kOwn) return dm::carlson_rj(r.x, r.y, r.z, r.p);
    if constexpr (impl == Impl::kBoostDouble)
      return boost::math::ellint_rj(r.x, r.y, r.z, r.p, boost_double_policy());
    if constexpr (impl == Impl::kBoostDefault) return boost::math::ellint_rj(r.x, r.y, r.z, r.p);
  }
}

// One pass over the set. Chained: each evaluation's phi depends on the previous result (phi + 0 *
// result, which IEEE arithmetic cannot fold away), so evaluations cannot overlap: the time is one
// evaluation's latency, not the throughput of independent ones.
template <Fn fn, Impl impl, bool chained = false>
inline void pass(const std::vector<Input>& in) {
  if constexpr (chained) {
    double previous = 0.0;
    for (Input r : in) {
      r.phi += 0.0 * previous;
      previous = eval<fn, impl>(r);
    }
    benchmark::DoNotOptimize(previous);
  } else {
    for (const Input& r : in)
      benchmark::DoNotOptimize(eval<fn, impl>(r));
  }
}

// For Pi/mixed/own-avx2: ellint_pi runs the kernel's AVX2+FMA copy while this lives.
struct UseAvx2Copy {
  const dm::detail::PiKernel before = dm::detail::pi_dd_kernel();
  UseAvx2Copy() { dm::detail::use_pi_dd_kernel(dm::detail::PiKernel::kAvx2Fma); }
  ~UseAvx2Copy() { dm::detail::use_pi_dd_kernel(before); }
  UseAvx2Copy(const UseAvx2Copy&) = delete;
  UseAvx2Copy& operator=(const UseAvx2Copy&) = delete;
};

template <Fn fn, Impl impl, bool chained = false>
void BM_Elliptic(benchmark::State& state, Band band) {
  std::optional<UseAvx2Copy> avx2_copy;
  if constexpr (impl == Impl::kOwnAvx2) avx2_copy.emplace();
  const std::vector<Input>& in = inputs(band);
  double t_impl = 0.0, t_base = 0.0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    pass<fn, impl, chained>(in);
    const auto t1 = Clock::now();
    pass<fn, Impl::kBoostDouble, chained>(in);
    const auto t2 = Clock::now();
    t_impl += seconds(t0, t1);
    t_base += seconds(t1, t2);
    state.SetIterationTime(seconds(t0, t1));
  }
  const double count = double(state.iterations()) * kInputs;
  state.SetItemsProcessed(state.iterations() * kInputs);
  state.counters["ns"] = t_impl / count * 1e9;
  state.counters["boost_double_ns"] = t_base / count * 1e9;
  state.counters["ratio_to_boost_double"] = t_base > 0 ? t_impl / t_base : 0.0;
}

template <Fn fn>
void register_fn(const char* fname, Band band, const char* bname) {
  const std::string base = std::string(fname) + "/" + bname + "/";
  benchmark::RegisterBenchmark((base + "own").c_str(), BM_Elliptic<fn, Impl::kOwn>, band)
      ->UseManualTime()
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark((base + "boost-double").c_str(), BM_Elliptic<fn, Impl::kBoostDouble>,
                               band)
      ->UseManualTime()
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark((base + "boost-default").c_str(),
                               BM_Elliptic<fn, Impl::kBoostDefault>, band)
      ->UseManualTime()
      ->Unit(benchmark::kMicrosecond);
}

void register_benchmarks() {
  register_fn<Fn::kF>("F", Band::kMixed, "mixed");
  benchmark::RegisterBenchmark("F/mixed/own-portable", BM_Elliptic<Fn::kF, Impl::kOwnPortable>,
                               Band::kMixed)
      ->UseManualTime()
      ->Unit(benchmark::kMicrosecond);
  if (dm::detail::pi_dd_kernel_available())
    benchmark::RegisterBenchmark("F/mixed/own-double", BM_Elliptic<Fn::kF, Impl::kOwnDoubleAlg>,
                                 Band::kMixed)
        ->UseManualTime()
        ->Unit(benchmark::kMicrosecond);
  // Where F's time goes: one evaluation's latency, and the cost by the kernel's path.
  benchmark::RegisterBenchmark("F/mixed/own-chained", BM_Elliptic<Fn::kF, Impl::kOwn, true>,
                               Band::kMixed)
      ->UseManualTime()
      ->Unit(benchmark::kMicrosecond);
  for (const auto& [band, name] :
       {std::pair{Band::kFSmall, "F/small/own"}, std::pair{Band::kFComplement, "F/complement/own"},
        std::pair{Band::kFSteps01, "F/steps0-1/own"}, std::pair{Band::kFSteps2, "F/steps2+/own"}})
    benchmark::RegisterBenchmark(name, BM_Elliptic<Fn::kF, Impl::kOwn>, band)
        ->UseManualTime()
        ->Unit(benchmark::kMicrosecond);
  register_fn<Fn::kPi>("Pi", Band::kMixed, "mixed");
  benchmark::RegisterBenchmark("Pi/mixed/own-portable", BM_Elliptic<Fn::kPi, Impl::kOwnPortable>,
                               Band::kMixed)
      ->UseManualTime()
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("Pi/mixed/own-double-loop",
                               BM_Elliptic<Fn::kPi, Impl::kOwnDoubleLoop>, Band::kMixed)
      ->UseManualTime()
      ->Unit(benchmark::kMicrosecond);
  if (dm::detail::pi_dd_kernel_supported(dm::detail::PiKernel::kAvx2Fma))
    benchmark::RegisterBenchmark("Pi/mixed/own-avx2", BM_Elliptic<Fn::kPi, Impl::kOwnAvx2>,
                                 Band::kMixed)
        ->UseManualTime()
        ->Unit(benchmark::kMicrosecond);
  register_fn<Fn::kPi>("Pi", Band::kPositive, "n>0");
  register_fn<Fn::kPi>("Pi", Band::kNegativeSmall, "-1<=n<0");
  register_fn<Fn::kPi>("Pi", Band::kNegativeLarge, "n<-1");
  register_fn<Fn::kRF>("RF", Band::kMixed, "mixed");
  register_fn<Fn::kRJ>("RJ", Band::kMixed, "mixed");
}

// The largest distance, in units in the last place of the library's value, between a plain-double
// variant and the library's function on the mixed set. F is faithful (within 1 ulp of the exact
// value) and Pi within 2 ulp, so a distance of D ulp means an error of at least D - 1 (F) or
// D - 2 (Pi) ulp.
template <Fn fn, Impl impl>
double max_ulp_distance() {
  double worst = 0.0;
  for (const Input& r : inputs(Band::kMixed)) {
    const double ref = eval<fn, Impl::kOwn>(r), v = eval<fn, impl>(r);
    const double a = std::fabs(ref);
    worst = std::max(worst, std::fabs(v - ref) / (std::nextafter(a, 2 * a + 1) - a));
  }
  return worst;
}

// After the console table: the median (or only) values per benchmark and the target check.
void print_summary(const disklab::bench::Results& rows) {
  using disklab::bench::counter;
  std::printf("\nMedian per evaluation, same run (ratio: time / boost-double's time):\n");
  std::printf("%-30s %10s %12s %8s\n", "benchmark", "ns", "boost-dbl ns", "ratio");
  for (const auto& [name, v] : rows)
    std::printf("%-30s %10.1f %12.1f %8.3f\n", name.c_str(), counter(v, "ns"),
                counter(v, "boost_double_ns"), counter(v, "ratio_to_boost_double"));
  const auto it = rows.find("Pi/mixed/own");
  if (it != rows.end()) {
    const double ratio = counter(it->second, "ratio_to_boost_double");
    std::printf(
        "\nTarget: own Pi <= %.2fx boost::math::ellint_3 (promote_double<false>): "
        "%.3fx on the mixed set, %s\n",
        kTargetPiRatio, ratio, ratio <= kTargetPiRatio ? "met" : "MISSED");
    if (dm::detail::pi_dd_kernel_available())
      std::printf("Pi/mixed/own ran the double-double kernel, %s copy.\n",
                  dm::detail::pi_dd_kernel_name(dm::detail::pi_dd_kernel()));
    else
      std::printf("Pi/mixed/own ran the portable long-double path.\n");
  }
  const auto f_own = rows.find("F/mixed/own");
  if (f_own != rows.end()) {
    const double ratio = counter(f_own->second, "ratio_to_boost_double");
    std::printf(
        "Target: own F <= %.2fx boost::math::ellint_1 (promote_double<false>): %.3fx on the "
        "mixed set, %s\n",
        kTargetFRatio, ratio, ratio <= kTargetFRatio ? "met" : "MISSED");
    std::printf("F/mixed/own ran %s.\n", dm::detail::f_dd_entry != nullptr
                                             ? "the double-double kernel"
                                             : "the portable long-double path");
  }
  if (rows.count("F/small/own") != 0) {
    std::array<int, 4> count{};
    for (const Input& r : inputs(Band::kMixed))
      ++count[f_kernel_path(r.phi, r.m)];
    std::printf(
        "F by the kernel's path (inputs drawn like the mixed set's; share of the mixed set):\n");
    const char* names[4] = {"F/small/own", "F/complement/own", "F/steps0-1/own", "F/steps2+/own"};
    for (int k = 0; k < 4; ++k) {
      const auto row = rows.find(names[k]);
      if (row == rows.end()) continue;
      std::printf(
          "  %-17s %5.1f%% of the mixed set: %5.1f ns, Boost %5.1f ns on the same inputs (%.3fx)\n",
          names[k], 100.0 * count[k] / kInputs, counter(row->second, "ns"),
          counter(row->second, "boost_double_ns"), counter(row->second, "ratio_to_boost_double"));
    }
  }
  const auto chained = rows.find("F/mixed/own-chained");
  if (chained != rows.end() && f_own != rows.end())
    std::printf(
        "F's latency (F/mixed/own-chained: each input waits for the previous result): %.1f ns, "
        "Boost %.1f ns; independent inputs overlap to %.1f ns (%.0f%% of the latency).\n",
        counter(chained->second, "ns"), counter(chained->second, "boost_double_ns"),
        counter(f_own->second, "ns"),
        100.0 * counter(f_own->second, "ns") / counter(chained->second, "ns"));
  if (rows.count("F/mixed/own-double") != 0)
    std::printf(
        "F/mixed/own-double (the duplication path for every input, in plain double): up to %.1f "
        "ulp from own F on the mixed set.\n",
        max_ulp_distance<Fn::kF, Impl::kOwnDoubleAlg>());
  if (rows.count("Pi/mixed/own-double-loop") != 0)
    std::printf(
        "Pi/mixed/own-double-loop (its loop in plain double): up to %.1f ulp from own Pi on the "
        "mixed set.\n",
        max_ulp_distance<Fn::kPi, Impl::kOwnDoubleLoop>());
  const auto avx2 = rows.find("Pi/mixed/own-avx2");
  if (avx2 != rows.end() && dm::detail::pi_dd_kernel() != dm::detail::PiKernel::kAvx2Fma) {
    const double ratio = counter(avx2->second, "ratio_to_boost_double");
    std::printf("The AVX2+FMA copy (CPUs without AVX-512VL): %.3fx, %s\n", ratio,
                ratio <= kTargetPiRatio ? "met" : "MISSED");
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_benchmarks();
  return disklab::bench::run_benchmarks(argc, argv, print_summary);
}
