#pragma once
// Shared by the libFuzzer harnesses: reading typed values from the fuzzer's bytes, and a check
// that aborts (the fuzzer's signal of a finding) with the violated contract on stderr.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace disklab::fuzz {

// Consumes the input front to back; past its end every value reads as 0.
class Bytes {
 public:
  Bytes(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  uint64_t u64() {
    uint64_t v = 0;
    const size_t n = size_ - pos_ < 8 ? size_ - pos_ : 8;
    std::memcpy(&v, data_ + pos_, n);
    pos_ += n;
    return v;
  }
  uint8_t u8() { return pos_ < size_ ? data_[pos_++] : 0; }
  // Any double, NaN, Inf and subnormals included: the raw bit pattern.
  double any_double() {
    const uint64_t bits = u64();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  // A double in [0, 1] (both ends reachable): 53 random bits.
  double unit() {
    const uint64_t b = u64() >> 10;  // 54 bits: [0, 2^54)
    return b >= (uint64_t{1} << 53) ? 1.0 : static_cast<double>(b) * 0x1p-53;
  }
  size_t left() const { return size_ - pos_; }
  const uint8_t* rest() const { return data_ + pos_; }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

[[noreturn]] inline void violated(const char* what, const char* file, int line) {
  std::fprintf(stderr, "contract violated at %s:%d: %s\n", file, line, what);
  std::abort();
}

}  // namespace disklab::fuzz

#define FUZZ_CHECK(cond) ((cond) ? (void)0 : ::disklab::fuzz::violated(#cond, __FILE__, __LINE__))
