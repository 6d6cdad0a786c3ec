#pragma once
// The six disk sampling strategies of Christensen 2018 (Sec. 3, Fig. 3) behind one interface,
// for the CLI, the experiments and the tests.
//
// A DiskSampler walks a square sequence and produces disk samples one at a time, the way the
// memo's renderer consumes them: sample s of a four-copy strategy (polar4, concentric4) uses
// square point s div 4 rotated by (s mod 4) * 90 degrees (Appendix A); rejection skips square
// points outside the disk; pad-zero keeps them with weight 0.
//
// Every DiskSample says what it cost and how to weigh it: mean(weight * f(point)) estimates the
// disk average (1/pi) int_D f dA for every strategy (weight is 1 for the maps). For polar4 and
// concentric4 this holds over whole groups of four samples (N a multiple of 4): copy k alone
// covers quadrant k only.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "disklab/disk/concentric.h"
#include "disklab/disk/estimators.h"
#include "disklab/disk/polar.h"
#include "disklab/types.h"

namespace disklab::disk {

enum class Strategy { pad_zero, rejection, polar, concentric, polar4, concentric4 };

// CLI names in the memo's order: pad-zero rejection polar concentric polar4 concentric4.
const std::vector<std::string>& strategy_names();
std::string_view strategy_name(Strategy s);
std::optional<Strategy> parse_strategy(std::string_view name);
inline constexpr Strategy kAllStrategies[] = {Strategy::pad_zero, Strategy::rejection,
                                              Strategy::polar,    Strategy::concentric,
                                              Strategy::polar4,   Strategy::concentric4};

// Disk points one square point yields: 4 for polar4/concentric4, else 1.
inline uint32_t copies_per_square_point(Strategy s) {
  return (s == Strategy::polar4 || s == Strategy::concentric4) ? 4u : 1u;
}

struct DiskSample {
  uint32_t square_index = 0;  // sequence index of the square point used
  Point2 uv;                  // that square point
  Point2 point;               // the disk point (pad-zero: a point of [-1,1]^2, maybe outside)
  double weight = 1.0;        // estimator weight (pad-zero 4/pi or 0; rejection 0 only on failure)
  uint32_t consumed = 1;      // square points consumed by this sample (0 for copies 1-3 of x4)
  uint32_t copy = 0;          // rotation index k of polar4/concentric4, else 0
};

template <class Seq>
class DiskSampler {
 public:
  DiskSampler(Strategy strategy, const Seq& seq, uint32_t first_index = 0)
      : strategy_(strategy), seq_(&seq), cursor_(first_index) {}

  DiskSample next() {
    DiskSample s;
    switch (strategy_) {
      case Strategy::pad_zero: {
        s = take();
        const PadZeroSample p = sample_pad_zero(s.uv);
        s.point = p.point;
        s.weight = p.weight;
        break;
      }
      case Strategy::rejection: {
        const RejectionSample r = sample_rejection(*seq_, cursor_);
        cursor_ += r.consumed;
        s.square_index = r.index;
        s.uv = r.uv;
        s.point = r.point;
        s.weight = r.weight();
        s.consumed = r.consumed;
        break;
      }
      case Strategy::polar:
        s = take();
        s.point = sample_polar(s.uv);
        break;
      case Strategy::concentric:
        s = take();
        s.point = sample_concentric(s.uv);
        break;
      case Strategy::polar4:
      case Strategy::concentric4:
        if (copy_ == 0) {
          last_ = take();
          quarter_ = strategy_ == Strategy::polar4 ? sample_polar_quarter(last_.uv)
                                                   : sample_concentric_quarter(last_.uv);
          s = last_;
        } else {
          s = last_;
          s.consumed = 0;
        }
        s.copy = copy_;
        s.point = rotate_quarter_turns(quarter_, copy_);
        copy_ = (copy_ + 1) & 3u;
        break;
    }
    return s;
  }

  // Square points consumed so far (the next square index is first_index + consumed()).
  uint32_t cursor() const { return cursor_; }

 private:
  DiskSample take() {
    DiskSample s;
    s.square_index = cursor_;
    s.uv = seq_->at(cursor_);
    ++cursor_;
    return s;
  }

  Strategy strategy_;
  const Seq* seq_;
  uint32_t cursor_;
  uint32_t copy_ = 0;
  DiskSample last_;
  Point2 quarter_;
};

}  // namespace disklab::disk
