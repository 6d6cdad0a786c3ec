#include "common.h"

#include <algorithm>
#include <sstream>

namespace disklab::test::seq {

bool is_02_net(const std::vector<FixedPoint2>& points, std::size_t start, int m, std::string* why) {
  const std::size_t count = std::size_t{1} << m;
  // Pigeonhole: 2^m points in 2^m cells are one per cell iff no cell is hit twice.
  std::vector<uint32_t> owner(count, 0);
  for (int k = 0; k <= m; ++k) {
    std::fill(owner.begin(), owner.end(), 0u);
    for (std::size_t i = start; i < start + count; ++i) {
      const uint64_t cx = static_cast<uint64_t>(points[i].x) >> (32 - k);
      const uint64_t cy = static_cast<uint64_t>(points[i].y) >> (32 - (m - k));
      const std::size_t c =
          (static_cast<std::size_t>(cx) << (m - k)) | static_cast<std::size_t>(cy);
      if (owner[c] != 0) {
        if (why) {
          std::ostringstream s;
          s << "block [" << start << ", " << start + count << "): shape 2^" << k << " x 2^"
            << (m - k) << " cell (" << cx << ", " << cy << ") holds point " << i << " and point "
            << (owner[c] - 1) << " (x=" << points[i].x << ", y=" << points[i].y
            << " as 32-bit fractions)";
          *why = s.str();
        }
        return false;
      }
      owner[c] = static_cast<uint32_t>(i) + 1;
    }
  }
  return true;
}

}  // namespace disklab::test::seq
